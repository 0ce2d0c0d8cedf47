#!/usr/bin/env python3
"""Turns the JSON output of PeerBenchmarks into the Markdown tables of bench/README.md.

Usage: comparison_table.py RESULTS.json

Reads the median of each benchmark when repetitions were run (the single run otherwise) and
prints: time per step, scene x engine, with the ratio to Thyrix; the details of every run;
the batch; and the goals of issues 7 and 27, met or not. Python 3 standard library only.
"""

import json
import math
import sys

ENGINES = ["thyrix", "thyrix_gs", "box2d_v3", "box2d", "chipmunk"]
ENGINE_TITLES = {
    "thyrix": "Thyrix (Baraff)",
    "thyrix_gs": "Thyrix (Gauss-Seidel)",
    "box2d_v3": "Box2D v3",
    "box2d": "Box2D 2.4.1",
    "chipmunk": "Chipmunk 7.0.3",
}
SCENES = ["arena", "arena80", "arena160", "crowd", "spherus", "pile1000", "pile10000", "chain10",
          "chain100", "chain1000"]


def load(path):
    """{(scene, engine): {"median": {...}, "stddev": {...}}} from a Google Benchmark JSON file."""
    with open(path) as f:
        data = json.load(f)
    runs = {}
    for entry in data["benchmarks"]:
        name = entry.get("run_name", entry["name"])
        parts = name.split("/")
        key = (parts[0], parts[1])
        kind = entry.get("aggregate_name", "single") if entry.get("run_type") == "aggregate" \
            else "single"
        if entry.get("error_occurred"):
            runs.setdefault(key, {})["error"] = entry.get("error_message", "error")
            continue
        runs.setdefault(key, {})[kind] = entry
    return data.get("context", {}), runs


def value(run, counter, kind="median"):
    entry = run.get(kind) or run.get("single")
    if entry is None or counter not in entry:
        return None
    return entry[counter]


def fmt(x, digits=3):
    if x is None:
        return "—"
    if x == 0:
        return "0"
    if abs(x) < 1e-3:
        return f"{x:.1e}"
    magnitude = math.floor(math.log10(abs(x)))
    decimals = max(0, digits - 1 - magnitude)
    return f"{x:,.{decimals}f}"


def deterministic(run):
    """'yes' when every repetition ended in the same state (the hash did not vary)."""
    spread = value(run, "hash", "stddev")
    if spread is None:
        return "1 run"
    # The counter holds 32 bits of the hash (up to 4.3e9). Google Benchmark's standard
    # deviation subtracts squares of that size, so equal values can show a spread of up to
    # about 1e-7 of the mean (session 3: 35.8 for five equal values near 2.2e9), while two
    # different 32-bit hashes differ by 1e-6 of the mean or less only once in a million.
    mean = abs(value(run, "hash", "mean") or 0)
    return "yes" if spread <= 1e-6 * mean + 0.01 else "NO"


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    context, runs = load(sys.argv[1])
    reps = {run.get("median", {}).get("repetitions") for run in runs.values()} - {None}
    print(f"Machine: {context.get('num_cpus', '?')} CPUs at {context.get('mhz_per_cpu', '?')} MHz,"
          f" load average {', '.join(fmt(x, 2) for x in context.get('load_avg', []))}"
          f" when the run started; {context.get('date', '')}")
    print(f"Statistic: median of {', '.join(str(r) for r in sorted(reps)) or '1'} repetitions.\n")

    print("### Time per step (µs, CPU time of the stepping thread) and ratio to Thyrix\n")
    print("Ratio = engine's time / Thyrix's time (Baraff, the default solver): above 1, "
          "Thyrix is faster.\n")
    engines = [e for e in ENGINES if any((s, e) in runs for s in SCENES)]
    print("| scene | " + " | ".join(ENGINE_TITLES[e] for e in engines) + " |")
    print("|---|" + "---:|" * len(engines))
    for scene in SCENES:
        if not any((scene, e) in runs for e in engines):
            continue
        base = value(runs.get((scene, "thyrix"), {}), "us_per_step")
        cells = []
        for engine in engines:
            run = runs.get((scene, engine))
            if run is None:
                cells.append("n/a" if engine.startswith("thyrix") else "—")
                continue
            if "error" in run:
                cells.append("error")
                continue
            t = value(run, "us_per_step")
            cell = fmt(t)
            if base and engine != "thyrix":
                cell += f" ({fmt(t / base, 2)}x)"
            cells.append(cell)
        print(f"| {scene} | " + " | ".join(cells) + " |")

    print("\n### Details\n")
    print("| scene | engine | µs/step | wall µs/step | steps/s | contacts/step | ns/contact "
          "| final hash | same every run | penetration / r (final) | penetration / r (max) "
          "| max joint gap (m) |")
    print("|---|---|---:|---:|---:|---:|---:|---|---|---:|---:|---:|")
    for scene in SCENES:
        for engine in ENGINES:
            run = runs.get((scene, engine))
            if run is None or "error" in run:
                continue
            entry = run.get("median") or run.get("single")
            label = entry.get("label", "").replace("hash=", "")
            pen = value(run, "penetration_r")
            worst = value(run, "max_penetration_r")
            gap = value(run, "max_gap")
            print(f"| {scene} | {engine} | {fmt(value(run, 'us_per_step'))} "
                  f"| {fmt(value(run, 'wall_us_per_step'))} "
                  f"| {fmt(value(run, 'steps_per_s'))} | {fmt(value(run, 'contacts'))} "
                  f"| {fmt(value(run, 'ns_per_contact') or None)} | `{label}` | {deterministic(run)} "
                  f"| {fmt(pen * 100, 2) + ' %' if pen is not None else '—'} "
                  f"| {fmt(worst * 100, 2) + ' %' if worst is not None else '—'} "
                  f"| {fmt(gap, 2) if gap is not None else '—'} |")

    chains = [("chain10", 10), ("chain100", 100), ("chain1000", 1000)]
    chain_engines = [e for e in ENGINES if any((c, e) in runs for c, _ in chains)]
    if chain_engines:
        print("\n### chainN: time per step per link (µs), to read how each engine scales with N\n")
        print("| engine | " + " | ".join(c for c, _ in chains) + " |")
        print("|---|" + "---:|" * len(chains))
        for engine in chain_engines:
            cells = []
            for chain, links in chains:
                t = value(runs.get((chain, engine), {}), "us_per_step")
                cells.append(fmt(t / links) if t else "—")
            print(f"| {ENGINE_TITLES[engine]} | " + " | ".join(cells) + " |")

    batch = {e: r for (s, e), r in runs.items()
             if s == "batch" and e != "thyrix_paired" and "error" not in r}
    paired = runs.get(("batch", "thyrix_paired"), {})
    paired_speedup = value(paired, "speedup_2_threads") if "error" not in paired else None
    one = batch.get("thyrix_1thread")
    if batch:
        print("\n### batch: independent Spherus episodes (wall time)\n")
        print("| threads | episodes/s | speed-up | µs/step (wall) | CPU µs/step (all threads) "
              "| identical to 1 thread | hash |")
        print("|---:|---:|---:|---:|---:|---|---|")
        for engine, run in sorted(batch.items(), key=lambda kv: value(kv[1], "threads")):
            eps = value(run, "episodes_per_s")
            speedup = eps / value(one, "episodes_per_s") if one else None
            entry = run.get("median") or run.get("single")
            print(f"| {value(run, 'threads'):.0f} | {fmt(eps)} | {fmt(speedup, 3)}x "
                  f"| {fmt(value(run, 'us_per_step'))} | {fmt(value(run, 'cpu_us_per_step'))} "
                  f"| {'yes' if value(run, 'identical') == 1 else 'NO'} "
                  f"| `{entry.get('label', '').replace('hash=', '')}` |")
        if paired_speedup is not None:
            print(f"\nIn pairs (the batch on 1 thread, then at once on 2; the median of the "
                  f"repetitions' ratios): {fmt(paired_speedup, 3)}x, episodes "
                  f"{'identical' if value(paired, 'identical') == 1 else 'DIFFERENT'}.")
        machine = runs.get(("machine", "parallel_capacity"))
        capacity = value(machine, "speedup_2_threads") if machine else None
        if capacity is not None:
            print(f"\nThe machine's own 2-thread speed-up in the same run (fixed arithmetic, no "
                  f"memory): {fmt(capacity, 3)}x. A batch speed-up near this one is all the "
                  f"machine had to give.")
    for (scene, engine), run in sorted(runs.items()):
        if "error" in run:
            print(f"\n**{scene}/{engine} failed:** {run['error']}")

    print("\n### Goals of issue 7\n")
    print("| goal | measured | met |")
    print("|---|---|---|")

    def ratio(scene, engine):
        t = value(runs.get((scene, engine), {}), "us_per_step")
        base = value(runs.get((scene, "thyrix"), {}), "us_per_step")
        return t / base if t and base else None

    def goal(text, measured, ok):
        met = "—" if ok is None else ("yes" if ok else "no")
        print(f"| {text} | {measured} | {met} |")

    for scene, engine, target in [("arena", "box2d", 20), ("arena", "chipmunk", 6),
                                  ("pile1000", "box2d", 4), ("pile1000", "chipmunk", 2),
                                  ("pile10000", "box2d", 4), ("pile10000", "chipmunk", 2)]:
        r = ratio(scene, engine)
        goal(f"{scene}: Thyrix at least {target}x faster than {ENGINE_TITLES[engine]}",
             f"{fmt(r, 2)}x" if r else "not run", r >= target if r else None)
    arena = value(runs.get(("arena", "thyrix"), {}), "us_per_step")
    spherus = value(runs.get(("spherus", "thyrix"), {}), "us_per_step")
    r = spherus / arena if arena and spherus else None
    goal("spherus: at most 2x the arena's time", f"{fmt(r, 2)}x" if r else "not run",
         r <= 2 if r else None)
    for scene in ["pile1000", "pile10000"]:
        pen = value(runs.get((scene, "thyrix"), {}), "penetration_r")
        goal(f"{scene}: Thyrix's penetration under 1% of the radius (final state)",
             f"{fmt(pen * 100, 2)} %" if pen is not None else "not run",
             pen < 0.01 if pen is not None else None)
        worst = value(runs.get((scene, "thyrix"), {}), "max_penetration_r")
        goal(f"{scene}: Thyrix's penetration under 1% of the radius (every sample of the run)",
             f"{fmt(worst * 100, 2)} %" if worst is not None else "not run",
             worst < 0.01 if worst is not None else None)
    for engine, target in [("box2d", 20), ("chipmunk", 10)]:
        r = ratio("chain1000", engine)
        goal(f"chain1000: Thyrix at least {target}x faster than {ENGINE_TITLES[engine]}",
             f"{fmt(r, 2)}x" if r else "not run", r >= target if r else None)
    # Linear in N: the time per link at 1000 links over the time per link at 10. A fixed cost
    # per step makes it below 1; the goal is taken as met up to 1.5 (Box2D's own is about 1.2,
    # where anything quadratic would give about 100).
    t10 = value(runs.get(("chain10", "thyrix"), {}), "us_per_step")
    t1000 = value(runs.get(("chain1000", "thyrix"), {}), "us_per_step")
    growth = t1000 / 1000 / (t10 / 10) if t10 and t1000 else None
    goal("chain10 to chain1000: Thyrix's time linear in N (time per link at 1000 over at 10, "
         "up to 1.5)", fmt(growth, 2) if growth else "not run",
         growth <= 1.5 if growth else None)
    two = batch.get("thyrix_2thread")
    if one and two:
        s = value(two, "episodes_per_s") / value(one, "episodes_per_s")
        same = value(two, "identical") == 1
        machine = runs.get(("machine", "parallel_capacity"))
        capacity = value(machine, "speedup_2_threads") if machine else None
        note = f" (the machine gave {fmt(capacity, 3)}x)" if capacity is not None else ""
        # Judged in pairs when they ran (see batchPaired in PeerBenchmarks.cpp); the ratio of
        # the separate benchmarks' medians is shown beside it.
        if paired_speedup is not None:
            goal("batch: 2 threads give at least 1.9x the episodes/s of 1 thread (in pairs)",
                 f"{fmt(paired_speedup, 3)}x (separate runs: {fmt(s, 3)}x){note}",
                 paired_speedup >= 1.9)
        else:
            goal("batch: 2 threads give at least 1.9x the episodes/s of 1 thread",
                 f"{fmt(s, 3)}x{note}", s >= 1.9)
        same = same and value(paired, "identical") != 0
        goal("batch: results identical to the 1-thread run", "yes" if same else "NO", same)

    print("\n### Goals of issue 27\n")
    print("The issue's ratios are to Thyrix with its Gauss-Seidel solver (to Thyrix with Baraff, "
          "the default, in parentheses).\n")
    print("| goal | measured | met |")
    print("|---|---|---|")

    def ratio_gs(scene, engine):
        t = value(runs.get((scene, engine), {}), "us_per_step")
        base = value(runs.get((scene, "thyrix_gs"), {}), "us_per_step")
        return t / base if t and base else None

    for scene, target in [("arena", 20), ("arena160", 5), ("pile1000", 3), ("pile10000", 10)]:
        r = ratio_gs(scene, "box2d_v3")
        rb = ratio(scene, "box2d_v3")
        goal(f"{scene}: Thyrix at least {target}x faster than Box2D v3",
             f"{fmt(r, 2)}x ({fmt(rb, 2)}x)" if r else "not run", r >= target if r else None)
    r = ratio("chain1000", "box2d_v3")
    goal("chain1000: Box2D v3 (no goal, for the table)", f"{fmt(r, 2)}x" if r else "not run", None)
    # Per agent: the crowd has 10 agents (and 50 times the balls) where the arena has one.
    for engine in ["thyrix", "thyrix_gs"]:
        crowd = runs.get(("crowd", engine), {})
        t = value(crowd, "us_per_step")
        agents = value(crowd, "agents")
        base = value(runs.get(("arena", engine), {}), "us_per_step")
        r = t / agents / base if t and agents and base else None
        goal(f"crowd ({ENGINE_TITLES[engine]}): per agent at most 3x the arena's time",
             f"{fmt(r, 2)}x" if r else "not run", r <= 3 if r else None)


if __name__ == "__main__":
    main()
