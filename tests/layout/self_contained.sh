#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# docs/ is self-contained: no source, shader, script or document of the repository cites a
# reference document outside it (the specifications the code follows are written in docs/).
# Tests may still *read* ../shared/fixtures, ../shared/seeds and ../shared/compat in place, and
# scripts/builtin-api.py reads the API checklist ../shared/reference/unity-builtin-api.tsv in
# place (issue #27: a data input whose facts docs/BUILTIN_API.md states; never a specification).
# Usage: self_contained.sh REPO_ROOT
set -u
cd "$1" || exit 1
pattern='unity-variant-selection\.md|unity-keywords\.md|unity-keywords §|unity-shadows\.md|peers\.md|style\.md|shared/reference'
# Every tracked file (git ls-files), so no folder is skipped; build trees are untracked.
checklist='shared/reference/unity-builtin-api.tsv'
hits=$(git ls-files -z | grep -zv '^tests/layout/self_contained.sh$' |
           xargs -0 grep -InE "$pattern" -- 2>/dev/null |
           while IFS= read -r line; do
               # A line citing only the checklist is fine; anything else it cites is not.
               grep -qE "$pattern" <<<"${line//$checklist/}" && printf '%s\n' "$line"
           done || true)
if [ -n "$hits" ]; then
    echo "citations of documents outside the repository (write the fact in docs/ and cite that):"
    echo "$hits"
    exit 1
fi
echo "no citation of a document outside the repository"
