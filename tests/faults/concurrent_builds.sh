#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Two `varc build` processes writing the same output and the same cache at once both succeed,
# the pack is the one a single build writes, no temporary is left, and the cache they filled
# together serves a third build whole.
# Usage: concurrent_builds.sh VARC INPUT... (run from the repository root)
set -u
varc=$1; shift
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

"$varc" build -o "$tmp/reference.svpack" "$@" >/dev/null || fail "reference build"
mkdir -p "$tmp/out"
"$varc" build -j 1 --cache-dir "$tmp/cache" -o "$tmp/out/lights.svpack" "$@" >"$tmp/a.log" 2>&1 &
a=$!
"$varc" build -j 1 --cache-dir "$tmp/cache" -o "$tmp/out/lights.svpack" "$@" >"$tmp/b.log" 2>&1 &
b=$!
wait "$a" || fail "first build: $(cat "$tmp/a.log")"
wait "$b" || fail "second build: $(cat "$tmp/b.log")"
cmp -s "$tmp/reference.svpack" "$tmp/out/lights.svpack" || fail "the pack differs from a single build"
[ "$(ls -A "$tmp/out")" = lights.svpack ] || fail "stray files: $(ls -A "$tmp/out")"
find "$tmp/cache" -name '*.tmp.*' | grep -q . && fail "temporaries left in the cache"
"$varc" build --cache-dir "$tmp/cache" -o "$tmp/third.svpack" "$@" > "$tmp/c.log" || fail "third build"
grep -qF "(0 preprocessed; cache:" "$tmp/c.log" || fail "the third build was not served by the cache: $(cat "$tmp/c.log")"
cmp -s "$tmp/reference.svpack" "$tmp/third.svpack" || fail "the cached pack differs"
echo "two concurrent builds: both succeeded, same pack, the shared cache serves a third build"
