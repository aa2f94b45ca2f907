#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Two builds sharing one Redis and one local folder at once both succeed without warnings and
# write the pack a build without cache writes; what they stored together serves a third build
# from Redis alone and a fourth from the folder alone.
# Usage: redis_concurrent.sh VARC FIXTURE_DIR INPUT... (run from the repository root)
set -u
varc=$1 fixture=$2; shift 2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
source "$(dirname "$0")/lib.sh"
require_redis
port=$(cat "$fixture/port") || fail "the redis fixture is not running"
url="redis://127.0.0.1:$port/2"
redis-cli -p "$port" -n 2 flushdb >/dev/null || fail "cannot empty database 2"
reference_build "$@"

for run in a b; do
    "$varc" build -j 1 --cache "file:$tmp/shared" --cache "$url" -o "$tmp/$run.svpack" "$@" \
        >"$tmp/$run.log" 2>&1 &
    eval "pid_$run=\$!"
done
wait "$pid_a" || fail "first build: $(cat "$tmp/a.log")"
wait "$pid_b" || fail "second build: $(cat "$tmp/b.log")"
same_pack "$tmp/a.svpack"
same_pack "$tmp/b.svpack"
cat "$tmp/a.log" "$tmp/b.log" | grep -q warning && fail "warnings: $(cat "$tmp/a.log" "$tmp/b.log")"
find "$tmp/shared" -name '*.tmp.*' | grep -q . && fail "temporaries left in the local cache"

"$varc" build --json --cache "$url" -o "$tmp/redis.svpack" "$@" >"$tmp/redis.json" || fail "Redis-only build"
same_pack "$tmp/redis.svpack"
[ "$(json_field "$tmp/redis.json" 'j["compiled_programs"]')" = 0 ] || fail "Redis did not serve the third build"
"$varc" build --json --cache "file:$tmp/shared" -o "$tmp/local.svpack" "$@" >"$tmp/local.json" ||
    fail "folder-only build"
same_pack "$tmp/local.svpack"
[ "$(json_field "$tmp/local.json" 'j["compiled_programs"]')" = 0 ] || fail "the folder did not serve the fourth build"
echo "two concurrent builds on one Redis and one folder: same pack, nothing corrupted"
