#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# A cache whose entries cannot be read (here: each entry's path is taken by a folder, which root
# cannot read as a file either) is a miss: the build succeeds, writes the same pack, and warns
# once that the cache is not updated.
# Usage: unreadable_cache.sh VARC INPUT... (run from the repository root)
set -u
varc=$1; shift
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

"$varc" build --cache-dir "$tmp/cache" -o "$tmp/first.svpack" "$@" >/dev/null || fail "first build"
entries=$(find "$tmp/cache" -type f \( -name '*.program' -o -name '*.source' \))
[ -n "$entries" ] || fail "the first build stored no entries"
for entry in $entries; do rm "$entry" && mkdir "$entry"; done
"$varc" build --cache-dir "$tmp/cache" -o "$tmp/second.svpack" "$@" >"$tmp/out.log" 2>"$tmp/err.log" ||
    fail "the build with unreadable entries failed: $(cat "$tmp/err.log")"
cmp -s "$tmp/first.svpack" "$tmp/second.svpack" || fail "the pack differs"
grep -q "warning: the program cache is not updated" "$tmp/err.log" ||
    fail "no warning about the cache: $(cat "$tmp/err.log")"
grep -qF "cache:" "$tmp/out.log" && fail "unreadable entries were counted as hits: $(cat "$tmp/out.log")"
echo "unreadable cache entries: recompiled, same pack, one warning"
