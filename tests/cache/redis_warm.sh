#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# A build with an empty local cache and a warm Redis compiles zero programs and writes the pack a
# build without cache writes; Redis hits are written back to the local folder; `varc cache
# stats` counts Redis's entries and `varc cache clear` removes them.
# Usage: redis_warm.sh VARC FIXTURE_DIR INPUT... (run from the repository root)
set -u
varc=$1 fixture=$2; shift 2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
source "$(dirname "$0")/lib.sh"
require_redis
port=$(cat "$fixture/port") || fail "the redis fixture is not running"
url="redis://127.0.0.1:$port/1"
redis-cli -p "$port" -n 1 flushdb >/dev/null || fail "cannot empty database 1"
reference_build "$@"

"$varc" build --json --cache "file:$tmp/first" --cache "$url" -o "$tmp/cold.svpack" "$@" \
    >"$tmp/cold.json" 2>"$tmp/cold.err" || fail "cold build: $(cat "$tmp/cold.err")"
same_pack "$tmp/cold.svpack"
[ "$(json_field "$tmp/cold.json" 'j["compiled_programs"] > 0')" = True ] || fail "the cold build compiled nothing"
[ "$(json_field "$tmp/cold.json" 'j["cache"][1]["writes"] > 0 and j["cache"][1]["errors"] == 0')" = True ] ||
    fail "the cold build wrote nothing to Redis: $(cat "$tmp/cold.json")"
writes=$(json_field "$tmp/cold.json" 'j["cache"][1]["writes"]')

"$varc" build --json --cache "file:$tmp/second" --cache "$url" -o "$tmp/warm.svpack" "$@" \
    >"$tmp/warm.json" 2>"$tmp/warm.err" || fail "warm build: $(cat "$tmp/warm.err")"
same_pack "$tmp/warm.svpack"
grep -q warning "$tmp/warm.err" && fail "warnings in the warm build: $(cat "$tmp/warm.err")"
[ "$(json_field "$tmp/warm.json" 'j["compiled_programs"]')" = 0 ] ||
    fail "the warm-Redis build compiled programs: $(cat "$tmp/warm.json")"
[ "$(json_field "$tmp/warm.json" 'j["cache"][1]["hits"] > 0 and j["cache"][1]["misses"] == 0')" = True ] ||
    fail "Redis did not serve every lookup the local folder missed: $(cat "$tmp/warm.json")"
[ "$(json_field "$tmp/warm.json" 'j["cache"][0]["writes"] == j["cache"][1]["hits"]')" = True ] ||
    fail "Redis hits were not written back to the local folder: $(cat "$tmp/warm.json")"

"$varc" build --json --cache "file:$tmp/second" -o "$tmp/local.svpack" "$@" >"$tmp/local.json" ||
    fail "local build"
same_pack "$tmp/local.svpack"
[ "$(json_field "$tmp/local.json" 'j["compiled_programs"]')" = 0 ] ||
    fail "the written-back local folder did not serve the build"

"$varc" cache stats --json --cache "$url" >"$tmp/stats.json" || fail "cache stats"
[ "$(json_field "$tmp/stats.json" 'j[0]["entries"]')" = "$writes" ] ||
    fail "cache stats counts $(cat "$tmp/stats.json"), the build wrote $writes"
"$varc" cache clear --cache "$url" >"$tmp/clear.log" || fail "cache clear"
grep -qF "removed $writes entries" "$tmp/clear.log" || fail "cache clear: $(cat "$tmp/clear.log")"
[ "$(redis-cli -p "$port" -n 1 dbsize)" = 0 ] || fail "entries left in Redis after clear"

# Attributes: a read-only level is never written; prefix= and ttl= shape the keys.
"$varc" build --json --cache "$url|read-only" -o "$tmp/ro.svpack" "$@" >"$tmp/ro.json" || fail "read-only build"
[ "$(redis-cli -p "$port" -n 1 dbsize)" = 0 ] || fail "a read-only Redis level was written"
"$varc" build --cache "$url|prefix=team:|ttl=600" -o "$tmp/ttl.svpack" "$@" >/dev/null || fail "prefix/ttl build"
key=$(redis-cli -p "$port" -n 1 --scan | head -1)
case $key in team:*) ;; *) fail "key '$key' lacks the prefix team:" ;; esac
[ "$(redis-cli -p "$port" -n 1 --scan | grep -vc '^team:')" = 0 ] || fail "keys without the prefix"
ttl=$(redis-cli -p "$port" -n 1 ttl "$key")
[ "$ttl" -gt 0 ] && [ "$ttl" -le 600 ] || fail "key '$key' has TTL $ttl, not 1-600"
echo "warm Redis: 0 programs compiled, same pack, written back locally; stats and clear agree"
