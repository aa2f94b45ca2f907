#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# An output folder varc may not write: the build fails with the reason, the pack already there is
# untouched and no temporary is left. CI runs as root, which ignores permissions, so the build
# runs as an unprivileged user inside a user namespace (`unshare --user`).
# Usage: readonly_output.sh VARC INPUT... (run from the repository root)
set -u
varc=$1; shift
tmp=$(mktemp -d)
trap 'chmod -R u+w "$tmp"; rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
chmod 755 "$tmp"

unshare --user true 2>/dev/null ||
    fail "cannot run as an unprivileged user here (unshare --user: user namespaces are off)"
mkdir "$tmp/out"
"$varc" build -o "$tmp/out/lights.svpack" "$@" >/dev/null || fail "the first build"
cp "$tmp/out/lights.svpack" "$tmp/before.svpack"
chmod 555 "$tmp/out"
unshare --user "$varc" build -o "$tmp/out/lights.svpack" "$@" >"$tmp/log" 2>&1
code=$?
[ "$code" != 0 ] || fail "the build into a read-only folder exited 0"
grep -q "Permission denied" "$tmp/log" || fail "no reason given: $(cat "$tmp/log")"
grep -qF "$tmp/out/lights.svpack" "$tmp/log" || fail "the output path is not named: $(cat "$tmp/log")"
cmp -s "$tmp/before.svpack" "$tmp/out/lights.svpack" || fail "the existing pack changed"
[ "$(ls -A "$tmp/out")" = lights.svpack ] || fail "stray files: $(ls -A "$tmp/out")"
echo "read-only output folder: exit $code, reason given, the existing pack untouched"
