#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Redis unreachable from the start (a closed port): the build succeeds at once, builds with the
# local folder, warns once, counts one error, and writes the same pack.
# Usage: redis_unreachable.sh VARC INPUT... (run from the repository root)
set -u
varc=$1; shift
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
source "$(dirname "$0")/lib.sh"
require_redis
reference_build "$@"
url="redis://127.0.0.1:$(free_port)/0"
"$varc" build --json --cache "file:$tmp/local" --cache "$url" -o "$tmp/out.svpack" "$@" \
    >"$tmp/out.json" 2>"$tmp/err.log" || fail "the build failed: $(cat "$tmp/err.log")"
same_pack "$tmp/out.svpack"
[ "$(grep -c warning "$tmp/err.log")" = 1 ] || fail "not exactly one warning: $(cat "$tmp/err.log")"
[ "$(warnings_in "$tmp/err.log" "the cache $url failed (cannot connect")" = 1 ] ||
    fail "the warning does not name the cache and the reason: $(cat "$tmp/err.log")"
[ "$(json_field "$tmp/out.json" 'j["cache"][1]["failed"] and j["cache"][1]["errors"] + j["cache"][1]["timeouts"] == 1')" = True ] ||
    fail "the failure is not counted once: $(cat "$tmp/out.json")"
[ "$(json_field "$tmp/out.json" 'j["cache"][0]["writes"] > 0')" = True ] || fail "the local folder was not filled"
VARC_CACHE="file:$tmp/local $url" "$varc" build --json -o "$tmp/again.svpack" "$@" >"$tmp/again.json" \
    2>/dev/null || fail "second build (VARC_CACHE)"
[ "$(json_field "$tmp/again.json" 'j["compiled_programs"]')" = 0 ] || fail "the local folder did not serve the second build"
same_pack "$tmp/again.svpack"
echo "unreachable Redis: built locally, one warning, one error counted, same pack"
