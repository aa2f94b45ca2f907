#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Redis answering garbage: (1) a server speaking no Redis protocol fails the level with one
# warning and the build goes on; (2) values overwritten with garbage under real keys are damaged
# misses, recompiled (never trusted) and replaced, without a warning. Same pack every time.
# Usage: redis_garbage.sh VARC INPUT... (run from the repository root)
set -u
varc=$1; shift
tmp=$(mktemp -d)
source "$(dirname "$0")/lib.sh"
require_redis
fake=""
trap '[ -n "$fake" ] && kill "$fake" 2>/dev/null; stop_redis "$tmp/redis"; rm -rf "$tmp"' EXIT
reference_build "$@"

port=$(free_port)
python3 - "$port" <<'PY' &
import socket, sys, threading
server = socket.socket()
server.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
server.bind(("127.0.0.1", int(sys.argv[1])))
server.listen(8)
def answer(connection):
    while connection.recv(65536):
        connection.sendall(b"hello, this is not redis\r\n")
while True:
    threading.Thread(target=answer, args=(server.accept()[0],), daemon=True).start()
PY
fake=$!
for _ in $(seq 100); do (exec 3<>"/dev/tcp/127.0.0.1/$port") 2>/dev/null && break; sleep 0.1; done
url="redis://127.0.0.1:$port/0"
"$varc" build --json --cache "file:$tmp/local" --cache "$url" -o "$tmp/fake.svpack" "$@" \
    >"$tmp/fake.json" 2>"$tmp/fake.err" || fail "the build against garbage failed: $(cat "$tmp/fake.err")"
same_pack "$tmp/fake.svpack"
[ "$(grep -c warning "$tmp/fake.err")" = 1 ] || fail "not exactly one warning: $(cat "$tmp/fake.err")"
[ "$(warnings_in "$tmp/fake.err" "the cache $url failed (MGET failed: Protocol error")" = 1 ] ||
    fail "the warning does not say why: $(cat "$tmp/fake.err")"
[ "$(json_field "$tmp/fake.json" 'j["cache"][1]["failed"] and j["cache"][1]["errors"] == 1')" = True ] ||
    fail "the failure is not counted once: $(cat "$tmp/fake.json")"

start_redis "$tmp/redis"
real="redis://127.0.0.1:$(cat "$tmp/redis/port")/0"
"$varc" build --json --cache "$real" -o "$tmp/cold.svpack" "$@" >"$tmp/cold.json" || fail "cold build"
keys=$(redis-cli -p "$(cat "$tmp/redis/port")" --scan --pattern 'varc:*')
[ -n "$keys" ] || fail "the cold build stored nothing in Redis"
for key in $keys; do echo "SET $key garbage"; done | redis-cli -p "$(cat "$tmp/redis/port")" >/dev/null
"$varc" build --json --cache "file:$tmp/fresh" --cache "$real" -o "$tmp/damaged.svpack" "$@" \
    >"$tmp/damaged.json" 2>"$tmp/damaged.err" || fail "the build over damaged values failed"
same_pack "$tmp/damaged.svpack"
grep -q warning "$tmp/damaged.err" && fail "damaged values are misses, not warnings: $(cat "$tmp/damaged.err")"
[ "$(json_field "$tmp/damaged.json" 'j["cache"][1]["hits"] == 0 and j["cache"][1]["damaged"] > 0')" = True ] ||
    fail "damaged values were trusted or not counted: $(cat "$tmp/damaged.json")"
[ "$(json_field "$tmp/damaged.json" 'j["compiled_programs"]')" = "$(json_field "$tmp/cold.json" 'j["compiled_programs"]')" ] ||
    fail "not every damaged program was recompiled"
"$varc" build --json --cache "$real" -o "$tmp/repaired.svpack" "$@" >"$tmp/repaired.json" || fail "repaired build"
[ "$(json_field "$tmp/repaired.json" 'j["compiled_programs"]')" = 0 ] || fail "the damaged values were not replaced"
same_pack "$tmp/repaired.svpack"
echo "garbage: a non-Redis server fails once with a warning; damaged values are recompiled and replaced"
