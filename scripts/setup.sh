#!/usr/bin/env bash
# The first command of the README: install what is missing, build, render the default scene to PNG
# frames (renders/default/) and an mp4 (renders/default.mp4).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DSL_BUILD_TESTS=OFF -DSL_BUILD_BENCH=OFF
cmake --build build --target linkage
build/linkage render scenes/default.json --video renders/default.mp4
echo "setup: frames in renders/default/, video renders/default.mp4"
