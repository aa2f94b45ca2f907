#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The compatibility corpus test (issue #10): every third-party `.shader` in ../shared/compat
# goes through `varc variants` and `varc build` as a user would run them, with the repository's
# folder as the include root (for the surface shaders in surface/, the repository folder inside
# surface/). The results become the table of
# docs/COMPATIBILITY.md; the test fails when
#   * varc crashes or hangs on any file (exit status other than 0 or 1, or the time limit), or
#     prints a glslang message that is not mapped to a file:line;
#   * a file that the committed table says builds no longer builds;
#   * anything else in the table changed (a file now builds, a reason changed): the table must
#     stay true, so rerun with --update and commit docs/COMPATIBILITY.md.
# Usage: corpus.sh VARC COMPAT_DIR DOC WORK_DIR [--update | --crashes-only]
# --crashes-only (the sanitizer job, where builds run several times slower): each pass builds an
# even sample of 32 of its variants (`--sample-variants`: every pass and every file still goes
# through the whole pipeline, and passes too big to build whole here are sampled instead of
# refused), and only crashes, hangs and unmapped messages fail the run.
# 32 rather than 64 keeps CI within its budget (#26): the largest pass, Grass_TransCutout, takes
# 14.8 s instead of 25.5 s under the sanitizers; the normal job builds every variant.
# The corpus is read in place and never copied into the project.
set -uo pipefail

varc="$1"
compat="$2"
doc="$3"
work="$4"
update="${5:-}"
unset VARC_BUILTIN_INCLUDE_DIR

[ -d "$compat" ] || { echo "FAIL: the compatibility corpus $compat is missing (../shared beside the checkout)"; exit 1; }
rm -rf "$work"
mkdir -p "$work/logs"
compat=$(cd "$compat" && pwd)
results="$work/results.tsv"
# Passes with more variants are refused before enumeration (a full Standard shader has 1.27
# million): the test stays within minutes, and such a refusal is a documented limit.
max_variants=200000
sample=()
[ "$update" = --crashes-only ] && sample=(--sample-variants 32)
: >"$results"
status=0

# One line of reason: the first error as "where: message", where is the line in the shader
# ("line 12") or the include file and line ("Noise.cginc:4"); no search list, at most 160 chars.
reasonOf() {
    local first
    first=$(grep -m1 -E 'error:' "$1" | sed -e "s|$compat/||g" -e 's/; searched: .*//')
    [ -n "$first" ] || return 0
    awk -v shader="$2" '{
        i = index($0, ": error: ")
        if (i == 0) { print $0; exit }
        where = substr($0, 1, i - 1); message = substr($0, i + 9)
        n = split(where, part, ":")
        file = part[1]; line = (n >= 2) ? part[2] : ""
        if (file == shader) where = "line " line
        else { sub(/.*\//, "", file); where = file (line != "" ? ":" line : "") }
        print where ": " message
    }' <<<"$first" | sed -e 's/|/\\|/g' | cut -c1-160
}

while IFS= read -r -d '' file; do
    rel=${file#"$compat"/}
    repo=${rel%%/*}
    if [ "$repo" = surface ]; then
        inner=${rel#surface/}
        repo="surface/${inner%%/*}"
    fi
    log="$work/logs/$(tr '/ ' '__' <<<"$rel")"
    timeout 300 "$varc" variants --json -I "$compat/$repo" "$file" >"$log.variants" 2>&1
    vstatus=$?
    # A hang detector, not a speed check: the largest file (whiteflare Grass_TransCutout, 34952
    # variants, 69904 preprocessings) takes 5 minutes on an idle 2-core machine and 20 with the
    # machine shared five ways, so a shared CI machine gets 20 minutes per file.
    timeout 1200 "$varc" build -j 2 --max-variants "$max_variants" "${sample[@]}" -o "$work/out.svpack" \
        -I "$compat/$repo" "$file" >"$log.build" 2>&1
    bstatus=$?
    passes=$(grep -o '"index":' "$log.variants" | wc -l)
    variants=$(grep -o '"variants":[0-9]*' "$log.variants" | tail -n 1 | cut -d: -f2)
    if [ "$vstatus" -gt 1 ] || [ "$bstatus" -gt 1 ]; then
        echo "FAIL: $rel: varc exited with $vstatus (variants) / $bstatus (build): crash or hang"
        tail -5 "$log.build"
        status=1
    fi
    # A glslang message without our file:line mapping (ERROR: 0:12: ...), or an error that
    # names no file and line at all, must never reach a user.
    if grep -q -E '^(ERROR|WARNING): [0-9]+:|^varc: (error|warning):' "$log.build"; then
        echo "FAIL: $rel: a message without its file:line reached the output"
        grep -m3 -E '^(ERROR|WARNING): [0-9]+:|^varc: (error|warning):' "$log.build"
        status=1
    fi
    if [ "$bstatus" -eq 0 ]; then
        outcome="built"
        reason=""
        # Passes whose only_renderers / exclude_renderers leave Vulkan out are not compiled.
        skipped=$(grep -c "is not compiled: its '#pragma" "$log.build")
        if [ "$skipped" -gt 0 ]; then
            reason="$skipped not for Vulkan ($(grep -m1 -o "'#pragma [a-z_]*renderers[^']*'" "$log.build" | tr -d "'"))"
        fi
    else
        outcome="refused"
        reason=$(reasonOf "$log.build" "$rel")
        [ -n "$reason" ] || reason=$(reasonOf "$log.variants" "$rel")
    fi
    printf '%s|%s|%s|%s|%s\n' "$rel" "$passes" "${variants:-0}" "$outcome" "$reason" >>"$results"
done < <(find "$compat" -name '*.shader' -print0 | LC_ALL=C sort -z)

total=$(wc -l <"$results")
built=$(grep -c '|built|' "$results")
surfaces=$(grep -c '^surface/' "$results")
surfacesBuilt=$(grep '^surface/' "$results" | grep -c '|built|')
table="$work/COMPATIBILITY.md"
{
    cat <<EOF
# Compatibility with real-world shaders

Third-party shaders written for Unity's built-in pipeline (\`../shared/compat/\`: one folder per
public repository, read in place, never copied). For every \`.shader\`, \`varc variants\` and
\`varc build --max-variants $max_variants\` run with the repository's folder as the include root
(for the surface shaders in \`surface/\`, the repository's folder inside \`surface/\`).
This page is written by the test \`compat.corpus\` (tests/compat/corpus.sh) and checked by it:
the test fails when a file that built stops building, when varc crashes, hangs or prints a
glslang message without its file:line, and when this table is no longer true. After an
intended change: \`bash tests/compat/corpus.sh build/varc ../shared/compat docs/COMPATIBILITY.md
build/compat --update\`.

**$built of $total files build every variant** (of the passes Unity compiles for Vulkan: a
pass whose \`#pragma only_renderers\` or \`exclude_renderers\` leaves Vulkan out is not compiled,
as in Unity, and the table says so). Of them, $surfacesBuilt of the $surfaces surface shaders in
\`surface/\` (\`#pragma surface\`) build: varc generates their passes
([SURFACE_SHADERS.md](SURFACE_SHADERS.md)).

## Why the remaining files are refused

Each refusal below is either a limit of varc named here or a fault in the shader that Microsoft's
fxc (which Unity uses for Direct3D) rejects as well.

* **Too many variants** (\`--max-variants\`): a full Standard-style pass of over a million
  variants is refused before enumeration; build it with a higher limit or strip keywords.
* **Faults in the shader**: a variable declared twice in one scope when two keywords are on
  together (\`redefinition\`); \`TRANSFER_SHADOW\` in a struct without the \`pos\` member it
  writes (\`SHADOWS_SCREEN\`); \`tex2D\` on the cube cookie \`_LightTexture0\` of a
  \`POINT_COOKIE\` variant (\`Expected Coordinate to have at least 3 components\`); a fragment
  program reading inputs its vertex program never writes, whose \`SHADOWS_CUBE\` variant also
  names an undeclared \`i\`.

| file | passes | variants | result |
|---|---:|---:|---|
EOF
    while IFS='|' read -r rel passes variants outcome reason; do
        if [ "$outcome" = built ] && [ -n "$reason" ]; then
            echo "| \`$rel\` | $passes | $variants | built; passes: $reason |"
        elif [ "$outcome" = built ]; then
            echo "| \`$rel\` | $passes | $variants | built |"
        else
            echo "| \`$rel\` | $passes | $variants | refused: $reason |"
        fi
    done <"$results"
} >"$table"

if [ "$update" = --crashes-only ]; then
    echo "corpus (crashes only, 32 variants of each pass of at most $max_variants): $built of $total built"
    exit $status
fi
# The page's hand-written tail is kept by --update and not compared here: from the section
# "## Text Unity accepts" (the leniency rules, each naming its test) or, when it is missing,
# "## Property validation" (compat.properties' own, tests/properties/corpus-properties.sh).
tail_heading='^## (Text Unity accepts|Property validation)'
# The page up to that tail, without the blank lines before it.
docHead() {
    awk -v h="$tail_heading" '$0 ~ h { exit } { lines[++n] = $0 }
        END { while (n > 0 && lines[n] == "") --n; for (i = 1; i <= n; ++i) print lines[i] }' "$doc"
}
docTail() { awk -v h="$tail_heading" '$0 ~ h { keep = 1 } keep' "$doc"; }
if [ "$update" = --update ]; then
    {
        cat "$table"
        if grep -qE "$tail_heading" "$doc"; then echo; docTail; fi
    } >"$work/doc.md"
    cp "$work/doc.md" "$doc"
    echo "corpus: $built of $total built; $doc updated"
    exit $status
fi

# Regressions first: a file the committed table lists as built must still build.
while IFS= read -r line; do
    rel=$(sed -E 's/^\| `([^`]*)`.*/\1/' <<<"$line")
    if ! grep -F "$rel|" "$results" | grep -F '|built|' >/dev/null; then
        echo "FAIL: $rel built before and no longer builds:"
        grep -F "$rel|" "$results" | cut -d'|' -f5
        status=1
    fi
done < <(docHead | grep -E '\| built(; [^|]*)? \|$')

if ! diff -u <(docHead) "$table" >"$work/table.diff"; then
    echo "FAIL: docs/COMPATIBILITY.md is not true any more; the differences:"
    head -60 "$work/table.diff"
    echo "(rerun with --update after an intended change)"
    status=1
fi
echo "corpus: $built of $total files built"
exit $status
