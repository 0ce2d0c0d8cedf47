#!/usr/bin/env bash
# 2 MPI ranks against 1 on this machine (issue 30's goal: at least 1.9x), SpherusEvolve with the
# same options and one thread a rank, repeated in interleaved pairs; prints the medians, the
# ratio with and without the start of the job (mpirun, MPI_Init and MPI_Finalize, measured
# apart as `SpherusEvolve --help`), each rank's CPU time and the 2-rank job's idle fractions.
# Builds nothing. Run it on an idle machine:
#   bench/mpi_scaling.sh BUILD_DIR [REPETITIONS]
# Environment: GENERATIONS (default 100), POPULATION (100), TRIALS (1), STEPS (1000),
# MPIRUN_FLAGS (extra mpirun options, e.g. "--bind-to none").
set -euo pipefail

build=${1:?usage: bench/mpi_scaling.sh BUILD_DIR [REPETITIONS]}
repetitions=${2:-5}
program=$build/examples/Spherus/SpherusEvolve
[ -x "$program" ] || { echo "no $program (build SpherusEvolve with MPI first)" >&2; exit 1; }
command -v mpirun > /dev/null || { echo "no mpirun on PATH" >&2; exit 1; }
[ -x /usr/bin/time ] || { echo "needs /usr/bin/time (Debian: apt-get install time)" >&2; exit 1; }
options=(--generations "${GENERATIONS:-100}" --population "${POPULATION:-100}"
         --trials "${TRIALS:-1}" --steps "${STEPS:-1000}" --seed 3 --threads 1)
mpirun=(mpirun)
[ "$(id -u)" = 0 ] && mpirun+=(--allow-run-as-root)
# shellcheck disable=SC2206  # the flags are words on purpose
mpirun+=(${MPIRUN_FLAGS:-})
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

now() { date +%s.%N; }

# run K NAME ARGS...: one job of K ranks; its wall time goes to NAME.wall, each rank's CPU time
# (user + system seconds) to NAME.cpu.RANK and its output to NAME.out.
run() {
  local ranks=$1 name=$2
  shift 2
  local begin end
  begin=$(now)
  # shellcheck disable=SC2016  # expanded by each rank's shell, which knows its rank
  "${mpirun[@]}" -n "$ranks" sh -c 'exec /usr/bin/time -f "%U %S" -o "$0.cpu.$OMPI_COMM_WORLD_RANK" "$@"' \
    "$work/$name" "$program" "$@" > "$work/$name.out" 2>&1
  end=$(now)
  awk -v b="$begin" -v e="$end" 'BEGIN { printf "%.3f\n", e - b }' > "$work/$name.wall"
}

for ((i = 1; i <= repetitions; ++i)); do
  for ranks in 1 2; do
    run "$ranks" "start$ranks.$i" --help
    run "$ranks" "job$ranks.$i" --out "$work/out$ranks.$i" "${options[@]}"
  done
  for f in fitness.csv best.genome checkpoint; do
    cmp -s "$work/out1.$i/$f" "$work/out2.$i/$f" ||
      { echo "repetition $i: $f differs between 1 and 2 ranks" >&2; exit 1; }
  done
  echo "repetition $i of $repetitions: 1 rank $(cat "$work/job1.$i.wall") s," \
       "2 ranks $(cat "$work/job2.$i.wall") s"
done

/usr/bin/python3 - "$work" "$repetitions" "${options[*]}" << 'EOF'
import re, statistics, sys
work, n, options = sys.argv[1], int(sys.argv[2]), sys.argv[3]
def wall(name): return float(open(f"{work}/{name}.wall").read())
def cpu(name, rank): return sum(map(float, open(f"{work}/{name}.cpu.{rank}").read().split()))
med = statistics.median
t = {k: med([wall(f"job{k}.{i}") for i in range(1, n + 1)]) for k in (1, 2)}
s = {k: med([wall(f"start{k}.{i}") for i in range(1, n + 1)]) for k in (1, 2)}
print(f"SpherusEvolve {options}, one thread a rank; medians of {n} interleaved runs")
print(f"  1 rank:  {t[1]:.3f} s wall (start {s[1]:.3f} s), "
      f"CPU {med([cpu(f'job1.{i}', 0) for i in range(1, n + 1)]):.3f} s")
cpus = [med([cpu(f"job2.{i}", r) for i in range(1, n + 1)]) for r in (0, 1)]
print(f"  2 ranks: {t[2]:.3f} s wall (start {s[2]:.3f} s), "
      f"CPU rank 0 {cpus[0]:.3f} s, rank 1 {cpus[1]:.3f} s")
print(f"  ratio {t[1] / t[2]:.3f}; without the start {(t[1] - s[1]) / (t[2] - s[2]):.3f}")
# The 2-rank jobs' own account: idle while a generation is evaluated, and between generations
# (rank 0 runs the strategy, rank 1 waits).
fractions = {0: [], 1: [], "between": []}
for i in range(1, n + 1):
    text = open(f"{work}/job2.{i}.out").read()
    ranks = {int(r): (float(idle), float(of)) for r, idle, of in
             re.findall(r"rank (\d): idle ([0-9.]+) s of ([0-9.]+) s", text)}
    found = re.search(r"between generations .*: ([0-9.]+) s", text)
    between = float(found.group(1)) if found else 0.0  # not printed before issue 30's balance
    span = ranks[0][1] + between
    fractions[0].append(ranks[0][0] / span)
    fractions[1].append((ranks[1][0] + between) / span)
    fractions["between"].append(between / span)
print(f"  2 ranks, idle share of the job's span (medians): rank 0 {100 * med(fractions[0]):.1f}%, "
      f"rank 1 {100 * med(fractions[1]):.1f}% (of which {100 * med(fractions['between']):.1f}% "
      f"between generations, while rank 0 runs the strategy)")
EOF
