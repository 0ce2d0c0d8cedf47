#!/usr/bin/env python3
"""Checks that PacWx --eat ate: in the program's --screenshot log, at least one food circle's
centre lies inside Pac 0's ring (the polygon of its circles' centres, in ring order).

  pac_eat_check.py LOG

LOG is the program's stdout: "screenshot ... step N", then one "object INDEX circle X Y R" line
per movable shape. Object indices follow PacSimulator's registration: 4 walls, Pac 0 (4) and its
ring circles 5 to 14, Pac 1 (15) and its circles 16 to 25, then the food from 26 on.
"""
import sys

PAC0 = range(5, 15)
FOOD_FIRST = 26


def inside(point, polygon):
    # Ray casting along +x: an odd number of edge crossings is inside.
    x, y = point
    result = False
    for i in range(len(polygon)):
        (ax, ay), (bx, by) = polygon[i], polygon[i - 1]
        if (ay > y) != (by > y) and x < ax + (y - ay) * (bx - ax) / (by - ay):
            result = not result
    return result


def main(log):
    centres, step = {}, None
    with open(log) as f:
        for line in f:
            w = line.split()
            if w and w[0] == "screenshot":
                step = int(w[-1])
            elif w and w[0] == "object":
                centres[int(w[1])] = (float(w[3]), float(w[4]))
    if step is None or any(i not in centres for i in PAC0):
        sys.exit("no 'screenshot' line or not Pac 0's circles in the program's output")
    ring = [centres[i] for i in PAC0]
    eaten = [i for i, c in centres.items() if i >= FOOD_FIRST and inside(c, ring)]
    food = sum(1 for i in centres if i >= FOOD_FIRST)
    print(f"step {step}: {len(eaten)} of {food} food circles inside Pac 0: {eaten}")
    return 0 if eaten else 1


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1]))
