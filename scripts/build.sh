#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Configures and builds varc into ${VARC_BUILD_DIR:-build} (Ninja, RelWithDebInfo).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${VARC_BUILD_DIR:-$root/build}
werror=OFF
if [ "${CI:-}" = true ]; then werror=ON; fi
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DVARC_WERROR=$werror "$@"
cmake --build "$build" -j "$(nproc)"
