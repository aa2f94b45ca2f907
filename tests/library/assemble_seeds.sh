#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Assembles the final shaders printed in seeds 001, 003 and 004 from the seed texts, read in place,
# into OUT_DIR (never into the repository): OUT_DIR/seed001/seed001.shader,
# OUT_DIR/seed003/{Shaders,ShaderLibrary}/Lit.{shader,hlsl} and OUT_DIR/seed004/seed004.shader.
# Nothing is rewritten; the only text not taken from the seeds is the glue listed below.
#   seed 001: the "Complete Shader Code" block, verbatim (from `Shader "` to the first `}` in
#             column 0).
#   seed 004: the skeleton `Shader "BetterDiffuse"` with, in each pass after `#pragma fragment frag`:
#             the multi_compile pragma of the pass (base: multi_compile_fwdbase, add:
#             multi_compile_fwdadd; the article does not print them, its downloadable source and
#             Unity need them for VERTEXLIGHT_ON and the light types), the three includes the
#             article names ("include UnityCG.cginc, Lighting.cginc and AutoLight.cginc"), the
#             property declarations, then the pass's structs, vertex and fragment functions as
#             printed: the add pass gets the first versions, the base pass the later
#             "ForwardBase" vertex_output/vert/frag. Pass PLAIN=1 to leave out the pragmas.
#   seed 003: assemble_seed003.py (its pieces, their final states and the frame of our own that
#             the text takes from a previous tutorial are listed there).
# Usage: assemble_seeds.sh SEEDS_DIR OUT_DIR
# Exit: 0 written; 1 a seed text is missing or no longer has the expected pieces.
set -euo pipefail

seeds="$1"
out="$2"
seed001=$(ls "$seeds"/001_*.txt)
seed003=$(ls "$seeds"/003_*.txt)
seed004=$(ls "$seeds"/004_*.txt)
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"

# Prints the Nth (1-based) piece of FILE that starts at a line matching REGEX and ends where its
# braces balance (a function body or a struct declaration).
braced_piece() {
    awk -v want="$3" -v re="$2" '
        !on && $0 ~ re { if (++n == want) on = 1 }
        on {
            print
            opened += gsub(/\{/, "{"); closed += gsub(/\}/, "}")
            if (opened > 0 && opened == closed) exit
        }
    ' "$1"
}

# Prints the lines of FILE from the first line matching FIRST through the next matching LAST.
line_range() {
    awk -v first="$2" -v last="$3" '$0 ~ first { on = 1 } on { print } on && $0 ~ last { exit }' "$1"
}

require() {  # require NAME TEXT: fail when a piece came out empty
    if [[ -z "$2" ]]; then echo "error: $1 not found in the seed text" >&2; exit 1; fi
}

mkdir -p "$out/seed001" "$out/seed004"

# Seed 001.
text=$(awk '/^Shader "/ { on = 1 } on { print } on && /^}/ { exit }' "$seed001")
require "seed 001 shader" "$text"
printf '%s\n' "$text" > "$out/seed001/seed001.shader"

# Seed 003.
python3 "$here/assemble_seed003.py" "$seed003" "$out/seed003"

# Seed 004.
skeleton=$(line_range "$seed004" '^Shader "BetterDiffuse"' '^}')
input=$(braced_piece "$seed004" '^struct vertex_input' 1)
output_add=$(braced_piece "$seed004" '^struct vertex_output' 1)
output_base=$(braced_piece "$seed004" '^struct vertex_output' 2)
vert_add=$(braced_piece "$seed004" '^vertex_output vert ?\(' 1)
vert_base=$(braced_piece "$seed004" '^ *vertex_output vert ?\(' 2)
frag_add=$(braced_piece "$seed004" '^half4 frag\(' 1)
frag_base=$(braced_piece "$seed004" '^fixed4 frag\(' 1)
properties=$(line_range "$seed004" '^sampler2D _MainTex;' '^fixed4 _LightColor0;')
for piece in skeleton input output_add output_base vert_add vert_base frag_add frag_base properties; do
    require "$piece" "${!piece}"
done
includes=$'#include "UnityCG.cginc"\n#include "Lighting.cginc"\n#include "AutoLight.cginc"'
pragma_base="#pragma multi_compile_fwdbase"
pragma_add="#pragma multi_compile_fwdadd"
if [[ "${PLAIN:-0}" == 1 ]]; then pragma_base=""; pragma_add=""; fi
body_base=$(printf '%s\n' "$pragma_base" "$includes" "$properties" "$input" "$output_base" "$vert_base" "$frag_base")
body_add=$(printf '%s\n' "$pragma_add" "$includes" "$properties" "$input" "$output_add" "$vert_add" "$frag_add")
BODY_BASE="$body_base" BODY_ADD="$body_add" awk '
    { print }
    /#pragma fragment frag/ { n++; print (n == 1 ? ENVIRON["BODY_BASE"] : ENVIRON["BODY_ADD"]) }
' <<<"$skeleton" > "$out/seed004/seed004.shader"
if [[ $(grep -c 'vertex_output vert' "$out/seed004/seed004.shader") -ne 2 ]]; then
    echo "error: seed 004 skeleton does not have two passes with '#pragma fragment frag'" >&2
    exit 1
fi
