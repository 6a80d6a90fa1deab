#!/usr/bin/env bash
# The developer's fast lane: builds the stages' own suites (the CMake target `unit_tests`, no `linkage`
# binary, no sanitizers) and runs them (`ctest -L unit`). The whole suite is scripts/test.sh (what CI runs).
#
#   scripts/unit.sh                 every stage suite
#   scripts/unit.sh -R Chain        extra arguments go to ctest (here: only tests whose name has "Chain")
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DSL_BUILD_TESTS=ON -DSL_BUILD_BENCH=ON >/dev/null
cmake --build build -j "$jobs" --target unit_tests
ctest --test-dir build -L unit -j "$jobs" --output-on-failure --timeout 600 "$@"
