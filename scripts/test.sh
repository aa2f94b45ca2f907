#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Installs what is missing, builds, and runs every test with ctest. Exit code = ctest's.
#
#   scripts/test.sh             the normal build in ${VARC_BUILD_DIR:-build}
#   scripts/test.sh --sanitize  the sanitizer job: one clang ASan + UBSan tree in
#                               ${VARC_SANITIZE_BUILD_DIR:-build-san} holding the suite and the
#                               fuzz targets, the whole suite, then every fuzz target for
#                               ${VARC_FUZZ_SECONDS:-60} s (scripts/fuzz.sh on the same tree)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
# timed LABEL CMD...: runs CMD and says how long it took; the README's CI figures come from these
# lines of a CI run.
timed() {
    local label=$1 start=$SECONDS rc=0
    shift
    "$@" || rc=$?
    echo "test: $label took $((SECONDS - start)) s"
    return $rc
}
if [ "${1:-}" = --sanitize ]; then
    build=${VARC_SANITIZE_BUILD_DIR:-$root/build-san}
    cxx=$(command -v clang++-14 || command -v clang++ || true)
    [ -n "$cxx" ] || { echo "test: clang++ not found (scripts/install-deps.sh installs clang-14)"; exit 1; }
    # One tree for the suite and the fuzzers (their libraries carry fuzzer-no-link coverage,
    # which the tests ignore), built by clang at -O1 with line tables only: 3-4x less compile
    # time than g++ -O2 -g with the sanitizers, and no second build of the libraries for the
    # fuzzers. Warnings are the normal job's gate (g++ with -Werror), so they stay warnings here.
    timed "sanitizer build" env VARC_BUILD_DIR="$build" "$root/scripts/build.sh" \
        -DCMAKE_CXX_COMPILER="$cxx" \
        -DVARC_SANITIZE="address;undefined" -DVARC_BUILD_FUZZERS=ON -DVARC_BUILD_BENCH=OFF \
        -DVARC_WERROR=OFF -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only -DNDEBUG"
    # Sanitizer reports are errors, leaks included, except in the tests that draw (label
    # vulkan), whose leaks lavapipe makes impossible to attribute (varc_draw_tests_skip_leak_check
    # turns leak detection off for those tests only). One ctest run, so the two cores stay busy
    # to its end: the tests that do not draw, those that draw, and sanitize.corpus_crashes (the
    # compatibility corpus for crashes, hangs and unmapped messages only, with small variant
    # spaces; it exists only in sanitizer trees, where the corpus builds several times slower).
    # Left out: packaging (label install: cmake install, cpack, an engine built against the
    # prefix; no code the sanitizers would see run); the built-in include tests (label builtin:
    # they check what varc's include files compile to, shader text that glslang, not
    # instrumented, reads through the same driver code the cli, library and faults tests run
    # here); and label compat, the normal job's full corpus tests (compat.properties draws ~45
    # packs on lavapipe, whose JIT runs many times slower under ASan, through the renderer code
    # the vulkan-labelled property tests already run here).
    export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
    export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
    timed "sanitizer tests" \
        ctest --test-dir "$build" --output-on-failure -j "$(nproc)" -LE "compat|install|builtin"
    export VARC_FUZZ_BUILD_DIR=$build VARC_FUZZ_REUSE_BUILD=1
    timed "fuzzers" "$root/scripts/fuzz.sh"
    exit 0
fi
timed build "$root/scripts/build.sh"
build=${VARC_BUILD_DIR:-$root/build}
timed tests ctest --test-dir "$build" --output-on-failure -j "$(nproc)"
