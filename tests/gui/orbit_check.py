#!/usr/bin/env python3
"""Checks OrbitWorldWx's --screenshot: its point, on a circle of radius 3 m about (5, 5) at
1 rad/s with time steps of 0.01 s, is a red disc of radius 0.4 m where the closed form puts it
at the step the screenshot was taken, and no longer where it started.

  orbit_check.py PICTURE LOG

LOG is the program's stdout, with its "screenshot FILE W H scale S centre CX CY step N" line.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from png_check import close, read_png  # noqa: E402

RED = (220, 40, 40)  # colors::red
RADIUS = 0.4


def main(picture, log):
    header = None
    with open(log) as f:
        for line in f:
            w = line.split()
            if w and w[0] == "screenshot":
                header = dict(w=int(w[2]), h=int(w[3]), s=float(w[5]),
                              cx=float(w[7]), cy=float(w[8]), step=int(w[10]))
    if header is None:
        sys.exit("no 'screenshot' line in the program's output")
    width, height, pixel = read_png(picture)

    def to_pixel(x, y):
        return (width / 2 + (x - header["cx"]) * header["s"],
                height / 2 - (y - header["cy"]) * header["s"])

    def red_hits(x, y):
        cx, cy = to_pixel(x, y)
        half = 0.5 * RADIUS * header["s"]
        points = [(round(cx + half * math.cos(a * math.pi)), round(cy + half * math.sin(a * math.pi)))
                  for a in (0.25, 0.75, 1.25, 1.75)] + [(round(cx), round(cy))]
        return sum(1 for px, py in points
                   if 0 <= px < width and 0 <= py < height and close(pixel(px, py), RED))

    angle = header["step"] * 0.01
    now = (5 + 3 * math.cos(angle), 5 + 3 * math.sin(angle))
    errors = []
    if (width, height) != (header["w"], header["h"]):
        errors.append(f"picture is {width}x{height}, the view {header['w']}x{header['h']}")
    if red_hits(*now) < 4:
        errors.append(f"no red disc at {now} (step {header['step']})")
    if math.dist(now, (8, 5)) > 2 * RADIUS and red_hits(8, 5) > 0:
        errors.append("the point is still drawn where it started")
    for e in errors:
        print("error:", e)
    print(f"{width}x{height} at step {header['step']}: point at ({now[0]:.3f}, {now[1]:.3f})")
    return 1 if errors else 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1], sys.argv[2]))
