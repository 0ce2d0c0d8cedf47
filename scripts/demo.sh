#!/usr/bin/env bash
# Builds Thyrix (Release) and runs the main console demo; extra arguments go to the demo.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release -DTHYRIX_BUILD_TESTS=OFF >/dev/null
cmake --build build/release -j"$(nproc)" --target ArenaText >/dev/null
exec build/release/examples/Demo/ArenaText "$@"
