#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The seed003 reference model is what makes seed 003's shader match: the seed003-* scenes of
# tests/scenes/seeds, copied into WORK_DIR with their materials' "reference" switched to the
# library's "varc-single-pass-lit" (normals by the inverse transpose, normalised per vertex),
# must FAIL `varc validate` where the seed's unnormalised per-vertex normals of scaled objects
# change the vertex lights (seed003-eight-lights, seed003-instanced-vertex-lights).
# Usage: seed003_model_check.sh VARC SEED_TEXT_PACK WORK_DIR
set -uo pipefail

varc="$1"
pack="$2"
work="$3"
fail() { echo "FAIL: $*"; exit 1; }

rm -rf "$work"
mkdir -p "$work/scenes"
for scene in tests/scenes/seeds/seed003-*.json; do
    grep -q '"reference": "seed003"' "$scene" || fail "$scene does not name the seed003 model"
    sed 's/"reference": "seed003"/"reference": "varc-single-pass-lit"/' "$scene" \
        > "$work/scenes/$(basename "$scene")"
done
output=$("$varc" validate --pack "$pack" --scenes "$work/scenes" --out "$work/out" 2>&1)
status=$?
echo "$output"
[[ $status -ne 0 ]] || fail "varc validate passed with the library's model in place of seed003"
for scene in seed003-eight-lights seed003-instanced-vertex-lights; do
    grep -q "^$scene: FAIL" <<<"$output" || fail "$scene matched the library's model"
done
echo "ok: the library's model does not match seed 003's shader; the seed003 model does"
