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
    # Errors, not warnings; leaks of third-party libraries (glslang's pools, the Vulkan loader,
    # Mesa and LLVM inside lavapipe) are suppressed by name in scripts/lsan.supp, ours are not.
    export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
    export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
    export LSAN_OPTIONS=suppressions=$root/scripts/lsan.supp:print_suppressions=0
    (cd "$build" && ctest --output-on-failure -j "$(nproc)")
    exec "$root/scripts/fuzz.sh"
fi
"$root/scripts/build.sh"
build=${VARC_BUILD_DIR:-$root/build}
cd "$build"
ctest --output-on-failure -j "$(nproc)"
