#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The CTest fixture of the cache tests: `start DIR` runs a redis-server on a free loopback port
# (DIR/port names it), `stop DIR` ends it. Exit 77 (skipped) when redis-server is not installed.
set -u
tmp=$2
source "$(dirname "$0")/lib.sh"
case $1 in
    start) require_redis; stop_redis "$tmp"; rm -rf "$tmp"; start_redis "$tmp"
           echo "redis-server on 127.0.0.1:$(cat "$tmp/port")" ;;
    stop) stop_redis "$tmp"; rm -rf "$tmp" ;;
    *) fail "usage: redis_fixture.sh start|stop DIR" ;;
esac
