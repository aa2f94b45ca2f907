#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# A full Redis (maxmemory reached, noeviction): writes are refused, the build succeeds, warns
# once, counts one error, keeps reading from Redis and writes the same pack.
# Usage: redis_full.sh VARC INPUT... (run from the repository root)
set -u
varc=$1; shift
tmp=$(mktemp -d)
trap 'stop_redis "$tmp/redis"; rm -rf "$tmp"' EXIT
source "$(dirname "$0")/lib.sh"
require_redis
reference_build "$@"
start_redis "$tmp/redis" --maxmemory 1mb --maxmemory-policy noeviction
port=$(cat "$tmp/redis/port")
# Fill it to the limit first, so the build's first write is refused.
# Fill it past the limit first (Redis refuses writes once used memory exceeds maxmemory), so
# the build's first write is refused.
filler=$(printf '%01000d' 0)
full=no
for i in $(seq 5000); do
    if redis-cli -p "$port" set "filler:$i" "$filler" | grep -q OOM; then full=yes; break; fi
done
[ $full = yes ] || fail "Redis is not full: $(redis-cli -p "$port" info memory | grep used_memory:)"
url="redis://127.0.0.1:$port/0"
"$varc" build --json --cache "file:$tmp/local" --cache "$url" -o "$tmp/out.svpack" "$@" \
    >"$tmp/out.json" 2>"$tmp/err.log" || fail "the build failed: $(cat "$tmp/err.log")"
same_pack "$tmp/out.svpack"
[ "$(grep -c warning "$tmp/err.log")" = 1 ] || fail "not exactly one warning: $(cat "$tmp/err.log")"
[ "$(warnings_in "$tmp/err.log" "the cache $url refused writes (SET answered OOM")" = 1 ] ||
    fail "the warning does not say Redis is full: $(cat "$tmp/err.log")"
[ "$(json_field "$tmp/out.json" 'not j["cache"][1]["failed"] and j["cache"][1]["errors"] == 1 and j["cache"][1]["writes"] == 0')" = True ] ||
    fail "the refusal is not counted once: $(cat "$tmp/out.json")"
[ "$(json_field "$tmp/out.json" 'j["cache"][1]["misses"] > 1 and j["cache"][0]["writes"] > 0')" = True ] ||
    fail "reads from Redis or the local folder stopped after the refused write: $(cat "$tmp/out.json")"
echo "full Redis: writes refused once with a warning, reads went on, same pack"
