#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# `cpack -G DEB` builds the Debian package: it lists the binary, the headers, the CMake package,
# the built-in includes, the man page and the bash completion under /usr, depends on the shared
# libraries varc runs with (dpkg-shlibdeps) and on the -dev packages the headers need.
#
#   debian_package.sh BUILD_DIR LIBDIR
set -euo pipefail
build=$1 libdir=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
for tool in cpack dpkg dpkg-deb dpkg-shlibdeps; do
    command -v "$tool" > /dev/null || fail "$tool not found (scripts/install-deps.sh installs it)"
done
cpack -G DEB -B "$tmp" --config "$build/CPackConfig.cmake" > "$tmp/cpack.log" 2>&1 ||
    { cat "$tmp/cpack.log"; fail "cpack -G DEB"; }
debs=("$tmp"/varc_*.deb)
[ -f "${debs[0]}" ] || { cat "$tmp/cpack.log"; fail "no varc_*.deb written"; }
deb=${debs[0]}
dpkg -c "$deb" > "$tmp/contents"
for path in ./usr/bin/varc ./usr/include/varc/reader/Pack.h \
    ./usr/include/varc/render/SceneRenderer.h "./usr/$libdir/libvarc_reader.a" \
    "./usr/$libdir/cmake/varc/varcConfig.cmake" "./usr/$libdir/cmake/varc/varcTargets.cmake" \
    "./usr/$libdir/pkgconfig/varc.pc" ./usr/share/varc/builtin/UnityCG.cginc \
    ./usr/share/varc/internal/ScreenSpaceShadows.shader ./usr/share/man/man1/varc.1 \
    ./usr/share/bash-completion/completions/varc; do
    grep -qE " $path\$" "$tmp/contents" || { cat "$tmp/contents"; fail "dpkg -c lacks $path"; }
done
depends=$(dpkg-deb -f "$deb" Depends)
# libc6 and libvulkan1 come from dpkg-shlibdeps; libvulkan-dev and libzstd-dev from the headers.
for package in libc6 libvulkan1 libzstd1 libvulkan-dev libzstd-dev libxxhash-dev libglm-dev; do
    grep -qE "(^|, )$package( |,|$)" <<< "$depends" || fail "Depends lacks $package: $depends"
done
echo "ok: $(basename "$deb"): $(wc -l < "$tmp/contents") entries; Depends: $depends"
