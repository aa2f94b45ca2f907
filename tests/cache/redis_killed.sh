#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Redis killed in the middle of a build: the build succeeds, warns once, counts the failure, goes
# on with the local folder (which then serves a build alone) and writes the same pack.
# Usage: redis_killed.sh VARC INPUT... (run from the repository root)
set -u
varc=$1; shift
tmp=$(mktemp -d)
trap 'stop_redis "$tmp/redis" KILL; rm -rf "$tmp"' EXIT
source "$(dirname "$0")/lib.sh"
require_redis
reference_build "$@"
start_redis "$tmp/redis"
port=$(cat "$tmp/redis/port")
url="redis://127.0.0.1:$port/0"
"$varc" build -j 1 --json --cache "file:$tmp/local" --cache "$url" -o "$tmp/out.svpack" "$@" \
    >"$tmp/out.json" 2>"$tmp/err.log" &
build=$!
# Kill Redis as soon as the build has stored something there (and has more to store).
for _ in $(seq 1200); do
    [ "$(redis-cli -p "$port" dbsize 2>/dev/null)" -gt 0 ] 2>/dev/null && break
    sleep 0.05
done
# Hold the build while Redis dies, so the kill lands mid-build however fast the machine is.
kill -STOP "$build" 2>/dev/null || fail "the build ended before Redis could be killed"
stop_redis "$tmp/redis" KILL
kill -CONT "$build"
wait "$build" || fail "the build failed: $(cat "$tmp/err.log")"
same_pack "$tmp/out.svpack"
[ "$(grep -c warning "$tmp/err.log")" = 1 ] || fail "not exactly one warning: $(cat "$tmp/err.log")"
[ "$(warnings_in "$tmp/err.log" "the cache $url failed")" = 1 ] ||
    fail "the warning does not name the cache: $(cat "$tmp/err.log")"
[ "$(json_field "$tmp/out.json" 'j["cache"][1]["failed"] and j["cache"][1]["errors"] + j["cache"][1]["timeouts"] == 1 and j["cache"][1]["writes"] > 0')" = True ] ||
    fail "the failure is not counted once after some writes: $(cat "$tmp/out.json")"
"$varc" build --json --cache "file:$tmp/local" -o "$tmp/again.svpack" "$@" >"$tmp/again.json" ||
    fail "local build"
[ "$(json_field "$tmp/again.json" 'j["compiled_programs"]')" = 0 ] ||
    fail "the build did not go on filling the local folder after Redis died"
echo "Redis killed mid-build: build went on locally, one warning, one error counted, same pack"
