#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Runs one declarative CLI case against the built varc executable.
#
# A case is a directory holding:
#   args           the command line after `varc`, one argument per line; @CASE@ expands to the
#                  case directory, @TMP@ to a fresh temporary directory
#   exit           the expected exit code (default 0)
#   stdout         optional: the exact expected standard output
#   stderr         optional: the exact expected standard error
#   stderr.grep    optional: lines that must each appear in standard error (fixed strings)
#   stdout.grep    optional: lines that must each appear in standard output
#   env            optional: NAME=VALUE lines, set in the command's environment only
#   setup          optional: bash run first (cwd = repo root) with $VARC, $CASE and $TMP set
#   verify         optional: bash run last, same environment; the case fails unless it exits 0
#                  (for checks on files the command wrote, or on what it must not have written)
# The command runs with the repository root as its working directory, so fixtures are named
# `../shared/fixtures/...` exactly as CI lays them out. VARC_UPDATE_GOLDENS=1 rewrites
# stdout/stderr from the actual output.
set -u
varc=$1 case_dir=$2 repo=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$repo" || exit 1

args=()
while IFS= read -r line || [ -n "$line" ]; do
    line=${line//@CASE@/$case_dir}
    line=${line//@TMP@/$tmp}
    args+=("$line")
done < "$case_dir/args"

if [ -f "$case_dir/setup" ]; then
    VARC=$varc CASE=$case_dir TMP=$tmp bash "$case_dir/setup" || { echo "setup failed"; exit 1; }
fi

environment=()
if [ -f "$case_dir/env" ]; then
    while IFS= read -r line || [ -n "$line" ]; do
        [ -n "$line" ] && environment+=("$line")
    done < "$case_dir/env"
fi
env "${environment[@]}" "$varc" "${args[@]}" > "$tmp/stdout" 2> "$tmp/stderr"
code=$?
expected_exit=$(cat "$case_dir/exit" 2>/dev/null || echo 0)
status=0

if [ "${VARC_UPDATE_GOLDENS:-0}" = 1 ]; then
    [ -f "$case_dir/stdout" ] && cp "$tmp/stdout" "$case_dir/stdout"
    [ -f "$case_dir/stderr" ] && cp "$tmp/stderr" "$case_dir/stderr"
fi
if [ "$code" != "$expected_exit" ]; then
    echo "exit code: expected $expected_exit, got $code"; status=1
fi
for stream in stdout stderr; do
    if [ -f "$case_dir/$stream" ] && ! diff -u "$case_dir/$stream" "$tmp/$stream"; then
        echo "$stream differs (above)"; status=1
    fi
    if [ -f "$case_dir/$stream.grep" ]; then
        while IFS= read -r want || [ -n "$want" ]; do
            [ -z "$want" ] && continue
            want=${want//@CASE@/$case_dir}
            if ! grep -qF -- "$want" "$tmp/$stream"; then
                echo "$stream lacks: $want"; status=1
            fi
        done < "$case_dir/$stream.grep"
    fi
done
if [ -f "$case_dir/verify" ]; then
    if ! VARC=$varc CASE=$case_dir TMP=$tmp bash "$case_dir/verify"; then
        echo "verify failed"; status=1
    fi
fi
if [ $status != 0 ]; then
    echo "--- command: varc ${args[*]}"
    echo "--- stdout:"; cat "$tmp/stdout"
    echo "--- stderr:"; cat "$tmp/stderr"
fi
exit $status
