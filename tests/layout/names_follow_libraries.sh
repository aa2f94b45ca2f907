#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Every library's folder, include prefix and namespace are one word, and no source folder is
# named like build output. Reads the layout manifest CMake writes (one line per library:
# NAME FOLDER PUBLIC PRIVATE) and the tracked files (git ls-files, so no folder is skipped the
# way `grep --exclude-dir` would skip one). Fails, one line per problem, when
#   - a folder holding code (C++ sources, CMake files) is named build*, out or bin (tools skip
#     those as output);
#   - a library folder of the repository is missing from the manifest, or the manifest names a
#     folder without tracked sources;
#   - a library has no include/varc/<name>/ folder, or one of its sources opens a varc namespace
#     other than varc::<name> (core: varc) or one nested in it.
# Usage: names_follow_libraries.sh REPO_ROOT MANIFEST
set -u
root=$1 manifest=$2
cd "$root" || exit 1
problems=()
files=$(git ls-files)
[ -n "$files" ] || { echo "no tracked files under $root (not a git checkout?)"; exit 1; }

while IFS= read -r dir; do
    problems+=("folder named like build output: $dir")
done < <(echo "$files" | grep -E '\.(h|cpp|cmake)$|(^|/)CMakeLists\.txt$' | xargs -n1 dirname \
             | tr '/' '\n' | grep -E '^(build.*|out|bin)$' | sort -u)

# The varc namespaces |file| opens to define something: a block holding only forward
# declarations (`namespace varc::cache { class CacheChain; }`) names another library's type
# and does not count.
definingNamespaces() {
    awk '
        /^namespace varc(::[A-Za-z_:]+)? *\{/ { ns = $2; defines = 0; next }
        ns != "" && /^}/ { if (defines) print ns; ns = ""; next }
        ns != "" && !/^[[:space:]]*$/ && !/^[[:space:]]*\/\// && \
            !/^[[:space:]]*(class|struct|enum class|enum) [A-Za-z_]+( : [A-Za-z_:]+)?;/ { defines = 1 }
    ' "$1" | sort -u
}

declare -A libraryOf
while read -r name folder _; do
    libraryOf[$folder]=$name
    sources=$(echo "$files" | grep -E "^$folder/(src|include)/.*\.(h|cpp)$")
    if [ ! -d "$folder/include/varc/$name" ] && [ -n "$(echo "$files" | grep "^$folder/src/")" ]; then
        problems+=("$folder: no include/varc/$name/ for library $name")
    fi
    expected="varc::$name"
    [ "$name" = core ] && expected="varc"
    while IFS= read -r file; do
        [ -n "$file" ] || continue
        while IFS= read -r ns; do
            case "$ns" in
                "$expected" | "$expected"::*) ;;
                *) problems+=("$file: namespace $ns in library $name (expected $expected)") ;;
            esac
        done < <(definingNamespaces "$file")
    done <<< "$sources"
done < "$manifest"

# Every folder that defines a library (a CMakeLists.txt calling varc_add_library) is in the
# manifest, so none escapes the checks above.
while IFS= read -r cmakefile; do
    folder=$(dirname "$cmakefile")
    if grep -q '^varc_add_library(' "$cmakefile" && [ -z "${libraryOf[$folder]:-}" ]; then
        problems+=("$folder defines a library the layout manifest does not list")
    fi
done < <(echo "$files" | grep -E '(^|/)CMakeLists\.txt$')

if [ ${#problems[@]} -gt 0 ]; then
    printf '%s\n' "${problems[@]}"
    echo "${#problems[@]} layout problem(s)"
    exit 1
fi
echo "${#libraryOf[@]} libraries: folder, include prefix and namespace agree; no folder named like output"
