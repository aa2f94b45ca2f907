#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Compiles every pass, variant and stage of the seed fixtures (read in place) and of this
# directory's coverage shaders against varc's built-in include library (shaders/builtin) with
# glslangValidator, the way varc's compile driver does, and validates each module with spirv-val.
#   CG/HLSL: HLSL front end, DX9-compatible samplers, auto-mapped bindings and locations,
#            Vulkan 1.0 / SPIR-V 1.0, Unity's predefined macros and the variant's keywords.
#   GLSL:    #version 140 with glslang's relaxed Vulkan rules (-R) and the legacy built-in
#            mapping of compiler/driver/src/GlslLegacyPreamble.cpp (gl_Vertex -> varc_Vertex, ...).
# Usage: compile_fixtures.sh [FIXTURES_DIR [BUILTIN_DIR]]
# Exit: 0 all compiled and validated; 1 a compile/validation failure (compiler output printed);
#       77 glslangValidator or spirv-val is not installed (CTest reports the test as skipped).
set -u

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
fixtures="${1:-$here/../../../shared/fixtures}"
builtin="${2:-$here/../../shaders/builtin}"

for tool in glslangValidator spirv-val; do
    if ! command -v "$tool" >/dev/null 2>&1; then
        echo "SKIP: $tool not found (Debian: apt-get install glslang-tools spirv-tools)"
        exit 77
    fi
done
if [[ ! -d "$fixtures" || ! -d "$builtin" ]]; then
    echo "error: fixtures '$fixtures' or built-in include dir '$builtin' not found" >&2
    exit 1
fi

work="$(mktemp -d "${TMPDIR:-/tmp}/varc-builtin.XXXXXX")"
trap 'rm -rf "$work"' EXIT

# Prints the text of the Nth (1-based) CGPROGRAM/HLSLPROGRAM/GLSLPROGRAM block of a .shader file.
extract_block() {
    awk -v want="$2" '
        /^[ \t]*(CG|HLSL|GLSL)PROGRAM[ \t]*$/ { n++; inside = (n == want); next }
        /^[ \t]*END(CG|HLSL|GLSL)[ \t]*$/     { inside = 0; next }
        inside { print }
    ' "$1"
}

# Prints CG, HLSL or GLSL: the kind of the Nth program block.
block_language() {
    awk -v want="$2" 'match($0, /^[ \t]*(CG|HLSL|GLSL)PROGRAM[ \t]*$/) {
        n++; if (n == want) { sub(/^[ \t]*/, ""); sub(/PROGRAM.*/, ""); print; exit } }' "$1"
}

# Prints the legacy GLSL preamble varc's driver adds for STAGE (vert|frag) and program text FILE:
# a declaration plus `#define gl_X varc_X` for each legacy built-in the text mentions.
glsl_legacy_preamble() {
    local stage="$1" body="$2" name decl stages
    while IFS='|' read -r name decl stages; do
        [[ "$stages" == *"$stage"* ]] || continue
        grep -q "\b$name\b" "$body" || continue
        printf '%b\n#define %s varc_%s\n' "$decl" "$name" "${name#gl_}"
    done <<'TABLE'
gl_Vertex|in vec4 varc_Vertex;|vert
gl_Normal|in vec3 varc_Normal;|vert
gl_Color|in vec4 varc_Color;|vert
gl_MultiTexCoord0|in vec4 varc_MultiTexCoord0;|vert
gl_MultiTexCoord1|in vec4 varc_MultiTexCoord1;|vert
gl_ModelViewProjectionMatrix|uniform mat4 varc_ModelViewProjectionMatrix;|vert frag
gl_ModelViewMatrix|uniform mat4 varc_ModelViewMatrix;|vert frag
gl_ProjectionMatrix|uniform mat4 varc_ProjectionMatrix;|vert frag
gl_NormalMatrix|uniform mat3 varc_NormalMatrix;|vert frag
gl_LightModel|struct varc_LightModelParameters { vec4 ambient; };\nuniform vec4 varc_LightModelAmbient;\n#define varc_LightModel varc_LightModelParameters(varc_LightModelAmbient)|vert frag
gl_FragColor|out vec4 varc_FragColor;|frag
TABLE
    if [[ $stage == vert ]]; then echo "#define varying out"; else echo "#define varying in"; fi
}

# Prints the LightMode tag of the pass that holds the Nth program block ("" when none).
block_lightmode() {
    awk -v want="$2" '
        /^[ \t]*Pass[ \t]*\{?/ { mode = "" }
        match($0, /"LightMode"[ \t]*=[ \t]*"[A-Za-z]+"/) {
            s = substr($0, RSTART, RLENGTH); sub(/.*=[ \t]*"/, "", s); sub(/"$/, "", s); mode = s
        }
        /^[ \t]*(CG|HLSL|GLSL)PROGRAM[ \t]*$/ { n++; if (n == want) { print mode; exit } }
    ' "$1"
}

pragma_value() {  # pragma_value FILE NAME -> first argument of "#pragma NAME x"
    sed -n "s/^[ \t]*#pragma[ \t][ \t]*$2[ \t][ \t]*\([A-Za-z0-9_.]*\).*/\1/p" "$1" | head -n 1
}

failures=0
compiled=0

# compile_block SHADER BLOCK_INDEX "VARIANT" ["VARIANT" ...]; a variant is a space-separated
# keyword list, "_" for none.
compile_block() {
    local shader="$1" index="$2"; shift 2
    local dir; dir="$(dirname "$shader")"
    local src="$work/block${index}_$(basename "$shader" .shader | tr -c 'A-Za-z0-9_\n' '_').hlsl"
    extract_block "$shader" "$index" > "$src"
    if [[ ! -s "$src" ]]; then
        echo "FAIL: $shader: program block $index not found"; failures=$((failures + 1)); return
    fi
    local language; language="$(block_language "$shader" "$index")"
    local vs fs target lightmode
    vs="$(pragma_value "$src" vertex)"; fs="$(pragma_value "$src" fragment)"
    target="$(pragma_value "$src" target)"; target="${target:-2.5}"
    lightmode="$(block_lightmode "$shader" "$index")"
    local defines=(-DSHADER_API_VULKAN=1 -DSHADER_API_DESKTOP=1 "-DSHADER_TARGET=${target/./}"
                   -DUNITY_VERSION=201940)
    if [[ -n "$lightmode" ]]; then
        defines+=("-DUNITY_PASS_$(echo "$lightmode" | tr '[:lower:]' '[:upper:]')=1")
    fi
    local variant stage entry keyword
    for variant in "$@"; do
        local kw=()
        for keyword in $variant; do [[ "$keyword" == _ ]] || kw+=("-D$keyword=1"); done
        for stage in vert frag; do
            if [[ $stage == vert ]]; then entry="$vs"; else entry="$fs"; fi
            local stagedef=-DSHADER_STAGE_VERTEX=1
            [[ $stage == frag ]] && stagedef=-DSHADER_STAGE_FRAGMENT=1
            local spv="$work/out.spv" label="$(basename "$shader") block $index ($lightmode) [$variant] $stage"
            local log
            if [[ $language == GLSL ]]; then
                # One text for all stages, selected by VERTEX / FRAGMENT; no entry-point pragmas.
                local glsl="$work/program.$stage" d
                {
                    echo "#version 140"
                    echo "#extension GL_GOOGLE_include_directive : enable"
                    for d in "${defines[@]}" "$stagedef" "${kw[@]}"; do
                        d="${d#-D}"; echo "#define ${d%%=*} ${d#*=}"
                    done
                    if [[ $stage == vert ]]; then echo "#define VERTEX 1"; else echo "#define FRAGMENT 1"; fi
                    glsl_legacy_preamble "$stage" "$src"
                    cat "$src"
                } > "$glsl"
                log="$(glslangValidator -V -R --auto-map-bindings --auto-map-locations --target-env vulkan1.0 \
                       -I"$dir" -I"$builtin" "$glsl" -o "$spv" 2>&1)"
            else
                log="$(glslangValidator -V -D --hlsl-dx9-compatible --auto-map-bindings --auto-map-locations \
                       --target-env vulkan1.0 -S "$stage" -e "$entry" "${defines[@]}" "$stagedef" "${kw[@]}" \
                       -I"$dir" -I"$builtin" "$src" -o "$spv" 2>&1)"
            fi
            if [[ $? -ne 0 ]]; then
                echo "FAIL: $label: glslangValidator"; echo "$log" | sed 's/^/    /'
                failures=$((failures + 1)); continue
            fi
            if ! log="$(spirv-val --target-env vulkan1.0 "$spv" 2>&1)"; then
                echo "FAIL: $label: spirv-val"; echo "$log" | sed 's/^/    /'
                failures=$((failures + 1)); continue
            fi
            compiled=$((compiled + 1))
        done
    done
}

# multi_compile_lightpass as Unity 5.5 lists it (docs/KEYWORDS.md §4), x (_ | UNITY_HDR_ON).
lightpass=("POINT" "DIRECTIONAL" "SPOT" "POINT_COOKIE" "DIRECTIONAL_COOKIE" "SHADOWS_DEPTH SPOT"
           "DIRECTIONAL SHADOWS_SCREEN" "DIRECTIONAL_COOKIE SHADOWS_SCREEN" "POINT SHADOWS_CUBE"
           "POINT_COOKIE SHADOWS_CUBE" "SHADOWS_DEPTH SHADOWS_SOFT SPOT" "POINT SHADOWS_CUBE SHADOWS_SOFT"
           "POINT_COOKIE SHADOWS_CUBE SHADOWS_SOFT")
lightpass_hdr=()
for v in "${lightpass[@]}"; do lightpass_hdr+=("$v" "$v UNITY_HDR_ON"); done

seed000="$fixtures/seed000-multiple-lights/My First Lighting Shader.shader"
seed002="$fixtures/seed002-deferred-lights/DeferredShading.shader"
compile_block "$seed000" 1 "_" "VERTEXLIGHT_ON"
compile_block "$seed000" 2 "POINT" "DIRECTIONAL" "SPOT" "POINT_COOKIE" "DIRECTIONAL_COOKIE"
compile_block "$seed002" 1 "${lightpass_hdr[@]}"
compile_block "$seed002" 2 "_"

# This directory's coverage shaders: the rest of the library, all its shadow keywords, GLSL.
fwdbase=("DIRECTIONAL" "DIRECTIONAL LIGHTPROBE_SH" "DIRECTIONAL SHADOWS_SCREEN"
         "DIRECTIONAL LIGHTPROBE_SH SHADOWS_SCREEN" "DIRECTIONAL VERTEXLIGHT_ON"
         "DIRECTIONAL LIGHTPROBE_SH VERTEXLIGHT_ON" "DIRECTIONAL SHADOWS_SCREEN VERTEXLIGHT_ON"
         "DIRECTIONAL LIGHTPROBE_SH SHADOWS_SCREEN VERTEXLIGHT_ON")
coverage="$here/shaders/LibraryCoverage.shader"
compile_block "$coverage" 1 "${fwdbase[@]}" "DIRECTIONAL LIGHTMAP_ON" "DIRECTIONAL FOG_EXP INSTANCING_ON" \
    "DIRECTIONAL FOG_LINEAR INSTANCING_ON VERTEXLIGHT_ON" "DIRECTIONAL FOG_EXP2 LIGHTPROBE_SH SHADOWS_SCREEN"
compile_block "$coverage" 2 "${lightpass[@]}" "FOG_LINEAR POINT"
compile_block "$coverage" 3 "SHADOWS_DEPTH" "SHADOWS_CUBE"
compile_block "$coverage" 4 "${lightpass_hdr[@]}"
compile_block "$here/shaders/GlslCoverage.shader" 1 "${fwdbase[@]}"
compile_block "$here/shaders/SrpCoverage.shader" 1 "_" "INSTANCING_ON"

echo "compiled and validated $compiled stage programs, $failures failures"
[[ $failures -eq 0 ]]
