#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Builds shaders into a pack with `varc build` exactly as a user would: no -I flags and no
# VARC_BUILTIN_INCLUDE_DIR, so includes of Unity's built-in files (UnityCG.cginc, AutoLight.cginc,
# ...) must come from varc's own built-in directory. `varc build` compiles every variant and
# validates every SPIR-V module with SPIRV-Tools (compiler/driver/src/CompileDriver.cpp,
# Builder::compileSource -> validateSpirv); an invalid module fails the build.
# Then checks the result against `varc variants`, twice:
#   * the build summary: the per-pass counts of `varc build --json` add up to the total of
#     `varc variants --json`;
#   * the pack itself, with PACK_CHECK (pack_check.cpp): it opens the pack with the runtime's
#     reader, validates every variant's vertex and fragment SPIR-V again, and counts the variants.
# Usage: build_check.sh VARC PACK_CHECK PACK PATH...
# Exit: 0 built, valid and complete; 1 otherwise (the tools' output is printed).
set -uo pipefail

varc="$1"
check="$2"
pack="$3"
shift 3
unset VARC_BUILTIN_INCLUDE_DIR

fail() { echo "FAIL: $*"; exit 1; }

# Total variant count: the last "variants" member of `varc variants --json` is the grand total.
if ! listing=$("$varc" variants --json "$@" 2>&1); then
    echo "$listing"; fail "varc variants $*"
fi
expected=$(grep -o '"variants":[0-9]*' <<<"$listing" | tail -n 1 | cut -d: -f2)
[[ -n "$expected" && "$expected" -gt 0 ]] || fail "no variants listed for $*"

rm -f "$pack"
summary=$("$varc" build --json -j 2 -o "$pack" "$@" 2>"$pack.log")
status=$?
if [[ $status -ne 0 ]]; then
    cat "$pack.log"; fail "varc build exited with $status for $*"
fi
[[ -s "$pack" ]] || fail "varc build did not write $pack"

# Sum of the per-pass variant counts in the build summary.
built=$(grep -o '"variants":[0-9]*' <<<"$summary" | cut -d: -f2 | awk '{ n += $1 } END { print n + 0 }')
compiled=$(grep -o '"compiled_sources":[0-9]*' <<<"$summary" | cut -d: -f2)
echo "$*: $built of $expected variants built, $compiled programs compiled to SPIR-V and validated, pack $(stat -c %s "$pack") bytes"
[[ "$built" == "$expected" ]] || fail "build summary has $built variants, varc variants lists $expected"
[[ -n "$compiled" && "$compiled" -gt 0 ]] || fail "no SPIR-V modules compiled"

# The pack, read back by the runtime: every variant present, every program valid.
report=$("$check" "$pack")
status=$?
if [[ $status -ne 0 ]]; then
    echo "$report"; fail "$check rejected $pack (exit $status)"
fi
in_pack=$(sed -n 's/^variants=\([0-9]*\) .*/\1/p' <<<"$report")
echo "pack: $(tail -n 1 <<<"$report")"
[[ "$in_pack" == "$expected" ]] || fail "the pack holds $in_pack variants, varc variants lists $expected"
