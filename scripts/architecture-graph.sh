#!/usr/bin/env bash
# Regenerates docs/architecture.svg, the graph of the program's libraries, from the build itself
# (CMake's --graphviz output, rendered by Graphviz's dot). Run after changing cmake/Stages.cmake:
#
#   scripts/architecture-graph.sh
#
# Needs the graphviz package (installed here when missing).
set -euo pipefail
cd "$(dirname "$0")/.."
if ! command -v dot >/dev/null; then
  as_root=()
  [ "$(id -u)" -eq 0 ] || as_root=(sudo)
  "${as_root[@]}" apt-get install -y -qq --no-install-recommends graphviz
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# Only the program's own libraries: no tests, benchmarks or system libraries.
cat > "$work/CMakeGraphVizOptions.cmake" <<'OPTIONS'
set(GRAPHVIZ_GRAPH_NAME "sphere-linkages")
set(GRAPHVIZ_EXTERNAL_LIBS OFF)
set(GRAPHVIZ_GENERATE_PER_TARGET OFF)
set(GRAPHVIZ_GENERATE_DEPENDERS OFF)
set(GRAPHVIZ_IGNORE_TARGETS "^test_|^bench_|^sl_synthetic_frame$|^sl_test_support$|^scene_fuzzer$")
OPTIONS
cmake -S . -B "$work/build" -G Ninja -DSL_BUILD_TESTS=OFF -DSL_BUILD_BENCH=OFF >/dev/null
cp "$work/CMakeGraphVizOptions.cmake" "$work/build/"
(cd "$work/build" && cmake --graphviz=stages.dot . >/dev/null)
# Without CMake's legend (a subgraph of its own), bottom-up with the contracts at the bottom.
awk '/subgraph clusterLegend/ {skip = 1} !skip {print} skip && /^}/ {skip = 0}' "$work/build/stages.dot" \
  > "$work/stages.dot"
dot -Grankdir=BT -Tsvg "$work/stages.dot" -o docs/architecture.svg
echo "architecture-graph: docs/architecture.svg"
