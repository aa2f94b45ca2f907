#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Builds the libFuzzer targets with clang, ASan and UBSan into ${VARC_FUZZ_BUILD_DIR:-build-fuzz}
# and runs each for ${VARC_FUZZ_SECONDS:-60} seconds on its seed corpus and dictionary. A crash,
# leak or sanitizer report fails the run and leaves the reproducer in the work folder
# (build-fuzz/findings/<target>/). Usage: scripts/fuzz.sh [target...] (default: all six, the
# longest first: `build` first runs its ~290 seed shaders, about two minutes under the sanitizers,
# so starting it first lets the other five share the second core meanwhile).
# The `build` target also starts from the corpus shaders, read in place from ../shared/compat
# (the folder beside the checkout) when it is there.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${VARC_FUZZ_BUILD_DIR:-$root/build-fuzz}
seconds=${VARC_FUZZ_SECONDS:-60}
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(build pack_reader shaderlab include front_end scene)

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
# fuzzOne TARGET: runs one target for $seconds; its report goes to $build/TARGET.report and its
# exit status is the run's (0 clean, 1 a finding).
fuzzOne() {
    local target=$1
    local work="$build/corpus/$target" findings="$build/findings/$target"
    mkdir -p "$work" "$findings"
    local seeds=() dict=()
    if [ "$target" = pack_reader ]; then
        "$build/tests/fuzz/varc_pack_fuzz_seed" "$work"
    else
        seeds=("$root/tests/fuzz/corpus/$target")
    fi
    # `build` reads the same text as front_end (its dictionary), plus the corpus's .shader files.
    local dict_name=$target
    if [ "$target" = build ]; then
        dict_name=front_end
        local compat
        compat=$(cd "$root/.." && pwd)/shared/compat
        if [ -d "$compat" ]; then
            find "$compat" -name '*.shader' | sort | paste -sd, | tr -d '\n' > "$build/build-seeds.txt"
            seeds+=(-seed_inputs=@"$build/build-seeds.txt")
        fi
    fi
    [ -f "$root/tests/fuzz/dict/$dict_name.dict" ] && dict=(-dict="$root/tests/fuzz/dict/$dict_name.dict")
    if ! "$build/tests/fuzz/varc_${target}_fuzzer" "$work" "${seeds[@]}" "${dict[@]}" \
            -max_total_time="$seconds" -max_len=20000 -timeout=20 -rss_limit_mb=4096 \
            -artifact_prefix="$findings/" -print_final_stats=1 > "$build/$target.log" 2>&1; then
        { echo "fuzz: $target FAILED; see $build/$target.log and $findings/"
          tail -40 "$build/$target.log"; } > "$build/$target.report"
        return 1
    fi
    { echo "fuzz: $target clean for ${seconds}s"
      grep -E '^stat::number_of_executed_units|^#[0-9]+ *DONE' "$build/$target.log" | tail -2
    } > "$build/$target.report"
}

# Each target is one single-threaded libFuzzer process: as many run at once as there are cores,
# so every target still gets its full $seconds while the job's wall time shrinks.
status=0
running=0
for target in "${targets[@]}"; do
    if [ "$running" -ge "$(nproc)" ]; then
        wait -n || status=1
        running=$((running - 1))
    fi
    echo "fuzz: $target for ${seconds}s"
    rm -f "$build/$target.report"
    fuzzOne "$target" &
    running=$((running + 1))
done
while [ "$running" -gt 0 ]; do
    wait -n || status=1
    running=$((running - 1))
done
for target in "${targets[@]}"; do
    cat "$build/$target.report" 2>/dev/null || { echo "fuzz: $target wrote no report"; status=1; }
done
exit $status
