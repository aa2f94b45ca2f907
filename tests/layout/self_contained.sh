#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# docs/ is self-contained: no source, shader, script or document of the repository cites a
# reference document outside it (the specifications the code follows are written in docs/).
# Tests may still *read* ../shared/fixtures, ../shared/seeds and ../shared/compat in place.
# Usage: self_contained.sh REPO_ROOT
set -u
cd "$1" || exit 1
pattern='unity-keywords\.md|unity-keywords §|unity-shadows\.md|peers\.md|style\.md|shared/reference'
# Every tracked file (git ls-files), so no folder is skipped; build trees are untracked.
hits=$(git ls-files -z | grep -zv '^tests/layout/self_contained.sh$' |
           xargs -0 grep -InE "$pattern" -- 2>/dev/null || true)
if [ -n "$hits" ]; then
    echo "citations of documents outside the repository (write the fact in docs/ and cite that):"
    echo "$hits"
    exit 1
fi
echo "no citation of a document outside the repository"
