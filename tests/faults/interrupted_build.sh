#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# SIGINT and SIGTERM during `varc build` leave no pack, no temporary and a consistent cache:
# a later build with the same cache writes the same pack as a build without one.
# Usage: interrupted_build.sh VARC INPUT... (run from the repository root)
set -u
varc=$1; shift
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

start=$(date +%s%N)
"$varc" build -j 1 -o "$tmp/reference.svpack" "$@" >/dev/null || fail "reference build"
elapsed_ms=$(( ($(date +%s%N) - start) / 1000000 ))
# Interrupt at a third of a cold build: well inside compilation, whatever the machine's speed.
delay=$(awk "BEGIN { printf \"%.3f\", $elapsed_ms / 3000 }")
echo "cold build: ${elapsed_ms} ms; signals after ${delay} s"

for signal in INT TERM; do
    out="$tmp/out-$signal" cache="$tmp/cache-$signal"
    mkdir -p "$out"
    "$varc" build -j 1 --cache-dir "$cache" -o "$out/lights.svpack" "$@" >/dev/null 2>&1 &
    pid=$!
    sleep "$delay"
    kill -s "$signal" "$pid"
    wait "$pid"
    code=$?
    expected=$(( 128 + $(kill -l "$signal") ))
    [ "$code" = "$expected" ] || fail "SIG$signal: exit $code, expected $expected (did the build end first?)"
    [ -z "$(ls -A "$out")" ] || fail "SIG$signal left files in the output folder: $(ls -A "$out")"
    if [ -d "$cache" ] && find "$cache" -name '*.tmp.*' | grep -q .; then
        fail "SIG$signal left temporaries in the cache"
    fi
    "$varc" build -j 1 --cache-dir "$cache" -o "$out/lights.svpack" "$@" >/dev/null ||
        fail "SIG$signal: the build after the interruption failed"
    cmp -s "$tmp/reference.svpack" "$out/lights.svpack" ||
        fail "SIG$signal: the build with the interrupted cache differs from a clean build"
    echo "SIG$signal: exit $code, nothing written, the cache still builds the same pack"
done
