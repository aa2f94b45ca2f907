#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Assembles seed 003's single-pass Lit shader ("Scriptable Render Pipeline: Lights") from the seed
# text, read in place, into OUT_DIR (never into the repository): OUT_DIR/Shaders/Lit.shader and
# OUT_DIR/ShaderLibrary/Lit.hlsl.
#
# The text prints its code in pieces, many of them with "…" for the unchanged rest, and never
# prints Lit.hlsl in one piece. This script finds each piece by the anchor it starts with, takes
# its last (final) printed state, applies the partial edits the text prints after that state, in
# the text's order, and puts the pieces inside a frame of our own (FRAME_* below: the include of
# SRP core's Common.hlsl, the per-frame matrix buffer, UNITY_MATRIX_M and the instancing include
# and per-instance _Color buffer; the text takes them from the previous tutorial, which is not a
# seed). The pieces and edits:
#   Lit.shader        the `Shader "My Pipeline/Lit"` block (§1.1), whole.
#   include guard     `#ifndef NAME #define NAME` and `#endif // NAME` (§1.1).
#   UnityPerDraw      the last `CBUFFER_START(UnityPerDraw)` block (§5.1).
#   light count       the last `#define MAX_VISIBLE_LIGHTS` (§5.2: 16).
#   _LightBuffer      the last `CBUFFER_START(_LightBuffer)` block (§4.1: four arrays).
#   VertexInput       the last `struct VertexInput` (§1.2).
#   VertexOutput      the last `struct VertexOutput` (§5.3, with vertexLighting).
#   DiffuseLight      the last one printed whole (§3.3, range fade), then §4.1's added
#                     `float3 spotDirection = ...;` after the lightAttenuation line, then §4.2's
#                     lines from `float rangeFade =` to `diffuse *= spotFade ...;` in place of
#                     §3.3's lines from `float rangeFade =` to `diffuse *= rangeFade ...;`.
#   LitPassVertex     the last one (§5.3, printed whole).
#   LitPassFragment   the last one (§5.3), its first light loop (printed as "…") filled with the
#                     last printed loop over unity_4LightIndices0 (§5.2).
# The text's line breaks are lost (it is extracted from a page): code lines are separated by runs
# of two or more spaces, which this script turns back into line breaks, and every preprocessor
# directive gets a line of its own. Nothing else is rewritten.
# Usage: assemble_seed003.py SEED_TEXT OUT_DIR
# Exit: 0 written; 1 the text is missing or lacks a piece (the message names the anchor).
import os
import re
import sys

ELLIPSIS = "\u2026"

FRAME_TOP = """#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/Common.hlsl"

CBUFFER_START(UnityPerFrame)
    float4x4 unity_MatrixVP;
CBUFFER_END
"""

FRAME_INSTANCING = """#define UNITY_MATRIX_M unity_ObjectToWorld
#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/UnityInstancing.hlsl"

UNITY_INSTANCING_BUFFER_START(PerInstance)
    UNITY_DEFINE_INSTANCED_PROP(float4, _Color)
UNITY_INSTANCING_BUFFER_END(PerInstance)
"""


class AssemblyError(Exception):
    pass


def starts_of(text, anchor):
    """Every index where |anchor| (a plain string) starts in |text|."""
    return [m.start() for m in re.finditer(re.escape(anchor), text)]


def braced_at(text, start, anchor):
    """The piece of |text| from |start| to the brace that closes its first '{' (plus a following
    ';' for a struct)."""
    depth = 0
    for i in range(start, len(text)):
        if text[i] == "{":
            depth += 1
        elif text[i] == "}":
            depth -= 1
            if depth == 0:
                end = i + 1
                rest = text[end:].lstrip(" ")
                if rest.startswith(";"):
                    end = len(text) - len(rest) + 1
                return text[start:end]
    raise AssemblyError("the piece starting with '%s' has no closing brace" % anchor)


def braced_pieces(text, anchor):
    pieces = [braced_at(text, s, anchor) for s in starts_of(text, anchor)]
    if not pieces:
        raise AssemblyError("anchor '%s' not found" % anchor)
    return pieces


def span(text, first, last, occurrence=-1):
    """The text from an occurrence of |first| through the next |last| (both included)."""
    starts = starts_of(text, first)
    if not starts:
        raise AssemblyError("anchor '%s' not found" % first)
    start = starts[occurrence]
    end = text.find(last, start)
    if end < 0:
        raise AssemblyError("anchor '%s' not found after '%s'" % (last, first))
    return text[start:end + len(last)]


def replace_once(piece, old, new, what):
    if piece.count(old) != 1:
        raise AssemblyError("%s: expected '%s' once in the piece" % (what, old.strip()))
    return piece.replace(old, new)


def last_whole(pieces, must_contain, anchor):
    """The last piece that contains |must_contain| and no ellipsis."""
    whole = [p for p in pieces if must_contain in p and ELLIPSIS not in p]
    if not whole:
        raise AssemblyError("no whole '%s' containing '%s'" % (anchor, must_contain))
    return whole[-1]


def reflow(code):
    """Line breaks back: runs of 2+ spaces end a line; directives start one."""
    code = re.sub(r"\s*(#(?:ifndef|define|endif|include|pragma)\b)", r"\n\1", code)
    code = re.sub(r"\s*\b(HLSLPROGRAM|ENDHLSL)\b", r"\n\1", code)
    lines = []
    for line in re.split(r"\n| {2,}", code):
        line = line.strip()
        if line:
            lines.append(line)
    return "\n".join(lines) + "\n"


def diffuse_light(text):
    anchor = "float3 DiffuseLight ("
    pieces = braced_pieces(text, anchor)
    base = last_whole(pieces, "rangeFade", anchor)
    spot = span(text, "float3 spotDirection =", ";")
    attenuation = span(base, "float4 lightAttenuation =", ";")
    base = replace_once(base, attenuation, attenuation + "  " + spot, "spot direction (4.1)")
    old = span(base, "float rangeFade =", "diffuse *= rangeFade / distanceSqr;")
    new = span(text, "float rangeFade =", "diffuse *= spotFade * rangeFade / distanceSqr;")
    return replace_once(base, old, new, "spot fade (4.2)")


def lit_pass_fragment(text):
    anchor = "float4 LitPassFragment ("
    fragment = braced_pieces(text, anchor)[-1]
    head = "for (int i = 0; i < min(unity_LightIndicesOffsetAndCount.y, 4); i++) {"
    loops = [p for p in braced_pieces(text, head) if ELLIPSIS not in p
             and "unity_4LightIndices0[i]" in p]
    if not loops:
        raise AssemblyError("no whole loop '%s' over unity_4LightIndices0" % head)
    holes = [p for p in braced_pieces(fragment, head) if ELLIPSIS in p]
    if len(holes) != 1:
        raise AssemblyError("the last LitPassFragment has no '%s %s }' to fill" % (head, ELLIPSIS))
    return replace_once(fragment, holes[0], loops[-1], "pixel light loop (5.2)")


def assemble(text):
    shader = braced_pieces(text, 'Shader "My Pipeline/Lit"')[0]
    guard = re.search(r"#ifndef (\w+) #define \1\b", text)
    if not guard or ("#endif // " + guard.group(1)) not in text:
        raise AssemblyError("include guard '#ifndef NAME #define NAME ... #endif // NAME' "
                            "not found")
    name = guard.group(1)
    per_draw = span(text, "CBUFFER_START(UnityPerDraw)", "CBUFFER_END")
    count = re.findall(r"#define MAX_VISIBLE_LIGHTS \d+", text)
    if not count:
        raise AssemblyError("anchor '#define MAX_VISIBLE_LIGHTS' not found")
    light_buffer = span(text, "CBUFFER_START(_LightBuffer)", "CBUFFER_END")
    vertex_input = braced_pieces(text, "struct VertexInput {")[-1]
    vertex_output = braced_pieces(text, "struct VertexOutput {")[-1]
    vertex = braced_pieces(text, "VertexOutput LitPassVertex (")[-1]
    fragment = lit_pass_fragment(text)
    seed_top = [per_draw, count[-1], light_buffer]
    seed_code = [vertex_input, vertex_output, diffuse_light(text), vertex, fragment]
    hlsl = ["#ifndef %s\n#define %s\n" % (name, name), FRAME_TOP]
    hlsl += [reflow(p) for p in seed_top]
    hlsl.append(FRAME_INSTANCING)
    hlsl += [reflow(p) for p in seed_code]
    hlsl.append("#endif // %s\n" % name)
    hlsl_text = "\n".join(hlsl)
    for line in hlsl_text.splitlines():
        if ELLIPSIS in line and not line.startswith("//"):
            raise AssemblyError("an omitted part ('%s') is left in: %s" % (ELLIPSIS, line))
    return reflow(shader), hlsl_text


def write(path, content):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    temp = path + ".tmp"
    with open(temp, "w", encoding="utf-8") as f:
        f.write(content)
    os.replace(temp, path)


def main(argv):
    if len(argv) != 3:
        print("usage: assemble_seed003.py SEED_TEXT OUT_DIR", file=sys.stderr)
        return 2
    try:
        with open(argv[1], encoding="utf-8") as f:
            text = re.sub(r"\s*\n\s*", "  ", f.read())
        shader, hlsl = assemble(text)
    except (OSError, AssemblyError) as e:
        print("%s: error: seed 003: %s" % (argv[1], e), file=sys.stderr)
        return 1
    write(os.path.join(argv[2], "Shaders", "Lit.shader"), shader)
    write(os.path.join(argv[2], "ShaderLibrary", "Lit.hlsl"), hlsl)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
