#!/usr/bin/env bash
# Fuzzes the scene loader and validator (fuzz/scene_fuzzer.cpp) with libFuzzer, clang and ASan+UBSan.
#
#   scripts/fuzz.sh [--time SECONDS | --runs N] [--jobs J] [--build DIR] [-- extra libFuzzer flags]
#
# Default: 300 seconds on one core. The working corpus lives in the build folder (DIR/corpus) and grows
# across invocations; it is seeded from fuzz/corpus/, scenes/ and tests/data/scenes/bad/. A crash, leak,
# hang (-timeout) or sanitizer report stops the run and leaves the input as DIR/crash-* (or leak-*,
# timeout-*); copy it to fuzz/regressions/ once fixed, where test_faults loads it on every ctest run.
set -euo pipefail
cd "$(dirname "$0")/.."

seconds=300 runs="" jobs=1 build=build-fuzz
while [[ $# -gt 0 ]]; do
  case "$1" in
    --time) seconds="$2"; shift 2 ;;
    --runs) runs="$2"; shift 2 ;;
    --jobs) jobs="$2"; shift 2 ;;
    --build) build="$2"; shift 2 ;;
    --) shift; break ;;
    *) echo "fuzz.sh: unknown option $1 (expected --time, --runs, --jobs, --build)" >&2; exit 2 ;;
  esac
done

flags="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
CC=clang CXX=clang++ cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" -DCMAKE_CXX_FLAGS="$flags" \
  -DCMAKE_PROJECT_INCLUDE="$PWD/fuzz/fuzz.cmake" -DSL_BUILD_TESTS=OFF -DSL_BUILD_BENCH=OFF >/dev/null
cmake --build "$build" -j 2 --target scene_fuzzer

corpus="$build/corpus"
mkdir -p "$corpus"
limit=(-max_total_time="$seconds")
[[ -n "$runs" ]] && limit=(-runs="$runs")
# -timeout: a scene taking over 2 s to validate is a hang. -rss_limit_mb: the validator must not
# allocate its way through the machine. Leak detection is on (ASan's default under libFuzzer).
# With --jobs > 1 libFuzzer runs that many workers; the run limit then applies to each of them.
parallel=()
[[ "$jobs" -gt 1 ]] && parallel=(-jobs="$jobs" -workers="$jobs")
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
"$build/scene_fuzzer" "${limit[@]}" "${parallel[@]}" -timeout=2 -rss_limit_mb=2048 -max_len=8192 \
  -dict=fuzz/scene.dict -artifact_prefix="$build/" -print_final_stats=1 "$@" \
  "$corpus" fuzz/corpus scenes tests/data/scenes/bad fuzz/regressions
