#!/usr/bin/env bash
# Builds flexure with AddressSanitizer and UndefinedBehaviorSanitizer (-DFLEXURE_SANITIZE=ON:
# address, undefined and float-cast-overflow, -fno-sanitize-recover=all) in build-sanitize/ and
# runs the whole ctest suite there. Any finding aborts the process it happens in, so the test fails
# and its output (--output-on-failure) shows the report with a stack trace.
#
#   bash scripts/sanitize.sh [JOBS]      (JOBS defaults to nproc)
#
# Dependencies as for scripts/test.sh (scripts/install-deps.sh); the sanitizer runtimes come with
# GCC. The build needs about 3.4 times the CPU time of the normal one (31 against 9 CPU minutes,
# so about 16 minutes on 2 cores) and the suite about twice as long; figures in the README.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs="${1:-$(nproc)}"

# RelWithDebInfo: optimised like the release build (the suite's timing-sensitive tests stay within
# their limits) but with line numbers in the sanitizer stack traces.
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFLEXURE_SANITIZE=ON
cmake --build build-sanitize -j "$jobs"

# halt_on_error/abort: the first report ends the process with a failing status. detect_leaks: a
# leak fails the process at exit (LeakSanitizer, part of AddressSanitizer on Linux).
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:halt_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
ctest --test-dir build-sanitize --output-on-failure -j "$jobs"
