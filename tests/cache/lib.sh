#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Shared by the cache tests: a redis-server on a free loopback port, a reference build, checks.
# Source it after setting |varc| and |tmp|; every function fails the test through fail().

fail() { echo "FAIL: $*"; exit 1; }

# Exit 77 (CTest: skipped, with the reason shown) when redis-server or redis-cli is missing.
require_redis() {
    for tool in redis-server redis-cli python3; do
        if ! command -v "$tool" >/dev/null; then
            echo "SKIP: $tool not found (Debian: scripts/install-deps.sh installs redis-server python3)"
            exit 77
        fi
    done
}

# A TCP port on 127.0.0.1 that nothing listens on right now.
free_port() {
    python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}

# start_redis DIR [redis-server options...]: starts a server on a free port, without persistence,
# as a daemon (so a CTest fixture can outlive its setup step); writes DIR/port, DIR/redis.pid and
# waits until it answers PING.
start_redis() {
    local dir=$1; shift
    mkdir -p "$dir"
    local port
    port=$(free_port)
    echo "$port" >"$dir/port"
    redis-server --bind 127.0.0.1 --port "$port" --save "" --appendonly no --daemonize yes \
        --pidfile "$dir/redis.pid" --logfile "$dir/redis.log" --dir "$dir" "$@" </dev/null ||
        fail "redis-server did not start: $(cat "$dir/redis.log" 2>/dev/null)"
    for _ in $(seq 100); do
        [ "$(redis-cli -p "$port" ping 2>/dev/null)" = PONG ] && [ -s "$dir/redis.pid" ] && return 0
        sleep 0.1
    done
    fail "redis-server did not answer on port $port: $(cat "$dir/redis.log" 2>/dev/null)"
}

# stop_redis DIR [SIGNAL]: ends the server start_redis started there (by its pid) and waits.
stop_redis() {
    local dir=$1 signal=${2:-TERM}
    [ -s "$dir/redis.pid" ] || return 0
    local pid
    pid=$(cat "$dir/redis.pid")
    kill -s "$signal" "$pid" 2>/dev/null
    for _ in $(seq 100); do
        kill -0 "$pid" 2>/dev/null || break
        sleep 0.1
    done
    rm -f "$dir/redis.pid"
}

# json_field FILE EXPR: evaluates EXPR (Python, over the build summary `j`) and prints it.
json_field() {
    python3 -c 'import json, sys; j = json.load(open(sys.argv[1])); print(eval(sys.argv[2]))' "$1" "$2"
}

# The pack a build without any cache writes, to compare every cached build with.
reference_build() {
    "$varc" build -o "$tmp/reference.svpack" "$@" >/dev/null || fail "reference build"
}

# same_pack FILE: the pack is byte for byte the reference.
same_pack() {
    cmp -s "$tmp/reference.svpack" "$1" || fail "$1 differs from the pack a build without cache writes"
}

# warnings_in LOG PATTERN: prints how many lines of LOG are cache warnings matching PATTERN.
warnings_in() {
    grep -c "warning: .*$2" "$1"
}
