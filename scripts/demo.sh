#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Installs what is missing, builds, and shows what varc does with the shader library and the
# seed fixtures. Outputs land in ${VARC_DEMO_DIR:-demo-out}.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
build=${VARC_BUILD_DIR:-$root/build}
out=${VARC_DEMO_DIR:-$root/demo-out}
mkdir -p "$out"
varc="$build/varc"
cd "$root"

fixtures=../shared/fixtures
echo
echo "== varc variants: the seed fixtures =="
if [ -d "$fixtures" ]; then
    "$varc" variants "$fixtures"
    "$varc" variants --json --list "$fixtures" > "$out/fixtures-variants.json"
    "$varc" lock -o "$out/fixtures.lock" "$fixtures"
    "$varc" check --lock "$out/fixtures.lock" "$fixtures"
else
    echo "(no ../shared/fixtures beside the checkout; skipped)"
fi

echo
echo "== varc's lighting shader library (shaders/) =="
"$varc" variants shaders
"$varc" check --lock shaders/variants.lock shaders
echo
echo "== varc build: the library into one pack (every variant, SPIR-V validated) =="
"$varc" build -o "$out/library.svpack" shaders

fixture_packs=()
if [ -d "$fixtures" ]; then
    echo
    echo "== varc build: the seed fixtures, one pack each =="
    for dir in "$fixtures"/*/; do
        name=$(basename "$dir")
        "$varc" build -o "$out/$name.svpack" "$dir"
        fixture_packs+=("$out/$name.svpack")
    done
fi

echo
echo "== varc info and lookup: what the runtime sees =="
"$varc" info "$out/library.svpack"
if [ ${#fixture_packs[@]} -gt 0 ]; then
    "$varc" lookup "${fixture_packs[0]}" --shader "Custom/My First Lighting Shader" --pass ForwardAdd \
        --light spot
fi

echo
echo "== varc validate: the forward scenes on lavapipe against the CPU reference =="
pack_args=(--pack "$out/library.svpack")
for pack in "${fixture_packs[@]}"; do pack_args+=(--pack "$pack"); done
validate_status=0
"$varc" validate "${pack_args[@]}" --scenes tests/scenes/forward --out "$out/scenes" || validate_status=$?

echo
echo "== varc validate: the deferred scenes (G-buffer, per-light passes, HDR and LDR encoding) =="
"$varc" validate "${pack_args[@]}" --scenes tests/scenes/deferred --out "$out/deferred" || validate_status=$?

echo
echo "== varc validate: the single-pass forward scenes (light buffer, per-object light lists, instancing) =="
"$varc" validate "${pack_args[@]}" --scenes tests/scenes/single_pass --out "$out/single-pass" || validate_status=$?

seeds=../shared/seeds
if [ -d "$seeds" ]; then
    echo
    echo "== varc validate: seeds 001, 003 and 004 as their texts print them"
    echo "   (assembled in $out/seed-texts; the lightmaps-* scenes draw every ForwardBase variant"
    echo "   of 001 and 004, the seed003-* scenes both variants of 003),"
    echo "   seed 002's own Custom/DeferredShading as the deferred path's light shader =="
    bash tests/library/assemble_seeds.sh "$seeds" "$out/seed-texts"
    "$varc" build -o "$out/seed-texts.svpack" "$out/seed-texts/seed001" \
        "$out/seed-texts/seed003" "$out/seed-texts/seed004"
    "$varc" validate "${pack_args[@]}" --pack "$out/seed-texts.svpack" \
        --scenes tests/scenes/seeds --out "$out/seeds" || validate_status=$?
fi

echo
echo "== summary =="
echo "variant listings: $out/fixtures-variants.json"
echo "lock file:        $out/fixtures.lock"
echo "library pack:     $out/library.svpack"
for pack in "${fixture_packs[@]}"; do echo "fixture pack:     $pack"; done
echo "rendered scenes:  $out/scenes/<scene>.png, .reference.png (CPU), .diff.png"
echo "deferred:         $out/deferred/<scene>.png, .reference.png, .diff.png"
echo "single-pass:      $out/single-pass/<scene>.png, .reference.png, .diff.png"
echo "seed shaders:     $out/seeds/<scene>.png, .reference.png, .diff.png"
exit $validate_status
