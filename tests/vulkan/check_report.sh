#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# `varc validate --report` end to end: renders a few scenes into the HTML report, opens it in
# headless Chromium and fails unless every <img> decoded, every in-page link has its anchor, the
# page logged nothing to the console and a screenshot was taken (kept in OUT_DIR as report.png).
# (A report that cannot be written: tests/cli/cases/validate-unwritable-report-fails.)
#   check_report.sh VARC PACK OUT_DIR SCENE.json...    the whole test
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
    body=$(grep -o '<body[^>]*>' "$dom" | head -n 1)
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

