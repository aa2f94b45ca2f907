#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# A no-change rebuild of the library + fixtures (what varc_bench_cache builds: ../shared/fixtures
# and shaders/) with `varc build --direct`: cold (empty cache folder), warm program cache without
# direct mode, and warm direct mode (the manifest checked, the pack copied). Prints the median
# wall time of each, in ms. Run from the repository root: bench/direct_mode.sh [build/varc] [-j N].
set -eu
varc=${1:-build/varc}
jobs=${2:-2}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
inputs=(../shared/fixtures shaders)

now_ms() { date +%s%N | awk '{ printf "%.3f", $1 / 1e6 }'; }
run_ms() {  # run_ms ARGS...: one varc build, its wall time in ms
    local start end
    start=$(now_ms)
    "$varc" build -j "$jobs" "$@" "${inputs[@]}" >"$work/last.txt"
    end=$(now_ms)
    awk -v a="$start" -v b="$end" 'BEGIN { printf "%.1f\n", b - a }'
}
median() { sort -n | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

cold=$(for i in 1 2 3; do run_ms --direct --cache-dir "$work/cold$i" -o "$work/cold.svpack"; done | median)
warm=$(for i in 1 2 3 4 5; do run_ms --cache-dir "$work/cold1" -o "$work/warm.svpack"; done | median)
direct=$(for i in $(seq 10); do run_ms --direct --cache-dir "$work/cold1" -o "$work/direct.svpack"; done | median)
grep -qF "direct hit: pack reused" "$work/last.txt" || { echo "no direct hit"; exit 1; }
cmp "$work/cold.svpack" "$work/direct.svpack"
cmp "$work/cold.svpack" "$work/warm.svpack"
echo "pack $(stat -c %s "$work/direct.svpack") bytes, -j $jobs"
echo "cold (empty cache, --direct):          $cold ms (median of 3)"
echo "warm program cache (no --direct):      $warm ms (median of 5)"
echo "warm direct hit:                       $direct ms (median of 10)"
awk -v c="$cold" -v d="$direct" -v w="$warm" \
    'BEGIN { printf "direct vs cold: %.1fx faster (%.2f%% of cold); vs warm program cache: %.1fx\n", c / d, 100 * d / c, w / d }'
