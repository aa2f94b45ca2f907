# SPDX-License-Identifier: Apache-2.0
# Sourced by the `build-direct-*` cases' setup and verify (cwd = repo root, $VARC and $TMP set):
# copies the sources to $TMP/src and defines the builds the cases compare.
direct_build() {  # direct_build OUT [OPTION]...: a --direct build with the cases' cache
    local out=$1; shift
    "$VARC" build --direct --cache-dir "$TMP/cache" -I "$TMP/src/inc" -o "$out" "$@" "$TMP/src/shaders"
}
fresh_build() {  # fresh_build OUT [OPTION]...: the same build without any cache
    local out=$1; shift
    "$VARC" build -I "$TMP/src/inc" -o "$out" "$@" "$TMP/src/shaders" >/dev/null
}
if [ ! -d "$TMP/src" ]; then
    cp -r tests/cli/inputs/direct "$TMP/src"
    rm "$TMP/src/prepare.sh"
fi
