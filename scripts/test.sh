#!/usr/bin/env bash
# The second command of the README: build and run the whole test suite (normal build, -Werror), then the
# fast tests again under AddressSanitizer + UndefinedBehaviorSanitizer (build-asan, -O1), then the scene
# fuzzer briefly (libFuzzer, 10^4 executions), so that every target the project has is built and run.
#
#   scripts/test.sh                      all passes (what CI runs)
#   SL_SKIP_SANITIZE=1 scripts/test.sh   the normal pass only (a quick local check)
#   SL_SKIP_SLURM=1 scripts/test.sh      everything but the Slurm cluster test
#
# Last, the cluster recipes on a real one-node Slurm (scripts/slurm-test.sh: installs slurm-wlm and munge if
# missing, about two minutes).
#
# The sanitizer build leaves OSMesa out (-DSL_WITH_OSMESA=OFF): it draws through EGL alone, as a build on a
# distribution without OSMesa (Mesa 25.1 and later: Debian 14, Fedora, Arch) does, so CI proves that build.
#
# The sanitizer pass leaves out the tests labelled "slow" (the process-fault tests, which drive the binary
# through signals and full disks: the normal pass covers them); the stages' own suites and the fault tests
# run, the `linkage` binary they start included. LeakSanitizer suppressions name Mesa's libraries only and
# live in the renderer (src/render/gl/renderer.cpp).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
jobs=$(nproc)

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DSL_BUILD_TESTS=ON -DSL_BUILD_BENCH=ON
cmake --build build -j "$jobs"
ctest --test-dir build --output-on-failure -j "$jobs" --timeout 600

[[ "${SL_SKIP_SANITIZE:-0}" == 1 ]] && exit 0
# -g1: line tables only. The reports still name file and line; the build (the largest part of CI) is about a
# quarter faster than with full debug information.
cmake -S . -B build-asan -G Ninja -DSL_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" -DSL_BUILD_TESTS=ON -DSL_BUILD_BENCH=OFF \
  -DSL_WITH_OSMESA=OFF -DSL_WITH_EGL=ON
# The stages' own suites and the fault tests, which also drive the sanitized `linkage` binary; the CLI,
# frame-builder and analysis suites run in the normal pass only, to keep CI well inside its time on 2 cores.
asan_targets=(test_contracts test_architecture test_linkage test_geometry test_simulation test_scene
              test_render_cpu test_render test_output test_faults random_starts)
cmake --build build-asan -j "$jobs" --target "${asan_targets[@]}"
# abort_on_error: any report fails its test. detect_leaks: LeakSanitizer at exit.
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:check_initialization_order=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# Suites not built here appear to CTest as <target>_NOT_BUILT: leave those out.
ctest --test-dir build-asan --output-on-failure -j "$jobs" --timeout 900 -LE slow -E '_NOT_BUILT$'
unset ASAN_OPTIONS UBSAN_OPTIONS

# The scene fuzzer builds (clang, libFuzzer) and runs 10^4 inputs from its corpus; longer runs: scripts/fuzz.sh.
scripts/fuzz.sh --runs 10000 --build build-fuzz

# The README's Slurm recipes (scripts/slurm/*.sbatch) on a throwaway one-node cluster: render and sweep arrays
# byte-identical to single runs, a cancelled task resubmitted.
[[ "${SL_SKIP_SLURM:-0}" == 1 ]] || scripts/slurm-test.sh
