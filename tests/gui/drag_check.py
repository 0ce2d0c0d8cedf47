#!/usr/bin/env python3
"""Plans and checks the mouse drag of drag_test.sh from SpherusWx's --print-drag output.

  drag_check.py plan LOG
      prints "INDEX X0 Y0 X1 Y1 ... Xn Yn": the object to drag and the pointer's screen pixels,
      from its centre along a straight path that passes clear of every other object and wall
  drag_check.py check LOG INDEX X0 Y0 ... Xn Yn
      checks the drag events the program logged against that plan

The view's mapping (printed as "view OX OY W H scale S centre CX CY") turns pixels into world
coordinates independently of the program, so the check also tests the printed mapping.
"""
import math
import sys

ARENA = 10.0        # the Spherus arena is [0, 10] x [0, 10] m
DISTANCE = 1.5      # length of the drag (m)
WAYPOINTS = 5       # pointer moves after the press
SPHERUS_RADIUS = 0.25


def parse(path):
    view, objects, events = None, {}, []
    with open(path) as f:
        for line in f:
            w = line.split()
            if not w:
                continue
            if w[0] == "view":
                view = dict(ox=int(w[1]), oy=int(w[2]), w=int(w[3]), h=int(w[4]),
                            s=float(w[6]), cx=float(w[8]), cy=float(w[9]))
            elif w[0] == "object":
                objects[int(w[1])] = (float(w[3]), float(w[4]), float(w[5]))
            elif w[0] == "drag":
                events.append(w[1:])
    if view is None or not objects:
        sys.exit("no 'view' or 'object' lines in " + path)
    return view, objects, events


def to_pixel(v, x, y):
    return (round(v["ox"] + v["w"] / 2 + (x - v["cx"]) * v["s"]),
            round(v["oy"] + v["h"] / 2 - (y - v["cy"]) * v["s"]))


def to_world(v, px, py):
    return (v["cx"] + (px - v["ox"] - v["w"] / 2) / v["s"],
            v["cy"] - (py - v["oy"] - v["h"] / 2) / v["s"])


def segment_distance(p, a, b):
    ab = (b[0] - a[0], b[1] - a[1])
    t = ((p[0] - a[0]) * ab[0] + (p[1] - a[1]) * ab[1]) / (ab[0] ** 2 + ab[1] ** 2)
    t = min(1.0, max(0.0, t))
    return math.dist(p, (a[0] + t * ab[0], a[1] + t * ab[1]))


def plan(path):
    view, objects, _ = parse(path)
    spherus = [o for o in objects.values() if o[2] >= SPHERUS_RADIUS - 1e-6]
    best = None
    for index, (x, y, r) in objects.items():
        if r >= SPHERUS_RADIUS - 1e-6:
            continue  # the agent moves by itself: drag a still obstacle
        for k in range(16):
            angle = 2 * math.pi * k / 16
            end = (x + DISTANCE * math.cos(angle), y + DISTANCE * math.sin(angle))
            if not all(r + 0.3 <= c <= ARENA - r - 0.3 for c in end):
                continue
            clearance = min(
                [segment_distance(o[:2], (x, y), end) - o[2] - r
                 for i, o in objects.items() if i != index] +
                # the random agent wanders: keep well away from where it is
                [segment_distance(o[:2], (x, y), end) - 2.0 for o in spherus])
            if best is None or clearance > best[0]:
                best = (clearance, index, (x, y), end)
    if best is None or best[0] < 0.15:
        sys.exit("no object has a free path to be dragged along")
    _, index, start, end = best
    pixels = [to_pixel(view, *start)]
    for k in range(1, WAYPOINTS + 1):
        f = k / WAYPOINTS
        pixels.append(to_pixel(view, start[0] + f * (end[0] - start[0]),
                               start[1] + f * (end[1] - start[1])))
    print(index, " ".join(f"{px} {py}" for px, py in pixels))


def check(path, args):
    view, objects, events = parse(path)
    index = int(args[0])
    pixels = [(int(args[i]), int(args[i + 1])) for i in range(1, len(args), 2)]
    pixel_size = 1 / view["s"]
    errors = []

    def expect(condition, message):
        if not condition:
            errors.append(message)

    starts = [e for e in events if e[0] == "start"]
    moves = [e for e in events if e[0] == "move"]
    ends = [e for e in events if e[0] == "end"]
    settled = {int(e[5]): e for e in events if e[0] == "settled"}
    expect(len(starts) == 1 and len(ends) == 1, f"one start and one end, got {events}")
    if errors:
        return report(errors)
    start, end = starts[0], ends[0]
    expect(int(start[1]) == index, f"grabbed object {start[1]}, not {index}")
    centre0 = (float(start[2]), float(start[3]))
    grab = (float(start[5]), float(start[6]))
    pressed = to_world(view, *pixels[0])
    expect(math.dist(grab, pressed) <= 2 * pixel_size,
           f"grabbed at {grab}, but the pointer was pressed at {pressed}")
    expect(math.dist(centre0, objects[index][:2]) < 0.05,
           f"the object was at {centre0} when grabbed, printed at {objects[index][:2]}")

    # Every pointer move reached the program as a drag target at the pointer's world point.
    targets = [(float(m[5]), float(m[6])) for m in moves]
    expect(len(targets) >= 1, "no drag move")
    for px, py in pixels[1:]:
        w = to_world(view, px, py)
        expect(any(math.dist(w, t) <= 2 * pixel_size for t in targets),
               f"no drag target at pointer {px},{py} (world {w}); targets {targets}")

    # Released where the pointer left it (the grabbed point on the last target), then still.
    final = to_world(view, *pixels[-1])
    expected = (final[0] - (grab[0] - centre0[0]), final[1] - (grab[1] - centre0[1]))
    released = (float(end[2]), float(end[3]))
    expect(math.dist(released, expected) < 0.1,
           f"released at {released}, expected near {expected}")
    moved = math.dist(released, centre0)
    expect(moved > 0.8 * DISTANCE, f"moved only {moved:.3f} m of {DISTANCE}")
    for after in (10, 50):
        expect(after in settled, f"no position {after} steps after release")
        if after in settled:
            p = (float(settled[after][2]), float(settled[after][3]))
            expect(math.dist(p, released) < 0.02,
                   f"{after} steps after release at {p}, released at {released}: still moving")
    print(f"object {index}: grabbed at {centre0}, released at {released} "
          f"(expected {expected}), {len(targets)} moves, still after release")
    return report(errors)


def report(errors):
    for e in errors:
        print("error:", e)
    return 1 if errors else 0


if __name__ == "__main__":
    if len(sys.argv) >= 3 and sys.argv[1] == "plan":
        plan(sys.argv[2])
    elif len(sys.argv) >= 5 and sys.argv[1] == "check":
        sys.exit(check(sys.argv[2], sys.argv[3:]))
    else:
        sys.exit(__doc__)
