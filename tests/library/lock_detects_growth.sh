#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The lock test can fail: copies the library's shaders (not the built-in includes, but the
# built-in fallback shaders the lock lists) to WORK_DIR, adds one keyword set to the ForwardAdd
# pass of forward/Forward.shader, and expects
# `varc check --lock` against the library's lock to exit 1 and name that pass.
# Usage: lock_detects_growth.sh VARC SHADERS_DIR LOCK WORK_DIR
set -uo pipefail

varc="$1"
shaders="$2"
lock="$3"
work="$4"

rm -rf "$work"
mkdir -p "$work"
for dir in "$shaders"/*/; do
    [[ "$(basename "$dir")" == builtin ]] || cp -r "$dir" "$work/"
done
mkdir -p "$work/builtin"
cp -r "$shaders/builtin/fallback" "$work/builtin/"
shader="$work/forward/Forward.shader"
grep -q '#pragma multi_compile_fwdadd' "$shader" || { echo "FAIL: no multi_compile_fwdadd in $shader"; exit 1; }
sed -i 's/\(#pragma multi_compile_fwdadd[a-z_]*\)$/\1\n            #pragma multi_compile _ VARC_LOCK_PROBE/' "$shader"
grep -q 'VARC_LOCK_PROBE' "$shader" || { echo "FAIL: could not add a keyword set to $shader"; exit 1; }

output=$("$varc" check --lock "$lock" "$work" 2>&1)
status=$?
echo "$output"
[[ $status -eq 1 ]] || { echo "FAIL: varc check exited with $status, expected 1"; exit 1; }
grep -q 'ForwardAdd' <<<"$output" || { echo "FAIL: the report does not name the ForwardAdd pass"; exit 1; }
echo "OK: the lock rejects the grown pass"
