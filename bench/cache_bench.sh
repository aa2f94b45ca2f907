#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The shared program cache (#12) in one run: the library + fixtures built cold (empty local
# folder and empty Redis), with a warm local folder, and with a warm Redis only (a fresh local
# folder, as a second developer or a CI job sees it). Prints the median wall time of each and
# the ratios to cold; the warm-Redis build must compile nothing.
# Usage: bench/cache_bench.sh VARC [RUNS] (run from the repository root; needs redis-server)
set -u
varc=$1 runs=${2:-5}
tmp=$(mktemp -d)
source "$(dirname "$0")/../tests/cache/lib.sh"
trap 'stop_redis "$tmp/redis"; rm -rf "$tmp"' EXIT
require_redis
inputs=(../shared/fixtures shaders)
start_redis "$tmp/redis"
port=$(cat "$tmp/redis/port")
url="redis://127.0.0.1:$port/0"

# seconds CMD...: runs CMD once (its --json summary to $tmp/last.json) and prints the wall time.
seconds() {
    local start end
    start=$(date +%s.%N)
    "$@" >"$tmp/last.json" || fail "$*"
    end=$(date +%s.%N)
    python3 -c "print($end - $start)"
}
median() { sort -g | awk '{ a[NR] = $1 } END { print a[int((NR + 1) / 2)] }'; }

: >"$tmp/cold" ; : >"$tmp/local" ; : >"$tmp/redis-only"
for run in $(seq "$runs"); do
    redis-cli -p "$port" flushall >/dev/null
    rm -rf "$tmp/a" "$tmp/b"
    seconds "$varc" build --json --cache "file:$tmp/a" --cache "$url" -o "$tmp/p.svpack" \
        "${inputs[@]}" >>"$tmp/cold"
    cold_programs=$(json_field "$tmp/last.json" 'j["compiled_programs"]')
    seconds "$varc" build --json --cache "file:$tmp/a" --cache "$url" -o "$tmp/p.svpack" \
        "${inputs[@]}" >>"$tmp/local"
    seconds "$varc" build --json --cache "file:$tmp/b" --cache "$url" -o "$tmp/p.svpack" \
        "${inputs[@]}" >>"$tmp/redis-only"
    [ "$(json_field "$tmp/last.json" 'j["compiled_programs"]')" = 0 ] ||
        fail "the warm-Redis build compiled programs"
done
cold=$(median <"$tmp/cold") local=$(median <"$tmp/local") redis=$(median <"$tmp/redis-only")
printf 'cold build (%s programs compiled): %.3f s\n' "$cold_programs" "$cold"
printf 'warm local folder:                 %.3f s  (%.1fx faster)\n' "$local" "$(python3 -c "print($cold / $local)")"
printf 'warm Redis only, fresh folder:     %.3f s  (%.1fx faster, 0 programs compiled)\n' \
    "$redis" "$(python3 -c "print($cold / $redis)")"
