#!/usr/bin/env bash
# Builds Thyrix (Release) and runs the main job: SpherusText, Spherus with a random controller
# in its arena, printing the agent's centre at each printed step. Arguments go to SpherusText
# (see --help).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build/demo -DCMAKE_BUILD_TYPE=Release -DTHYRIX_BUILD_TESTS=OFF >/dev/null
cmake --build build/demo -j"$(nproc)" --target SpherusText >/dev/null
exec build/demo/examples/Spherus/SpherusText "$@"
