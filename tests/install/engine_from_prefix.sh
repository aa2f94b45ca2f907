#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The installed package stands on its own: `cmake --install` to a temporary prefix, then
#   - the files an engine and a user need are there (binary, headers, CMake package, pkg-config,
#     built-in includes, man page, bash completion);
#   - the installed varc reads its built-in includes from <prefix>/share/varc/builtin and builds
#     the seed-000 fixture with them;
#   - examples/engine configures with find_package(varc) from the prefix alone (nothing in its
#     build refers to the build tree), builds, runs on lavapipe, and writes a PNG identical to the
#     one `varc render` writes for the same pack and scene (same encoder: equal bytes = equal
#     pixels);
#   - a program built with `pkg-config --cflags --libs varc` opens the same pack.
#
#   engine_from_prefix.sh BUILD_DIR SOURCE_DIR CXX LIBDIR [SANITIZE_FLAGS]
set -euo pipefail
build=$(cd "$1" && pwd) src=$(cd "$2" && pwd) cxx=$3 libdir=$4 sanitize=${5:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
prefix=$tmp/prefix
fail() { echo "FAIL: $*"; exit 1; }
run() {  # run LOG command...: quiet unless it fails
    local log=$1; shift
    "$@" > "$log" 2>&1 || { cat "$log"; fail "$*"; }
}
cd "$src"  # fixtures are ../shared/... from the repository root, as in the CLI cases

run "$tmp/install.log" cmake --install "$build" --prefix "$prefix"
for file in bin/varc include/varc/reader/Pack.h include/varc/render/SceneRenderer.h \
    include/varc/core/Result.h "$libdir/libvarc_reader.a" "$libdir/libvarc_render.a" \
    "$libdir/cmake/varc/varcConfig.cmake" "$libdir/cmake/varc/varcConfigVersion.cmake" \
    "$libdir/cmake/varc/varcTargets.cmake" "$libdir/cmake/varc/FindXxHash.cmake" \
    "$libdir/pkgconfig/varc.pc" share/varc/builtin/UnityCG.cginc \
    share/varc/builtin/fallback/VertexLit.shader share/varc/internal/ScreenSpaceShadows.shader \
    share/man/man1/varc.1 share/bash-completion/completions/varc share/doc/varc/README.md \
    share/doc/varc/examples/engine/main.cpp; do
    [ -f "$prefix/$file" ] || fail "not installed: $file"
done

varc=$prefix/bin/varc
version=$(env -u VARC_BUILTIN_INCLUDE_DIR "$varc" --version)
grep -qxF "built-in includes: $prefix/share/varc/builtin" <<< "$version" ||
    fail "installed varc does not use its own built-in includes: $version"
pack=$tmp/seed000.svpack
run "$tmp/build.log" env -u VARC_BUILTIN_INCLUDE_DIR "$varc" build -o "$pack" \
    ../shared/fixtures/seed000-multiple-lights

engine=$tmp/engine
run "$tmp/configure.log" cmake -S "$src/examples/engine" -B "$engine" -G Ninja \
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_CXX_COMPILER="$cxx" \
    -DCMAKE_CXX_FLAGS="$sanitize" -DCMAKE_EXE_LINKER_FLAGS="$sanitize"
grep -qxF "varc_DIR:PATH=$prefix/$libdir/cmake/varc" "$engine/CMakeCache.txt" ||
    fail "find_package(varc) did not use the prefix: $(grep varc_DIR "$engine/CMakeCache.txt")"
run "$tmp/compile.log" cmake --build "$engine"
if grep -qF "$build" "$engine/build.ninja"; then fail "the example's build refers to $build"; fi

scene=tests/scenes/forward/directional.json
run "$tmp/engine.log" "$engine/varc_engine" "$pack" "$scene" "$tmp/engine.png"
# One directional light and no vertex lights: the ForwardBase variant without VERTEXLIGHT_ON.
variant="variant: shader 'Custom/My First Lighting Shader' pass 0 (LightMode ForwardBase) {}"
grep -qxF "$variant" "$tmp/engine.log" || { cat "$tmp/engine.log"; fail "not looked up: $variant"; }
grep -q "^pipeline: " "$tmp/engine.log" || { cat "$tmp/engine.log"; fail "no pipeline"; }
run "$tmp/render.log" "$varc" render "$pack" --scene "$scene" -o "$tmp/varc.png"
cmp "$tmp/engine.png" "$tmp/varc.png" || fail "the example's frame differs from varc render's"

cat > "$tmp/count.cpp" <<'CPP'
#include <iostream>
#include "varc/reader/Pack.h"
int main(int, char** argv) {
    auto pack = varc::reader::Pack::open(argv[1]);
    if (!pack) return 1;
    std::cout << pack->shaderCount() << "\n";
}
CPP
flags=$(PKG_CONFIG_PATH="$prefix/$libdir/pkgconfig" pkg-config --cflags --libs varc) ||
    fail "pkg-config varc"
# shellcheck disable=SC2086  # the flags are words
run "$tmp/pkgconfig.log" "$cxx" -std=c++20 $sanitize "$tmp/count.cpp" -o "$tmp/count" $flags
[ "$("$tmp/count" "$pack")" = 1 ] || fail "the pkg-config program does not read the pack"
echo "ok: installed to $prefix, example built from it, frames equal"
