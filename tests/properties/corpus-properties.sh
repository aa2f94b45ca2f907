#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The compatibility corpus's property validation (issue #16), the test compat.properties: every
# corpus shader with a ForwardBase pass (its own, or generated from `#pragma surface`) that
# docs/COMPATIBILITY.md's build table lists as built
# and that has at most MAX_VARIANTS variants is built into its own pack (the repository as
# project root) and run through `varc validate --properties`. The verdicts become the section
# "## Property validation" of docs/COMPATIBILITY.md (a column per relation); the test fails when
#   * a pack no longer builds, a shader no longer renders, or varc crashes or hangs;
#   * any verdict or model in that section changed (a regression in varc, or a change in the
#     relations): after an intended change rerun with --update and commit the page.
# The last column, the cause of each FAIL, is written by hand and kept by --update (a new row
# gets "not analysed").
# Usage: corpus-properties.sh VARC COMPAT_DIR DOC WORK_DIR [--update] (MAX_VARIANTS: env, 1200)
set -uo pipefail
varc=$1 compat=$2 doc=$3 work=$4 update=${5:-}
max=${MAX_VARIANTS:-1200}
heading="## Property validation"
unset VARC_BUILTIN_INCLUDE_DIR

[ -d "$compat" ] || { echo "FAIL: the compatibility corpus $compat is missing (../shared beside the checkout)"; exit 1; }
[ -x "$varc" ] || { echo "FAIL: no varc at $varc"; exit 1; }
compat=$(cd "$compat" && pwd)
rm -rf "$work"
mkdir -p "$work/packs" "$work/logs"
rows="$work/rows.md"
: >"$rows"
skipped=()
trimmed=()
unlit=()
status=0
relations=(finite dark lit out_of_range black_cookie white_cookie additivity additivity_ldr
           intensity translation rotation mirror scale light_axis behind forward_deferred every_variant)

# "a, b, c" ("none" when empty).
commaList() {
    [ $# -gt 0 ] || { echo none; return; }
    local IFS=,
    sed 's/,/, /g' <<<"$*"
}

# The cause of |rel|'s row for |shader| in the committed section ("not analysed" when new).
causeOf() {
    local cause
    cause=$(sed -n "/^$heading/,\$p" "$doc" | grep -F "| \`$1\` | \`$2\` |" | head -1 |
            awk -F' \\| ' '{print $NF}' | sed 's/ |$//')
    echo "${cause:-not analysed}"
}

# One table row per shader from `varc validate --properties` output: the row's fields end with
# the 16 verdicts, the model, renders, drawn, time and the light types; the name may hold spaces.
rowsOf() {
    awk -v n="${#relations[@]}" '
        NR == 1 { next }
        / lit shaders hold every relation/ { next }
        {
            for (j = n + 2; j <= NF; ++j) {
                if ($j !~ /^(lit|not-lit|non-linear)$/) continue
                ok = 1
                for (k = j - n; k < j; ++k) if ($k !~ /^(pass|FAIL|n\/a)$/) ok = 0
                if (!ok) continue
                name = $1
                for (k = 2; k < j - n; ++k) name = name " " $k
                line = name "\t" $j
                for (k = j - n; k < j; ++k) line = line "\t" $k
                if ($NF == "ERROR") line = line "\tERROR"
                print line
                break
            }
        }' "$1"
}

# |1| with its material-keyword pragmas commented out (the line numbers kept): a
# `multi_compile`/`shader_feature` (`_local`, per stage) whose first option is `_` or `__`, and a
# one-keyword `shader_feature` (`_ K`): each keyword is off in every variant left, which are the
# only ones the generated scenes (no material keyword) draw. The shortcuts (`multi_compile_fwdbase`,
# `_fog`, ...) and sets without an off state stay.
trimmedCopy() {
    local stage='(_vertex|_fragment|_hull|_domain|_geometry)?'
    sed -E "s@^([[:space:]]*)#pragma[[:space:]]+(((multi_compile|shader_feature)(_local)?$stage[[:space:]]+__?[[:space:]].*)|shader_feature(_local)?$stage[[:space:]]+[A-Za-z0-9_]+[[:space:]]*(//.*)?)\$@\1// (trimmed) #pragma \2@" "$1"
}

# The screen-space shadow collector (varc's shaders/internal), beside every corpus pack: with it
# the checks draw directional shadows too (every_variant).
root=$(cd "$(dirname "$0")/../.." && pwd)
internal="$work/packs/internal.svpack"
if ! "$varc" build -o "$internal" "$root/shaders/internal" >"$work/logs/internal.build" 2>&1; then
    echo "FAIL: shaders/internal does not build (see $work/logs/internal.build)"
    exit 1
fi

while IFS= read -r -d '' file; do
    rel=${file#"$compat"/}
    # A surface shader (`#pragma surface`) gets its ForwardBase pass from varc's generator.
    grep -qi "ForwardBase" "$file" || grep -q "pragma[[:space:]]*surface" "$file" || continue
    row=$(grep -F "| \`$rel\` |" "$doc" | head -1)
    case "$row" in *"| built"*) ;; *) continue ;; esac
    variants=$(echo "$row" | awk -F'|' '{gsub(/ /, "", $4); print $4}')
    name=$(tr '/ ' '__' <<<"$rel")
    pack="$work/packs/$name.svpack"
    log="$work/logs/$name"
    source=$file
    # The include root: the repository folder, also the project root; a surface shader's
    # repository folder is inside surface/, and its project root (the folder holding the Assets/
    # its includes name, which may be deeper) is found by varc, as compat.corpus lets it.
    includes=(-I "$(dirname "$file")" --project-root "$compat/${rel%%/*}")
    case "$rel" in surface/*)
        inner=${rel#surface/}
        includes=(-I "$compat/surface/${inner%%/*}" -I "$(dirname "$file")") ;;
    esac
    if [ "$variants" -gt "$max" ]; then
        # Too many variants to build in the test's time: a trimmed copy holds the variants the
        # checks draw (every material keyword off; see trimmedCopy), its includes read in place.
        source="$work/trimmed/$rel"
        mkdir -p "$(dirname "$source")"
        trimmedCopy "$file" >"$source"
        kept=$("$varc" variants --json "${includes[@]}" "$source" 2>/dev/null |
               grep -o '"variants":[0-9]*' | tail -n 1 | cut -d: -f2)
        if [ -z "$kept" ] || [ "$kept" -gt "$max" ]; then
            skipped+=("\`$rel\` ($variants; ${kept:-?} trimmed)")
            continue
        fi
        trimmed+=("\`$rel\` ($variants → $kept)")
    fi
    timeout 600 "$varc" build "${includes[@]}" \
        -o "$pack" "$source" >"$log.build" 2>&1
    bstatus=$?
    if [ "$bstatus" -ne 0 ]; then
        echo "FAIL: $rel: the pack does not build (exit $bstatus; see $log.build)"
        tail -3 "$log.build"
        echo "| \`$rel\` | | does not build |$(printf ' |%.0s' "${relations[@]}") $(causeOf "$rel" "") |" >>"$rows"
        status=1
        continue
    fi
    timeout 600 "$varc" validate --properties --pack "$pack" --pack "$internal" \
        --out "$work/images/$name" \
        >"$log.out" 2>"$log.err"
    vstatus=$?
    # "ForwardBase" in the text but no lit pass in the pack: listed, not checked.
    if [ "$vstatus" -eq 1 ] && grep -q "no shader with a ForwardBase pass" "$log.err"; then
        if grep -q "is not compiled: its '#pragma" "$log.build"; then
            unlit+=("\`$rel\` (not for Vulkan)")
        else
            unlit+=("\`$rel\` (no ForwardBase pass compiled)")
        fi
        continue
    fi
    if [ "$vstatus" -gt 1 ]; then
        echo "FAIL: $rel: varc validate --properties exited with $vstatus (crash, hang or no device)"
        tail -3 "$log.err"
        status=1
    fi
    found=0
    while IFS=$'\t' read -r shader model verdicts; do
        found=1
        case "$verdicts" in *ERROR*)
            echo "FAIL: $rel: $shader does not render:"
            grep -m1 "error:" "$log.err"
            status=1
            model="does not render"
            verdicts=${verdicts%$'\t'ERROR} ;;
        esac
        cause=-
        case "$verdicts" in *FAIL*) cause=$(causeOf "$rel" "$shader") ;; esac
        echo "| \`$rel\` | \`$shader\` | $model | ${verdicts//$'\t'/ | } | $cause |" >>"$rows"
    done < <(rowsOf "$log.out")
    if [ "$found" -eq 0 ]; then
        echo "FAIL: $rel: no lit shader checked (see $log.out, $log.err)"
        status=1
    fi
done < <(find "$compat" -name '*.shader' -print0 | LC_ALL=C sort -z)

checked=$(grep -c . "$rows")
clean=$(grep -v 'FAIL\|does not' "$rows" | grep -c .)
notLit=$(grep -c '| not-lit |' "$rows")
nonLinear=$(grep -c '| non-linear |' "$rows")
section="$work/section.md"
{
    cat <<EOF
$heading

Written and checked by the test \`compat.properties\` (tests/properties/corpus-properties.sh):
every file above that builds and has a \`ForwardBase\` pass (over $max variants: a trimmed copy,
below) is built into its own pack and run through \`varc validate --properties\`; docs/PROPERTIES.md has the
relations, their tolerances and the models. The test fails when a pack stops building, a shader
stops rendering or any verdict below changes. After an intended change: \`bash
tests/properties/corpus-properties.sh build/varc ../shared/compat docs/COMPATIBILITY.md
build/compat-properties --update\` (the cause column, written by hand, is kept).

**$clean of $checked shaders with lit passes hold every relation that applies** ($notLit
not lit: their relations about lights are n/a; $nonLinear with a non-linear model: \`intensity\`
is n/a). Over $max variants, checked on a trimmed copy (variants → kept): $(commaList \
"${trimmed[@]}"); the copy, written in the work folder, comments out each material-keyword
pragma with an off state (\`multi_compile _ ...\`, \`shader_feature\`), so its pack holds the
variants with every material keyword off: those the scenes, which set no keyword, draw, and the
set \`every_variant\` compares with. Not checked: $(commaList "${skipped[@]}"). No lit pass in
varc's pack, though the text names \`ForwardBase\`: $(commaList "${unlit[@]}"). A
pass whose \`#pragma only_renderers\` leaves out Vulkan is not compiled, as in Unity. \`forward_deferred\`
applies to a shader with a \`Deferred\` pass besides its forward passes only (n/a otherwise).

**\`LightMode\` on a SubShader.** varc gives a SubShader's (or its Category's) \`LightMode\` tag
to each of its passes that sets none; a pass's own tag wins. Unity's manual asks for
\`LightMode\` in the Pass, but Unity's compiler writes a SubShader's tags into each pass's tags:
its compiled listings show a SubShader's \`Queue\` and \`RenderType\` in every Pass's \`Tags\`,
and shaders rely on it (the Crest ocean's built-in-pipeline shader, wave-harmonic/crest, tags
only its SubShader \`"LightMode"="ForwardBase"\` so that Unity sets the main light's uniforms).
Eleven corpus files are written so (Shell, ToonLit, BlinnPhong and eight of liminal-bear's); they
are checked below.

| file | shader | model | $(IFS='|'; echo "${relations[*]}" | sed 's/|/ | /g') | cause of each FAIL |
|---|---|---|$(printf -- '---|%.0s' "${relations[@]}")---|
EOF
    cat "$rows"
} >"$section"

if [ "$update" = --update ]; then
    # The page before the section (compat.corpus's), one blank line, the section.
    awk -v h="$heading" 'index($0, h) == 1 { exit } { lines[++n] = $0 }
        END { while (n > 0 && lines[n] == "") --n; for (i = 1; i <= n; ++i) print lines[i] }' \
        "$doc" >"$work/doc.md"
    { echo; cat "$section"; } >>"$work/doc.md"
    cp "$work/doc.md" "$doc"
    echo "corpus properties: $clean of $checked hold every relation; $doc updated"
    exit $status
fi
if ! diff -u <(sed -n "/^$heading/,\$p" "$doc") "$section" >"$work/section.diff"; then
    echo "FAIL: the property verdicts in $doc are not true any more; the differences:"
    head -60 "$work/section.diff"
    echo "(rerun with --update after an intended change)"
    status=1
fi
echo "corpus properties: $clean of $checked shaders hold every relation that applies"
exit $status
