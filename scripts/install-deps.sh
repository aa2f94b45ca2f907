#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Installs the Debian packages varc needs, skipping those already present (dpkg -s first).
set -euo pipefail

packages=(
    build-essential cmake ninja-build pkg-config
    glslang-dev glslang-tools spirv-tools
    libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers vulkan-tools
    libglm-dev nlohmann-json3-dev libcli11-dev libzstd-dev libxxhash-dev libpng-dev
    libyaml-cpp-dev
    libgtest-dev libgmock-dev googletest libbenchmark-dev
    chromium
    groff-base file dpkg-dev
    libhiredis-dev redis-server redis-tools python3
    python3-jsonschema
    clang-14 libclang-rt-14-dev
)
# The SARIF schema the diagnostics tests validate against comes from an npm package: Debian's
# npm unless a Node.js that ships its own npm is installed already.
if ! command -v npm >/dev/null 2>&1; then packages+=(npm); fi

missing=()
for package in "${packages[@]}"; do
    if ! dpkg -s "$package" >/dev/null 2>&1; then missing+=("$package"); fi
done
if [ ${#missing[@]} -eq 0 ]; then
    echo "install-deps: all ${#packages[@]} packages present"
    exit 0
fi
echo "install-deps: installing ${missing[*]}"
sudo=""
if [ "$(id -u)" != 0 ]; then sudo="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
