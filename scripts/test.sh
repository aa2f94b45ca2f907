#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Installs what is missing, builds, and runs every test with ctest. Exit code = ctest's.
#
#   scripts/test.sh             the normal build in ${VARC_BUILD_DIR:-build}
#   scripts/test.sh --sanitize  the sanitizer job: ASan + UBSan build in
#                               ${VARC_SANITIZE_BUILD_DIR:-build-san}, the whole suite, then every
#                               fuzz target for ${VARC_FUZZ_SECONDS:-60} s (scripts/fuzz.sh)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
if [ "${1:-}" = --sanitize ]; then
    build=${VARC_SANITIZE_BUILD_DIR:-$root/build-san}
    VARC_BUILD_DIR=$build "$root/scripts/build.sh" -DVARC_SANITIZE="address;undefined" \
        -DVARC_BUILD_BENCH=OFF
    # Sanitizer reports are errors. Leak detection runs on every test that does not draw; the
    # tests that draw (label vulkan) run with it off, because lavapipe is unloaded when the
    # Vulkan instance goes and its leaks then come from a module LeakSanitizer can no longer
    # name, so they can be neither attributed nor suppressed. Address and undefined-behaviour
    # checks stay on everywhere.
    export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
    (cd "$build" && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 \
        ctest --output-on-failure -j "$(nproc)" -LE "vulkan|compat")
    # The compatibility corpus builds several times slower under the sanitizers: there it runs
    # for crashes, hangs and unmapped messages only, with small variant spaces. Its property
    # check (compat.properties, label compat) is left out: it draws ~45 packs on lavapipe,
    # whose JIT runs many times slower under ASan, and the renderer code it drives is the code
    # the vulkan-labelled property tests (library, seeds, mutants) already run here.
    ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 bash "$root/tests/compat/corpus.sh" \
        "$build/varc" "$root/../shared/compat" "$root/docs/COMPATIBILITY.md" \
        "$build/compat-crashes" --crashes-only
    (cd "$build" && ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 \
        ctest --output-on-failure -j "$(nproc)" -L vulkan)
    exec "$root/scripts/fuzz.sh"
fi
"$root/scripts/build.sh"
build=${VARC_BUILD_DIR:-$root/build}
cd "$build"
ctest --output-on-failure -j "$(nproc)"
