#!/usr/bin/env bash
# Builds and runs every test of Thyrix, warnings as errors:
#   1. Release, real = double, with the wxWidgets front-end when wxWidgets is installed, and
#      the Python package with its pytest tests (the CTest test Python.pytest);
#   2. an installed Thyrix found by find_package from another project, and a smoke run of the
#      peer benchmarks (bench/PeerBenchmarks, shortened);
#   3. Debug under AddressSanitizer + UndefinedBehaviorSanitizer, with the front-end too;
#   4. Release, real = float;
#   5. Release, real = float, built with clang;
#   6. Release, the scalar build (THYRIX_SIMD=scalar: no intrinsics, no run-time AVX copies),
#      the library tests only (no examples, Python or MPI);
#   7. the libFuzzer targets (fuzz/, clang, AddressSanitizer + UndefinedBehaviorSanitizer), each
#      run for a bounded time from its seed corpus.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)
common=(-DTHYRIX_WARNINGS_AS_ERRORS=ON -DTHYRIX_BUILD_TESTS=ON)
passed=0

ctest_in() {  # directory: runs its tests and adds them to the total
  local log
  log=$(cd "$1" && ctest -j"$jobs" --output-on-failure) || { echo "$log"; exit 1; }
  echo "$log" | grep -E "tests passed|Total Test time"
  passed=$((passed + $(echo "$log" | sed -n 's/.*tests failed out of \([0-9]*\).*/\1/p')))
}

run() {  # name, then cmake options
  local name=$1; shift
  echo "=== $name ==="
  cmake -S . -B "build/$name" "${common[@]}" "$@" >/dev/null
  cmake --build "build/$name" -j"$jobs"
  ctest_in "build/$name"
}

# The wxWidgets front-end and its tests (under Xvfb) in the release and sanitizer
# configurations, when wxWidgets is installed (scripts/install-deps.sh with THYRIX_WITH_GUI=1).
gui=()
if dpkg -s libwxgtk3.2-dev >/dev/null 2>&1; then gui=(-DTHYRIX_BUILD_GUI=ON); fi

run release -DCMAKE_BUILD_TYPE=Release "${gui[@]}"

echo "=== reference manual (Doxygen, warnings are errors) ==="
cmake --build build/release --target docs

echo "=== find_package(Thyrix) from another project ==="
rm -rf build/install build/consumer
cmake --install build/release --prefix build/install >/dev/null
cmake -S tests/consumer -B build/consumer -DCMAKE_PREFIX_PATH="$PWD/build/install" >/dev/null
cmake --build build/consumer -j"$jobs" >/dev/null
ctest_in build/consumer

echo "=== peer benchmarks (built, and a few scenes run shortened) ==="
# A smoke test of bench/: it compiles (with Box2D v3 when ../shared/peers/box2d-v3.tar.gz is
# there, and Box2D 2.4 and Chipmunk when installed) and runs. Only PeerBenchmarks is built, in
# the release tree, which then goes back to no benchmarks.
cmake -S . -B build/release -DTHYRIX_BUILD_BENCHMARKS=ON | grep 'PeerBenchmarks:' || true
cmake --build build/release -j"$jobs" --target PeerBenchmarks
log=$(build/release/bench/PeerBenchmarks --quick \
  --benchmark_filter='^(arena|crowd|pile1000|chain10)/' 2>&1) || { echo "$log"; exit 1; }
if echo "$log" | grep -q "ERROR OCCURRED"; then echo "$log"; exit 1; fi
cmake -S . -B build/release -DTHYRIX_BUILD_BENCHMARKS=OFF >/dev/null

export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
run sanitize -DCMAKE_BUILD_TYPE=Debug -DTHYRIX_SANITIZE=address,undefined "${gui[@]}"
run float -DCMAKE_BUILD_TYPE=Release -DTHYRIX_REAL=float
run clang-float -DCMAKE_BUILD_TYPE=Release -DTHYRIX_REAL=float -DCMAKE_CXX_COMPILER=clang++-14
run scalar -DCMAKE_BUILD_TYPE=Release -DTHYRIX_SIMD=scalar -DTHYRIX_BUILD_EXAMPLES=OFF \
  -DTHYRIX_BUILD_PYTHON=OFF -DTHYRIX_WITH_MPI=OFF

echo "=== fuzzers (clang, address + undefined sanitizers, ${fuzz_seconds:=60} s each) ==="
# A shape leaking through a border (issue 25, defect 5: one world in about 84,000 still does,
# fuzz/known-leaks/) is saved and counted, not fatal, while leaks_fatal is 0; every other
# finding fails the run.
leaks_fatal=0
cmake -S . -B build/fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++-14 \
  -DTHYRIX_BUILD_FUZZERS=ON -DTHYRIX_SANITIZE=address,undefined -DTHYRIX_WARNINGS_AS_ERRORS=ON \
  -DTHYRIX_BUILD_TESTS=OFF -DTHYRIX_BUILD_EXAMPLES=OFF >/dev/null
cmake --build build/fuzz -j"$jobs"
rm -rf build/fuzz/runs build/fuzz/leaks && mkdir -p build/fuzz/leaks
for fuzzer in NarrowPhaseFuzzer WorldFuzzer; do
  mkdir -p "build/fuzz/runs/$fuzzer"  # new inputs go there, never into the committed corpus
  leak_folder=()
  if [ "$fuzzer" = WorldFuzzer ] && [ "$leaks_fatal" = 0 ]; then
    leak_folder=(env THYRIX_FUZZ_LEAK_FOLDER="$PWD/build/fuzz/leaks")
  fi
  "${leak_folder[@]}" "build/fuzz/fuzz/$fuzzer" -max_total_time="$fuzz_seconds" -print_final_stats=1 \
    -artifact_prefix="build/fuzz/runs/$fuzzer-" "build/fuzz/runs/$fuzzer" "fuzz/corpus/$fuzzer" \
    2>&1 | grep -E "^(Done|stat::number_of_executed_units)|ERROR|Fuzzer:" || true
  if ls "build/fuzz/runs/$fuzzer"-* >/dev/null 2>&1; then
    echo "$fuzzer found a failure: build/fuzz/runs/$fuzzer-*"; exit 1
  fi
done
echo "worlds with a shape outside their box (saved in build/fuzz/leaks): $(ls build/fuzz/leaks | wc -l)"

echo "total: $passed passed, 0 failed"
