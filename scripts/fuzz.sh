#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Builds the libFuzzer targets with clang, ASan and UBSan into ${VARC_FUZZ_BUILD_DIR:-build-fuzz}
# and runs each for ${VARC_FUZZ_SECONDS:-60} seconds on its seed corpus and dictionary. A crash,
# leak or sanitizer report fails the run and leaves the reproducer in the work folder
# (build-fuzz/findings/<target>/). Usage: scripts/fuzz.sh [target...] (default: all six).
# The `build` target also starts from the corpus shaders, read in place from ../shared/compat
# (the folder beside the checkout) when it is there.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${VARC_FUZZ_BUILD_DIR:-$root/build-fuzz}
seconds=${VARC_FUZZ_SECONDS:-60}
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(pack_reader shaderlab include front_end scene build)

# VARC_FUZZ_REUSE_BUILD=1: $build is a configured tree with VARC_BUILD_FUZZERS=ON (the sanitizer
# job's, scripts/test.sh --sanitize); only the fuzz targets are built in it.
if [ "${VARC_FUZZ_REUSE_BUILD:-}" != 1 ]; then
    cxx=$(command -v clang++-14 || command -v clang++ || true)
    [ -n "$cxx" ] || { echo "fuzz: clang++ not found (scripts/install-deps.sh installs clang-14)"; exit 1; }
    cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
          -DCMAKE_CXX_COMPILER="$cxx" -DVARC_BUILD_FUZZERS=ON -DVARC_SANITIZE="address;undefined" \
          -DVARC_BUILD_TESTS=OFF -DVARC_BUILD_BENCH=OFF -DVARC_ENABLE_VULKAN_TESTS=OFF \
          -DVARC_WERROR=OFF >/dev/null
elif ! grep -q '^VARC_BUILD_FUZZERS:BOOL=ON' "$build/CMakeCache.txt" 2>/dev/null; then
    echo "fuzz: $build is not a tree configured with VARC_BUILD_FUZZERS=ON"; exit 1
fi
cmake --build "$build" -j "$(nproc)" --target varc_fuzzers

# UBSan findings are errors, not warnings; glslang's process-wide pools are freed at exit.
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
status=0
for target in "${targets[@]}"; do
    work="$build/corpus/$target" findings="$build/findings/$target"
    mkdir -p "$work" "$findings"
    if [ "$target" = pack_reader ]; then
        "$build/tests/fuzz/varc_pack_fuzz_seed" "$work"
        seeds=()
    else
        seeds=("$root/tests/fuzz/corpus/$target")
    fi
    # `build` reads the same text as front_end (its dictionary), plus the corpus's .shader files.
    dict_name=$target
    if [ "$target" = build ]; then
        dict_name=front_end
        compat=$(cd "$root/.." && pwd)/shared/compat
        if [ -d "$compat" ]; then
            find "$compat" -name '*.shader' | sort | paste -sd, | tr -d '\n' > "$build/build-seeds.txt"
            seeds+=(-seed_inputs=@"$build/build-seeds.txt")
        fi
    fi
    dict=()
    [ -f "$root/tests/fuzz/dict/$dict_name.dict" ] && dict=(-dict="$root/tests/fuzz/dict/$dict_name.dict")
    echo "fuzz: $target for ${seconds}s"
    if ! "$build/tests/fuzz/varc_${target}_fuzzer" "$work" "${seeds[@]}" "${dict[@]}" \
            -max_total_time="$seconds" -max_len=20000 -timeout=20 -rss_limit_mb=4096 \
            -artifact_prefix="$findings/" -print_final_stats=1 > "$build/$target.log" 2>&1; then
        echo "fuzz: $target FAILED; see $build/$target.log and $findings/"
        tail -40 "$build/$target.log"
        status=1
    else
        grep -E '^stat::number_of_executed_units|^#[0-9]+ *DONE' "$build/$target.log" | tail -2
    fi
done
exit $status
