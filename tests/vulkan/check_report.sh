#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# `varc validate --report` end to end: renders a few scenes into the HTML report, opens it in
# headless Chromium and fails unless every <img> decoded, every in-page link has its anchor, the
# page logged nothing to the console and a screenshot was taken (kept in OUT_DIR as report.png).
# (A report that cannot be written: tests/cli/cases/validate-unwritable-report-fails.)
# With --properties, `varc validate --properties --report` over packs holding the mutants of
# tests/properties and the library: the page's "Property checks" section must show the mutant
# NoAttenuation failing out_of_range with its actual / expected / diff images and worst pixels,
# and varc/Forward and varc-tests/ForwardDeferred passing every relation they apply to.
#   check_report.sh VARC PACK OUT_DIR SCENE.json...    the whole test
#   check_report.sh --properties VARC OUT_DIR PACK...  the property section test
#   check_report.sh --check-page PAGE.html SCREENSHOT.png IMAGES   only the browser checks
set -euo pipefail

fail() {
    echo "check_report: FAILED: $*" >&2
    exit 1
}

chromium_bin=${CHROMIUM:-chromium}
run_chromium() {
    local profile
    profile=$(mktemp -d)
    timeout 120 "$chromium_bin" --headless --no-sandbox --disable-gpu --disable-quic \
        --no-first-run --disable-background-networking --disable-component-update --disable-sync \
        --user-data-dir="$profile" --virtual-time-budget=10000 "$@"
    local status=$?
    rm -rf "$profile"
    return $status
}

# check_page PAGE SCREENSHOT IMAGES: every image of PAGE decoded (IMAGES of them), every in-page
# link has its anchor, no console message, and SCREENSHOT written as a PNG.
check_page() {
    local page=$1 screenshot=$2 images=$3 url
    command -v "$chromium_bin" >/dev/null ||
        fail "'$chromium_bin' not found: install Debian's chromium (scripts/install-deps.sh)"
    url="file://$(realpath "$page")"
    local dom="$screenshot.dom.html" log="$screenshot.console.log"
    run_chromium --enable-logging=stderr --v=0 --dump-dom "$url" >"$dom" 2>"$log" ||
        fail "chromium --dump-dom exited with $? (log: $log)"
    local body
    body=$(grep -o '<body[^>]*>' "$dom" | sed -n 1p)
    echo "check_report: $body"
    [[ $body == *'data-images-checked="yes"'* ]] ||
        fail "the page's image check did not run (no data-images-checked on <body>)"
    [[ $body == *"data-images=\"$images\""* ]] || fail "expected $images images: $body"
    [[ $body == *'data-broken-images=""'* ]] || fail "images that did not load: $body"
    [[ $body == *'data-broken-links=""'* ]] || fail "links to missing anchors: $body"
    if grep -E 'CONSOLE|Uncaught' "$log"; then fail "the page wrote to the console (above)"; fi
    rm -f "$screenshot"
    run_chromium --hide-scrollbars --window-size=1280,2000 --screenshot="$screenshot" "$url" \
        >/dev/null 2>>"$log" || fail "chromium --screenshot exited with $? (log: $log)"
    [[ $(head -c 8 "$screenshot" 2>/dev/null | od -An -tx1 | tr -d ' \n') == 89504e470d0a1a0a ]] ||
        fail "no PNG screenshot at $screenshot"
    echo "check_report: page ok, $images images loaded; screenshot $screenshot"
}

# Under pipefail, a reader that stops early (`head`, `grep -q`) can kill the writer with SIGPIPE
# and fail the pipeline at random; the readers here consume their whole input.
# row_of DOM SHADER: the Property checks table row of SHADER (on one line).
row_of() {
    tr '\n' ' ' <"$1" | grep -oP "<tr data-shader=\"$2\".*?</tr>" | sed -n 1p
}

# check_properties VARC OUT_DIR PACK...: the property section test (see the top).
check_properties() {
    local varc=$1 out=$2 status=0 name images=0 pack
    shift 2
    local packs=()
    for pack in "$@"; do packs+=(--pack "$pack"); done
    mkdir -p "$out"
    rm -rf "$out/png" "$out/report.html"
    "$varc" validate --properties "${packs[@]}" --out "$out/png" --report "$out/report.html" \
        >"$out/validate.log" 2>&1 || status=$?
    [[ $status -eq 1 ]] ||
        fail "validate --properties over the mutants exited with $status, not 1 ($out/validate.log)"
    [[ -s $out/report.html ]] || fail "no report at $out/report.html"
    grep -q 'http://\|https://' "$out/report.html" && fail "the report names a network URL"
    # Every image the page shows is a PNG the run wrote.
    while read -r name; do
        [[ -n $(find "$out/png" -name "$name") ]] || fail "the page shows $name, not in $out/png"
        images=$((images + 1))
    done < <(grep -o '<code>[^<]*\.png</code>' "$out/report.html" | sed 's/<[^>]*>//g')
    check_page "$out/report.html" "$out/report.png" "$images"
    local dom="$out/report.png.dom.html" row kind
    grep -q '<h2 id="property-checks">Property checks</h2>' "$dom" || fail "no Property checks"
    grep -q 'data-shader="varc-mutants/NoAttenuation" data-relation="out_of_range"' "$dom" ||
        fail "no failing out_of_range section for varc-mutants/NoAttenuation"
    for kind in actual expected diff; do
        grep -q "alt=\"varc-mutants/NoAttenuation out_of_range point $kind\"" "$dom" ||
            fail "no $kind image of NoAttenuation's out_of_range case 'point'"
    done
    local section
    section=$(tr '\n' ' ' <"$dom" |
        grep -oP 'data-shader="varc-mutants/NoAttenuation" data-relation="out_of_range">.*?</div>' ||
        true)
    [[ $section == *'worst: ('* ]] || fail "NoAttenuation's out_of_range section shows no worst pixels"
    row=$(row_of "$dom" varc-mutants/NoAttenuation)
    [[ $row == *'data-result="FAIL"'* && $row == *'href="#prop-'* ]] ||
        fail "NoAttenuation's row does not fail with a link to its failure: $row"
    for name in varc/Forward varc-tests/ForwardDeferred; do
        row=$(row_of "$dom" "$name")
        [[ -n $row ]] || fail "no Property checks row for $name"
        [[ $row == *'data-result="pass"'* && $row != *'class="fail"'* ]] ||
            fail "$name does not pass every relation in the report: $row"
    done
    [[ $(row_of "$dom" varc-tests/ForwardDeferred | grep -o '<td class="pass">pass</td>' |
        wc -l) -eq 17 ]] || fail "varc-tests/ForwardDeferred does not show 17 passing relations"
    echo "check_report: property section ok ($images images of failing cases)"
}

if [[ ${1:-} == --properties ]]; then
    [[ $# -ge 4 ]] || fail "usage: $0 --properties VARC OUT_DIR PACK..."
    shift
    check_properties "$@"
    exit 0
fi

if [[ ${1:-} == --check-page ]]; then
    [[ $# -eq 4 ]] || fail "usage: $0 --check-page PAGE.html SCREENSHOT.png IMAGES"
    check_page "$2" "$3" "$4"
    exit 0
fi

[[ $# -ge 4 ]] || fail "usage: $0 VARC PACK OUT_DIR SCENE.json..."
varc=$1 pack=$2 out=$3
shift 3
rm -rf "$out/scenes"
mkdir -p "$out/scenes"
for scene in "$@"; do ln -s "$(realpath "$scene")" "$out/scenes/"; done

rm -f "$out/report.html"
"$varc" validate --pack "$pack" --scenes "$out/scenes" --out "$out/png" \
    --report "$out/report.html" || fail "varc validate --report exited with $?"
[[ -s $out/report.html ]] || fail "no report at $out/report.html"
grep -q 'http://\|https://' "$out/report.html" && fail "the report names a network URL"
# Four images per scene: GPU, reference, difference, mask.
check_page "$out/report.html" "$out/report.png" $(($# * 4))

