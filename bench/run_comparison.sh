#!/usr/bin/env bash
# Runs the comparison of issues 7 and 27 in one go: Thyrix side by side with Box2D v3, Box2D
# 2.4 and Chipmunk 7 (each included when it was found: Box2D v3 is built from its source tarball,
# ../shared/peers/box2d-v3.tar.gz beside the repository or BOX2D_V3_TARBALL; this script
# installs nothing), then prints the tables of bench/README.md.
#
#   bench/run_comparison.sh                 # the full suite, 5 repetitions interleaved, medians
#   bench/run_comparison.sh --quick         # every scene 10 to 20 times shorter
#   bench/run_comparison.sh --benchmark_filter=pile    # any PeerBenchmarks option passes on
#
# Environment: BUILD_DIR (default build/bench), REPETITIONS (default 5), JOBS (default nproc),
# BOX2D_V3_TARBALL (default: the build's cache, first ../shared/peers/box2d-v3.tar.gz).
# The repetitions of all benchmarks are interleaved at random, so that a slow spell of a shared
# machine spreads over every engine and scene instead of landing on one of them.
# The JSON results are kept in $BUILD_DIR/peer_results.json.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$root/build/bench}
repetitions=${REPETITIONS:-5}
jobs=${JOBS:-$(nproc 2>/dev/null || echo 2)}

# Release, benchmarks on; the examples provide Spherus (spherus and batch scenes); the tests
# are not needed here.
mkdir -p "$build"
box2d_v3=()
if [ -n "${BOX2D_V3_TARBALL:-}" ]; then box2d_v3=(-DTHYRIX_BOX2D_V3_TARBALL="$BOX2D_V3_TARBALL"); fi
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DTHYRIX_BUILD_BENCHMARKS=ON \
  -DTHYRIX_BUILD_EXAMPLES=ON -DTHYRIX_BUILD_TESTS=OFF "${box2d_v3[@]}" >"$build/configure.log" 2>&1 ||
  { cat "$build/configure.log"; exit 1; }
grep 'PeerBenchmarks:' "$build/configure.log" || true
cmake --build "$build" -j "$jobs" --target PeerBenchmarks

results=$build/peer_results.json
echo "Running PeerBenchmarks ($repetitions repetitions; $(nproc) CPUs, load $(cut -d' ' -f1-3 /proc/loadavg))"
"$build/bench/PeerBenchmarks" --benchmark_repetitions="$repetitions" \
  --benchmark_report_aggregates_only=true --benchmark_enable_random_interleaving=true \
  --benchmark_out="$results" \
  --benchmark_out_format=json "$@"
echo
python3 "$root/bench/comparison_table.py" "$results"
