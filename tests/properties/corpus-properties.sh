#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Property validation over the compatibility corpus, by hand (issue #16; not yet part of
# compat.corpus): builds every corpus shader with a ForwardBase pass that docs/COMPATIBILITY.md
# lists as built and that has at most MAX_VARIANTS variants (one pack each, the repository as
# project root), then runs `varc validate --properties` over all the packs.
# Usage: tests/properties/corpus-properties.sh build/varc ../shared/compat OUT_DIR [MAX_VARIANTS]
set -u
varc=$1 corpus=$2 out=$3 max=${4:-1200}
mkdir -p "$out/packs"
packs=()
while IFS= read -r -d '' file; do
    rel=${file#"$corpus"/}
    case "$rel" in */surface/*) continue ;; esac
    grep -qi "ForwardBase" "$file" || continue
    row=$(grep -F "| \`$rel\` |" docs/COMPATIBILITY.md | head -1)
    case "$row" in *"| built"*) ;; *) continue ;; esac
    variants=$(echo "$row" | awk -F'|' '{gsub(/ /, "", $4); print $4}')
    [ "$variants" -le "$max" ] || { echo "skipped (variants $variants > $max): $rel"; continue; }
    pack="$out/packs/$(echo "$rel" | tr '/ ' '__').svpack"
    if "$varc" build --project-root "$corpus/${rel%%/*}" -o "$pack" "$file" > "$pack.log" 2>&1; then
        packs+=(--pack "$pack")
    else
        echo "build failed: $rel (see $pack.log)"
    fi
done < <(find "$corpus" -name '*.shader' -print0 | sort -z)
"$varc" validate --properties "${packs[@]}" --out "$out/images"
