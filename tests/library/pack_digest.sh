#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The library and fixture packs, fingerprinted: the SHA-256 of every SPIR-V program `varc extract`
# writes, of its manifest (stage, entry point, source) and of `varc info --json` (shaders,
# passes, keyword sets, variant and program counts), without the pack's own path, its inputs
# hash and its size: those also cover the include files a build read (their text and the list
# each program records), which change whenever varc's built-in library grows. The fingerprint is committed in
# tests/library/packs.digest, so a change that alters any program of varc's library or of the
# seed fixtures fails here unless it is meant: then rerun with VARC_UPDATE_GOLDENS=1 and commit.
# Usage: pack_digest.sh VARC WORK_DIR DIGEST_FILE   (from the repository root)
set -uo pipefail
varc="$1" work="$2" digest="$3"
unset VARC_BUILTIN_INCLUDE_DIR
rm -rf "$work"
mkdir -p "$work"
actual="$work/packs.digest"
: >"$actual"
for input in shaders ../shared/fixtures/seed000-multiple-lights ../shared/fixtures/seed002-deferred-lights; do
    name=$(basename "$input")
    if ! "$varc" build -j 2 -o "$work/$name.svpack" "$input" >"$work/$name.log" 2>&1; then
        cat "$work/$name.log"
        echo "FAIL: varc build $input"
        exit 1
    fi
    "$varc" extract "$work/$name.svpack" -o "$work/$name" >/dev/null || exit 1
    sed -i '/"pack":/d' "$work/$name/manifest.json"
    "$varc" info --json "$work/$name.svpack" |
        sed -e 's/"file":"[^"]*",\{0,1\}//' -e 's/"inputs_hash":"[^"]*",\{0,1\}//' \
            -e 's/,"pack":[0-9]*//' >"$work/$name/info.json"
    (cd "$work/$name" && sha256sum -- *) | sed "s|^|$name |" >>"$actual"
done
if [ "${VARC_UPDATE_GOLDENS:-}" = 1 ]; then
    cp "$actual" "$digest"
    echo "pack digest: $digest updated ($(wc -l <"$actual") entries)"
    exit 0
fi
if ! diff -u "$digest" "$actual"; then
    echo "FAIL: the library or fixture packs changed (lines above: - committed, + now)."
    echo "If that is intended, rerun with VARC_UPDATE_GOLDENS=1 and commit $digest."
    exit 1
fi
echo "pack digest: $(wc -l <"$actual") entries match"
