#!/usr/bin/env python3
"""Checks a Thyrix window program's --screenshot picture against what it says it drew.

  png_check.py PICTURE LOG [--size S] [--colour FIRST-LAST=R,G,B ...]

--size is the side of the square walled arena (default 10, Spherus's); each --colour gives the
fill of the objects with indices FIRST to LAST; other objects must be blue. Without --colour,
Spherus's layout is assumed (its two circles, objects 5 and 6, yellow).

LOG is the program's stdout: "screenshot FILE W H scale S centre CX CY step N", then one
"object INDEX circle X Y R" line per movable shape. The picture must be W x H, not blank, show
the arena's walls, and have each object's colour inside its projected disc: Spherus's two
circles yellow, the obstacles blue (ThyrixLite/ColorDefinitions.h). The PNG is decoded here with
zlib and struct alone (8-bit RGB or RGBA, non-interlaced, the five filter types), independently
of the program's drawing code.
"""
import math
import struct
import sys
import zlib

YELLOW = (240, 200, 40)      # Spherus's circles
BLUE = (40, 90, 220)         # colors::object, the obstacles
WALL = (64, 64, 64)          # colors::fixedObject, the borders
TOLERANCE = 40               # per channel: anti-aliasing, the orientation line
SPHERUS_FIRST, SPHERUS_LAST = 5, 6   # object indices of Spherus's circles (after 4 walls, agent)


def read_png(path):
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        sys.exit(f"{path} is not a PNG")
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        elif kind == b"IEND":
            break
        pos += 12 + length
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or colour not in (2, 6) or interlace != 0:
        sys.exit(f"unsupported PNG: depth {depth}, colour type {colour}, interlace {interlace}")
    channels = 3 if colour == 2 else 4
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        line = raw[y * (stride + 1):(y + 1) * (stride + 1)]
        kind, row = line[0], bytearray(line[1:])
        for i in range(stride):
            a = row[i - channels] if i >= channels else 0
            b = previous[i]
            c = previous[i - channels] if i >= channels else 0
            if kind == 1:
                row[i] = (row[i] + a) & 255
            elif kind == 2:
                row[i] = (row[i] + b) & 255
            elif kind == 3:
                row[i] = (row[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                row[i] = (row[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(row)
        previous = row
    pixel = lambda x, y: tuple(rows[y][x * channels:x * channels + 3])
    return width, height, pixel


def close(colour, expected):
    return all(abs(a - b) <= TOLERANCE for a, b in zip(colour, expected))


def main(picture, log, size=10.0, colours=None):
    colours = colours or [(SPHERUS_FIRST, SPHERUS_LAST, YELLOW)]
    header, objects = None, []
    with open(log) as f:
        for line in f:
            w = line.split()
            if w and w[0] == "screenshot":
                header = dict(w=int(w[2]), h=int(w[3]), s=float(w[5]),
                              cx=float(w[7]), cy=float(w[8]), step=int(w[10]))
            elif w and w[0] == "object":
                objects.append((int(w[1]), float(w[3]), float(w[4]), float(w[5])))
    if header is None or not objects:
        sys.exit("no 'screenshot' or 'object' lines in the program's output")
    width, height, pixel = read_png(picture)
    errors = []
    if (width, height) != (header["w"], header["h"]):
        errors.append(f"picture is {width}x{height}, the view {header['w']}x{header['h']}")

    def to_pixel(x, y):
        return (header["w"] / 2 + (x - header["cx"]) * header["s"],
                header["h"] / 2 - (y - header["cy"]) * header["s"])

    # Not blank: a good share of coloured pixels, many distinct colours.
    sample = [pixel(x, y) for y in range(0, height, 4) for x in range(0, width, 4)]
    coloured = sum(1 for p in sample if p != (255, 255, 255)) / len(sample)
    if coloured < 0.02 or len(set(sample)) < 8:
        errors.append(f"picture looks blank: {coloured:.1%} non-white, {len(set(sample))} colours")

    # The walls x = 0 and x = 10 are dark lines at their projected columns.
    for wall_x in (0.0, size):
        px, py = to_pixel(wall_x, size / 2)
        column = [pixel(x, int(py)) for x in range(int(px) - 2, int(px) + 3)
                  if 0 <= x < width]
        if not any(close(p, WALL) for p in column):
            errors.append(f"no wall at x = {wall_x} (pixel column {px:.0f}): {column}")

    # Each object's colour at four points halfway out from its projected centre.
    matched = 0
    for index, x, y, r in objects:
        expected = next((c for first, last, c in colours if first <= index <= last), BLUE)
        cx, cy = to_pixel(x, y)
        half = 0.5 * r * header["s"]
        hits = 0
        for angle in (0.25, 0.75, 1.25, 1.75):
            px = round(cx + half * math.cos(angle * math.pi))
            py = round(cy + half * math.sin(angle * math.pi))
            if 0 <= px < width and 0 <= py < height and close(pixel(px, py), expected):
                hits += 1
        if hits >= 3:
            matched += 1
        else:
            errors.append(f"object {index} at ({x}, {y}): colour {pixel(round(cx), round(cy))} "
                          f"around pixel ({cx:.0f}, {cy:.0f}), expected {expected}")
    for e in errors:
        print("error:", e)
    print(f"{width}x{height} at step {header['step']}: {matched}/{len(objects)} objects "
          f"in their colours, {coloured:.1%} of pixels coloured")
    return 1 if errors else 0


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    arena, ranges, rest = 10.0, [], sys.argv[3:]
    while rest:
        option, value, rest = rest[0], rest[1], rest[2:]
        if option == "--size":
            arena = float(value)
        elif option == "--colour":
            span, rgb = value.split("=")
            first, last = (int(v) for v in span.split("-"))
            ranges.append((first, last, tuple(int(v) for v in rgb.split(","))))
        else:
            sys.exit(f"unknown option {option}\n{__doc__}")
    sys.exit(main(sys.argv[1], sys.argv[2], arena, ranges))
