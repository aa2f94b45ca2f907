#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Configures and builds varc into ${VARC_BUILD_DIR:-build} (Ninja, RelWithDebInfo with line tables
# only: -g1 keeps file:line in backtraces and profiles and costs a third less compile time than
# full -g, which a debugging session configures for itself). Extra arguments go to cmake.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${VARC_BUILD_DIR:-$root/build}
werror=OFF
if [ "${CI:-}" = true ]; then werror=ON; fi
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" -DVARC_WERROR=$werror "$@"
cmake --build "$build" -j "$(nproc)"
