#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The shaders printed in seeds 001, 003 and 004 build unchanged: assembles them from the seed texts
# (read in place) into WORK_DIR with assemble_seeds.sh, then builds each with build_check.sh.
# Seed 004 is built twice: with the multi_compile pragmas of its passes and without (the text as
# printed, which has none). Seed 003 (assemble_seed003.py) must build both variants (`_`,
# INSTANCING_ON), and the assembler must refuse, naming the anchor, a text that lacks a piece.
# Usage: seed_texts.sh VARC PACK_CHECK SEEDS_DIR WORK_DIR
set -euo pipefail

varc="$1"
check="$2"
seeds="$3"
work="$4"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"

rm -rf "$work"
bash "$here/assemble_seeds.sh" "$seeds" "$work/full"
PLAIN=1 bash "$here/assemble_seeds.sh" "$seeds" "$work/plain"
bash "$here/build_check.sh" "$varc" "$check" "$work/seed001.svpack" "$work/full/seed001"
bash "$here/build_check.sh" "$varc" "$check" "$work/seed004.svpack" "$work/full/seed004"
bash "$here/build_check.sh" "$varc" "$check" "$work/seed004-plain.svpack" "$work/plain/seed004"
bash "$here/build_check.sh" "$varc" "$check" "$work/seed003.svpack" "$work/full/seed003"
listing=$("$varc" variants "$work/full/seed003")
grep -q 'multi_compile_instancing: _ INSTANCING_ON' <<<"$listing" ||
    { echo "FAIL: seed 003 lacks the two instancing variants:"; echo "$listing"; exit 1; }

# A text without the final DiffuseLight's spot-fade lines (4.2) is refused, naming the anchor.
seed003=$(ls "$seeds"/003_*.txt)
sed 's/diffuse \*= spotFade \* rangeFade/diffuse *= rangeFade/' "$seed003" > "$work/003-cut.txt"
if err=$(python3 "$here/assemble_seed003.py" "$work/003-cut.txt" "$work/cut" 2>&1); then
    echo "FAIL: assemble_seed003.py accepted a text without the spot fade"; exit 1
fi
grep -q "error: seed 003: anchor 'diffuse \*= spotFade \* rangeFade / distanceSqr;' not found" \
    <<<"$err" || { echo "FAIL: unexpected message: $err"; exit 1; }
[[ ! -e "$work/cut" ]] || { echo "FAIL: a refused assembly wrote $work/cut"; exit 1; }
echo "seed 003: assembled, 2 variants built; a cut text is refused: $err"
