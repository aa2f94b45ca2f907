#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The shaders printed in seeds 001 and 004 build unchanged: assembles them from the seed texts
# (read in place) into WORK_DIR with assemble_seeds.sh, then builds each with build_check.sh.
# Seed 004 is built twice: with the multi_compile pragmas of its passes and without (the text as
# printed, which has none). Seed 003 cannot be assembled from its text alone (tests/library/README.md).
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
