#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Inventory of Unity's built-in-pipeline include API (issue #27): reads the checklist
# ../shared/reference/unity-builtin-api.tsv (in place, never copied) and varc's include files
# (shaders/builtin/), classifies every row and writes docs/BUILTIN_API.md.
#   implemented  defined by varc's includes with a compatible signature, and either trivial
#                (a constant, an alias, a declaration) or named by a value test
#                (`// api-value-tested:` lines in tests/vulkan/*.cpp)
#   declared     defined with a compatible signature, but non-trivial and not value-tested
#   missing      not defined (or only with another parameter list) in the include closure of
#                the row's file
# A function row that varc's includes do not define but glslang's HLSL front end provides as a
# DX9 intrinsic with the same parameter list (NATIVE_FUNCTIONS: tex2D(sampler2D, float2) & co.)
# is implemented ("native HLSL"); --calls-dir calls each such row with its own parameter types,
# so builtin.api-calls fails if glslang stops accepting one. Likewise the struct rows of the
# sampler types (NATIVE_TYPES: Unity's DXC path emulates them as structs).
# Usage (from anywhere):
#   scripts/builtin-api.py --write           rewrite docs/BUILTIN_API.md
#   scripts/builtin-api.py --check           exit 1 when docs/BUILTIN_API.md is stale
#   scripts/builtin-api.py --calls-dir DIR   write DIR/api-calls-*.shader: one shader per include
#                                            file calling every implemented/declared function in
#                                            the vertex stage (unless it needs derivatives or
#                                            implicit-LOD sampling) and the fragment stage
# Options: --tsv PATH, --builtin DIR, --doc PATH.
import argparse
import collections
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
VERSIONS = ["5.6", "2017.4", "2018.4", "2019.4", "2020.3", "2021.3", "2022.3"]
KINDS = ["include", "macro", "function", "variable", "struct", "member"]
STATUSES = ["implemented", "declared", "missing"]

IDENT = re.compile(r"[A-Za-z_]\w*")
QUALIFIERS = {"in", "out", "inout", "uniform", "const", "static", "inline", "precise",
              "nointerpolation", "linear", "centroid", "noperspective", "sample", "triangle",
              "point", "line", "lineadj", "triangleadj"}
PRECISION = [(re.compile(r"\b(?:half|fixed|min16float|min10float|real)(\d(?:x\d)?)?\b"),
              lambda m: "float" + (m.group(1) or "")),
             (re.compile(r"\bunityShadowCoord(\d(?:x\d)?)?\b"), lambda m: "float" + (m.group(1) or "")),
             (re.compile(r"\b(sampler(?:1D|2D|3D|CUBE))_(?:half|float|h|f)\b"), lambda m: m.group(1)),
             (re.compile(r"\bfloat1\b"), lambda m: "float")]


# ---------------------------------------------------------------------------------------------
# Reading C-like source.
# ---------------------------------------------------------------------------------------------
def strip_comments(text):
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            i = n if j < 0 else j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            body = text[i:n if j < 0 else j + 2]
            out.append("\n" * body.count("\n") or " ")
            i = n if j < 0 else j + 2
        elif c == '"':
            j = i + 1
            while j < n and text[j] != '"' and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            out.append(text[i:j + 1])
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


def logical_lines(text):
    text = strip_comments(text.replace("\r\n", "\n"))
    return re.sub(r"\\\n", " ", text).split("\n")


def split_top(text, sep=","):
    parts, depth, cur = [], 0, []
    for c in text:
        if c in "([<{":
            depth += 1
        elif c in ")]>}":
            depth -= 1
        if c == sep and depth == 0:
            parts.append("".join(cur))
            cur = []
        else:
            cur.append(c)
    parts.append("".join(cur))
    return [p.strip() for p in parts if p.strip()]


def norm_type(t):
    t = " ".join(t.split())
    for pattern, repl in PRECISION:
        t = pattern.sub(repl, t)
    return t


def parse_param(p):
    """('inout'|'out'|'', normalised type) of one parameter, or None for `void`."""
    p = re.sub(r"=.*$", "", p)
    p = re.sub(r":\s*\w+\s*$", "", p).strip()
    if p in ("", "void"):
        return None
    words = p.replace("[", " [").split()
    array = "".join(w for w in words if w.startswith("["))
    words = [w for w in words if not w.startswith("[")]
    direction = "out" if "out" in words else ("inout" if "inout" in words else "")
    words = [w for w in words if w not in QUALIFIERS]
    if len(words) >= 2:
        words = words[:-1]  # drop the parameter name
    return (direction, norm_type(" ".join(words)) + ("[]" if array else ""))


def param_list(params):
    out = []
    for p in split_top(params):
        parsed = parse_param(p)
        if parsed:
            out.append(parsed)
    return tuple(out)


class Source:
    """What one of varc's include files defines."""

    def __init__(self, name, text):
        self.name = name
        self.includes = []
        self.macros = {}        # name -> list of (arity or None, replacement, condition)
        self.functions = {}     # name -> list of (params, body, condition)
        self.variables = set()
        self.structs = {}       # name -> body text
        self.parse(text)

    def parse(self, text):
        stack, code = [], []   # condition stack; code lines with their condition
        guard_seen = False
        for line in logical_lines(text):
            s = line.strip()
            m = re.match(r"#\s*(\w+)\s*(.*)$", s)
            if not m:
                code.append((line, " && ".join(c for c in stack if c)))
                continue
            directive, rest = m.group(1), m.group(2).strip()
            if directive in ("if", "ifdef", "ifndef"):
                cond = {"ifdef": "defined(%s)" % rest, "ifndef": "!defined(%s)" % rest}.get(
                    directive, rest)
                if not guard_seen and directive in ("ifndef", "if") and not stack and not code:
                    guard_seen = True
                    cond = ""   # the include guard
                stack.append(cond)
            elif directive == "elif" and stack:
                stack[-1] = "(%s)" % rest
            elif directive == "else" and stack:
                stack[-1] = "!(%s)" % stack[-1] if stack[-1] else ""
            elif directive == "endif" and stack:
                stack.pop()
            elif directive == "include":
                inc = re.match(r'[<"]([^">]+)[">]', rest)
                if inc:
                    self.includes.append(os.path.basename(inc.group(1)))
            elif directive == "define":
                dm = re.match(r"([A-Za-z_]\w*)(\(([^)]*)\))?\s*(.*)$", rest)
                if dm and stack and stack[-1] == "!defined(%s)" % dm.group(1):
                    stack[-1] = ""  # an include guard (or a default: not a condition of use)
                if dm:
                    arity = None if dm.group(2) is None else len(split_top(dm.group(3)))
                    self.macros.setdefault(dm.group(1), []).append(
                        (arity, dm.group(4).strip(), " && ".join(c for c in stack if c)))
        self.parse_code(code)

    def parse_code(self, code):
        # Statements at brace depth 0 (cbuffer bodies count as depth 0).
        stmt, cond = [], ""
        depth, block = 0, None  # block = (kind, header, body chars, condition) while depth > 0
        for line, line_cond in code:
            s = line.strip()
            if depth == 0 and re.fullmatch(r"[A-Z_][A-Z0-9_]*\s*(\(.*\))?", s) and not "".join(stmt).strip():
                self.statement(s)
                continue
            if depth == 0 and re.fullmatch(r"[A-Z_][A-Z0-9_]*\s*(\(.*\))?", s):
                self.statement("".join(stmt))
                stmt = []
                self.statement(s)
                continue
            for c in line + "\n":
                if depth > 0:
                    if c == "{":
                        depth += 1
                    elif c == "}":
                        depth -= 1
                        if depth == 0:
                            self.block(block[0], block[1], "".join(block[2]), block[3])
                            block = None
                            continue
                    block[2].append(c)
                    continue
                if c == "{":
                    header = "".join(stmt).strip()
                    stmt = []
                    if re.match(r"(cbuffer|tbuffer)\b|uniform\s+\w+$", header):
                        continue  # a uniform block: its members are globals
                    depth, block = 1, ("block", header, [], cond or line_cond)
                elif c == "}":
                    stmt = []  # end of a cbuffer
                elif c == ";":
                    self.statement("".join(stmt))
                    stmt = []
                else:
                    if not stmt:
                        cond = line_cond
                    stmt.append(c)

    def statement(self, s):
        s = " ".join(s.split())
        if not s:
            return
        s = re.sub(r"^(CBUFFER_START|UNITY_INSTANCING_BUFFER_START)\s*\([^)]*\)\s*", "", s)
        s = re.sub(r"^(CBUFFER_END|UNITY_INSTANCING_BUFFER_END\s*\([^)]*\))\s*", "", s)
        if not s:
            return
        m = re.fullmatch(r"typedef\s+.*\b(\w+)", s)
        if m:
            self.variables.add(m.group(1))
            return
        m = re.fullmatch(r"struct\s+(\w+)", s)
        if m:
            self.structs.setdefault(m.group(1), "")
            return
        m = re.fullmatch(r"([A-Z_][A-Z0-9_]*)\s*\((.*)\)", s)
        if m:
            args = split_top(m.group(2))
            if args and IDENT.fullmatch(args[-1]):
                self.variables.add(args[-1])
                if m.group(1) == "UNITY_DEFINE_INSTANCED_PROP":
                    self.variables.add(args[-1] + "Array")  # the array it declares when instanced
            return
        s = re.sub(r"\s*=.*$", "", s)
        s = re.sub(r"\s*:\s*register\s*\(.*$", "", s)
        for decl in split_top(s):
            ids = IDENT.findall(re.sub(r"\[[^\]]*\]", "", decl))
            if ids:
                self.variables.add(ids[-1])

    def block(self, kind, header, body, cond):
        if header.rstrip().endswith("="):  # an initialiser list: `static const float3x3 M = {..}`
            self.statement(header.rstrip()[:-1])
            return
        m = re.fullmatch(r"(?:typedef\s+)?struct\s+(\w+)", header)
        if m:
            self.structs[m.group(1)] = body
            return
        m = re.match(r"(.*?)\b([A-Za-z_]\w*)\s*\((.*)\)\s*(?::\s*\w+)?$", header, re.S)
        if m and not re.match(r"(if|for|while|switch)\b", m.group(2)):
            try:
                params = param_list(m.group(3))
            except Exception:
                params = ()
            self.functions.setdefault(m.group(2), []).append((params, body, cond))


def load_builtin(directory):
    sources = {}
    for name in sorted(os.listdir(directory)):
        path = os.path.join(directory, name)
        if os.path.isfile(path) and name.endswith((".cginc", ".hlsl", ".glslinc")):
            with open(path, encoding="utf-8") as f:
                sources[name] = Source(name, f.read())
    return sources


def closure(sources, name):
    seen, todo = [], [name]
    while todo:
        n = todo.pop()
        if n in seen or n not in sources:
            continue
        seen.append(n)
        todo.extend(sources[n].includes)
    return seen


# ---------------------------------------------------------------------------------------------
# Classification.
# ---------------------------------------------------------------------------------------------
SIMPLE_ARG = re.compile(r"\(?([\w.#]+(\[\w+\])?|\w+\(\s*[-\d.,\sfh]*\)|-?\d+\.?\d*[fh]?)\)?")
INTRINSICS = {"mul", "dot", "cross", "normalize", "saturate", "float2", "float3", "float4", "half2",
              "half3", "half4", "fixed2", "fixed3", "fixed4", "max", "min", "abs"}


def alias_balanced(text):
    depth = 0
    for c in text:
        depth += {"(": 1, ")": -1}.get(c, 0)
        if depth < 0:
            return False
    return depth == 0


def alias_target(expr):
    """The callee when |expr| is a constant, a name or one call passing names and literals
    through (an alias): '' for a constant or name, the callee's name for a call, None else."""
    e = " ".join(expr.split())
    while e.startswith("(") and e.endswith(")") and len(split_top(e[1:-1])) == 1 \
            and alias_balanced(e[1:-1]):
        e = e[1:-1].strip()
    if not e or SIMPLE_ARG.fullmatch(e):
        return ""
    m = re.fullmatch(r"([A-Za-z_]\w*)\s*\((.*)\)(\.\w+)?", e)
    if m and all(SIMPLE_ARG.fullmatch(a) for a in split_top(m.group(2))):
        return m.group(1)
    return None


def body_returns(body):
    lines = [l.strip() for l in body.split("\n") if l.strip() and not l.strip().startswith("#")]
    stmts = [s.strip() for s in " ".join(lines).split(";") if s.strip()]
    if not stmts or not all(s.startswith("return") for s in stmts):
        return None
    return [s[6:] for s in stmts]


class Triviality:
    """Whether a function or macro of varc's includes is trivial: every definition is a constant,
    a name, or an alias of an intrinsic or of a trivial or value-tested function/macro."""

    def __init__(self, sources, tested):
        self.sources, self.tested, self.memo = sources, tested, {}

    def expr(self, e, depth):
        target = alias_target(e)
        if target is None:
            return False
        if target == "" or target in INTRINSICS:
            return True
        return self.name(target, depth + 1)

    def name(self, n, depth=0):
        if n in self.tested:
            return True
        if n in self.memo:
            return self.memo[n]
        if depth > 8:
            return False
        self.memo[n] = False
        funcs = [d for s in self.sources.values() for d in s.functions.get(n, [])]
        macros = [d for s in self.sources.values() for d in s.macros.get(n, [])]
        ok = bool(funcs or macros)
        for d in funcs:
            returns = body_returns(d[1])
            ok = ok and returns is not None and all(self.expr(r, depth) for r in returns)
        for d in macros:
            ok = ok and (d[0] is None or self.expr(d[1], depth))
        if not funcs and not macros:
            ok = True  # an intrinsic
        self.memo[n] = ok
        return ok

    def defs(self, defs, depth=0):
        for d in defs:
            if len(d) == 3 and isinstance(d[0], tuple):
                returns = body_returns(d[1])
                if returns is None or not all(self.expr(r, depth) for r in returns):
                    return False
            elif d[0] is not None and not self.expr(d[1], depth):
                return False
        return True


def value_tested_names():
    names = set()
    vulkan = os.path.join(ROOT, "tests", "vulkan")
    for name in sorted(os.listdir(vulkan)):
        if name.endswith(".cpp"):
            with open(os.path.join(vulkan, name), encoding="utf-8") as f:
                for m in re.finditer(r"//\s*api-value-tested:(.*)", f.read()):
                    names.update(m.group(1).split())
    return names


def tsv_params(signature):
    m = re.match(r"(.*?)\b([A-Za-z_]\w*)\s*\((.*)\)\s*$", signature)
    return param_list(m.group(3)) if m else ()


def same_params(a, b):
    return len(a) == len(b) and all(x[0] == y[0] and x[1] == y[1] for x, y in zip(a, b))


# Names Unity's include files #define only for compilers that lack them, and which glslang's
# HLSL front end knows natively (types, semantics, intrinsics); builtin.api-calls uses each
# (NATIVE_SHADER below).
NATIVE = ({"half", "half2", "half3", "half4", "half2x2", "half3x3", "half4x4", "min16float",
           "min16float2", "min16float3", "min16float4", "min10float", "min10float2", "min10float3",
           "min10float4", "asuint", "SV_POSITION", "SV_Target", "SV_Depth", "VFACE", "COLOR",
           "uint", "uint1", "uint2", "uint3", "uint4", "min16uint", "min16uint1", "min16uint2",
           "min16uint3", "min16uint4"} |
          {"SV_Target%d" % i for i in range(8)} | {"COLOR%d" % i for i in range(8)})
NATIVE_SHADER = """// Generated by scripts/builtin-api.py --calls-dir: the names docs/BUILTIN_API.md counts as
// native to glslang's HLSL front end.
Shader "varc-api-calls/native" {
    SubShader {
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma target 3.0
            struct v2f { float4 pos : SV_POSITION; half4 c : COLOR0; half4 c1 : COLOR1; %s };
            v2f vert(float4 v : POSITION, half4 col : COLOR) {
                v2f o = (v2f)0;
                o.pos = v;
                half h = 0; half2 h2 = 0; half3 h3 = 0; half4 h4 = 0;
                half2x2 m2 = (half2x2)0; half3x3 m3 = (half3x3)0; half4x4 m4 = (half4x4)0;
                min16float a = 0; min16float2 a2 = 0; min16float3 a3 = 0; min16float4 a4 = 0;
                min10float b = 0; min10float2 b2 = 0; min10float3 b3 = 0; min10float4 b4 = 0;
                uint c = 0; uint1 c1 = 0; uint2 c2 = 0; uint3 c3 = 0; uint4 c4 = 0;
                min16uint d = 0; min16uint1 d1 = 0; min16uint2 d2 = 0; min16uint3 d3 = 0; min16uint4 d4 = 0;
                o.c = col + h + h2.x + h3.x + h4 + m2[0].x + m3[0].x + m4[0] + a + a2.x + a3.x + a4
                    + b + b2.x + b3.x + b4 + (float)asuint(1.0) + c + c1 + c2.x + c3.x + c4.x + d + d1
                    + d2.x + d3.x + d4.x;
                o.c1 = 0;
                return o;
            }
            struct fout { %s float depth : SV_Depth; };
            fout frag(v2f i, float face : VFACE) {
                fout o = (fout)0;
                o.target = i.c * face;
                o.depth = 0;
                return o;
            }
            ENDCG
        }
    }
}
""" % (" ".join("half4 c%d : COLOR%d;" % (i, i) for i in range(2, 8)),
       "half4 target : SV_Target; " + " ".join("half4 t%d : SV_Target%d;" % (i, i) for i in range(1, 8)))


# DX9 sampling intrinsics of glslang's HLSL front end, by name: the (normalised) parameter lists
# it accepts. Probed by compiling each checklist overload (float4 coordinate for the bias, lod
# and proj forms; the 3-component tex2Dproj and texCUBEproj are not among them: varc's
# HLSLSupport.cginc provides those).
def _native_tex(dim, coord):
    s = "sampler" + dim
    return {"": [(("", s), ("", coord)), (("", s), ("", coord), ("", coord), ("", coord))],
            "bias": [(("", s), ("", "float4"))], "lod": [(("", s), ("", "float4"))],
            "grad": [(("", s), ("", coord), ("", coord), ("", coord))],
            "proj": [(("", s), ("", "float4"))] if dim != "CUBE" else []}


NATIVE_FUNCTIONS = collections.defaultdict(list)
for _prefix, _dim, _coord in (("tex1D", "1D", "float"), ("tex2D", "2D", "float2"),
                              ("tex3D", "3D", "float3"), ("texCUBE", "CUBE", "float3")):
    for _suffix, _lists in _native_tex(_dim, _coord).items():
        NATIVE_FUNCTIONS[_prefix + _suffix].extend(_lists)
NATIVE_TYPES = {"sampler1D", "sampler2D", "sampler3D", "samplerCUBE"}


def native_function(name, params):
    return any(same_params(p, params) for p in NATIVE_FUNCTIONS.get(name, []))


# Macros have no signature to generate a call from: this shader uses the ones added for #27 in
# the stages where Unity allows them.
MACRO_SHADER = """// Generated by scripts/builtin-api.py --calls-dir: macros of docs/BUILTIN_API.md in use.
Shader "varc-api-calls/macros" {
    SubShader {
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma target 3.5
            #include "UnityCG.cginc"
            UNITY_DECLARE_TEX2DARRAY(_A);
            UNITY_DECLARE_TEX2DARRAY_NOSAMPLER(_B);
            UNITY_DECLARE_TEXCUBEARRAY(_C);
            UNITY_DECLARE_TEXCUBEARRAY_NOSAMPLER(_C2);
            UNITY_DECLARE_TEX3D_FLOAT(_D);
            UNITY_DECLARE_TEX3D_HALF(_D2);
            UNITY_DECLARE_TEX3D_NOSAMPLER(_D3);
            UNITY_DECLARE_TEX2D_NOSAMPLER_FLOAT(_E);
            UNITY_DECLARE_TEX2D_NOSAMPLER_HALF(_E2);
            UNITY_DECLARE_TEX2D_NOSAMPLER_INT(_E3);
            UNITY_DECLARE_TEX2D_NOSAMPLER_UINT(_E4);
            UNITY_DECLARE_TEXCUBE_NOSAMPLER(_F);
            Texture2D_half _G1; Texture2D_float _G2; Texture3D_half _G3; Texture3D_float _G4;
            TextureCube_half _G5; TextureCube_float _G6; Texture2DArray_half _G7;
            Texture2DArray_float _G8; TextureCubeArray_half _G9; TextureCubeArray_float _G10;
            samplerCUBE _H;
            float4 _T_ST;
            GLOBAL_CBUFFER_START(ApiGlobal)
                float4 _ApiValue;
            GLOBAL_CBUFFER_END
            CBUFFER_START_WITH_BINDING(ApiBound, 0, 5)
                DECL_WITH_BINDING(float4, _ApiBound, 0, 6);
            CBUFFER_END
            float4 arrays(UNITY_ARGS_TEX2DARRAY(t), UNITY_ARGS_TEX2DARRAY_NOSAMPLER(n),
                          UNITY_ARGS_TEXCUBEARRAY(c), UNITY_ARGS_TEXCUBEARRAY_NOSAMPLER(cn),
                          UNITY_ARGS_TEXCUBE_NOSAMPLER(f), float4 p) {
                return t.Sample(samplert, p.xyz) + n.Load(int4(0, 0, 0, 0)) + c.Sample(samplerc, p)
                     + cn.SampleLevel(samplerc, p, 0) + f.SampleLevel(samplerc, p.xyz, 0);
            }
            float4 vert(float4 v : POSITION) : SV_POSITION {
                return v + UNITY_SAMPLE_TEX2DARRAY_LOD(_A, v.xyz, 0)
                     + UNITY_SAMPLE_TEX2DARRAY_SAMPLER_LOD(_B, _A, v.xyz, 0)
                     + UNITY_SAMPLE_TEXCUBEARRAY_LOD(_C, v, 0)
                     + UNITY_SAMPLE_TEXCUBEARRAY_SAMPLER_LOD(_C2, _C, v, 0)
                     + UNITY_SAMPLE_TEX3D_LOD(_D, v.xyz, 0) + UNITY_SAMPLE_TEX3D_SAMPLER_LOD(_D3, _D, v.xyz, 0)
                     + UNITY_Z_0_FAR_FROM_CLIPSPACE(v.z) + TransformStereoScreenSpaceTex(v.xy, 1).x
                     + float4(TRANSFORM_TEX(v.xy, _T), 0, 0) + _ApiValue + _ApiBound;
            }
            float4 frag(float4 p : SV_POSITION) : SV_Target {
                return arrays(UNITY_PASS_TEX2DARRAY(_A), UNITY_PASS_TEX2DARRAY_NOSAMPLER(_B),
                              UNITY_PASS_TEXCUBEARRAY(_C), UNITY_PASS_TEXCUBEARRAY_NOSAMPLER(_C2),
                              UNITY_PASS_TEXCUBE_NOSAMPLER(_F), p)
                     + UNITY_SAMPLE_TEX2DARRAY(_A, p.xyz) + UNITY_SAMPLE_TEX2DARRAY_SAMPLER(_B, _A, p.xyz)
                     + UNITY_SAMPLE_TEXCUBEARRAY(_C, p) + UNITY_SAMPLE_TEXCUBEARRAY_SAMPLER(_C2, _C, p)
                     + UNITY_SAMPLE_TEX3D_SAMPLER(_D2, _D, p.xyz) + _E.Load(int3(0, 0, 0))
                     + _E2.Load(int3(0, 0, 0)) + (float4)_E3.Load(int3(0, 0, 0)) + (float4)_E4.Load(int3(0, 0, 0))
                     + _G1.Load(int3(0, 0, 0)) + _G2.Load(int3(0, 0, 0)) + _G3.Load(int4(0, 0, 0, 0))
                     + _G4.Load(int4(0, 0, 0, 0)) + _G5.Sample(sampler_D, p.xyz) + _G6.Sample(sampler_D, p.xyz)
                     + _G7.Load(int4(0, 0, 0, 0)) + _G8.Load(int4(0, 0, 0, 0)) + _G9.Sample(sampler_D, p)
                     + _G10.Sample(sampler_D, p) + UNITY_SAMPLE_TEXCUBE_SHADOW(_H, p)
                     + SAMPLE_DEPTH_CUBE_TEXTURE(_H, p.xyz) + UNITY_SAMPLE_DEPTH(p);
            }
            ENDCG
        }
    }
}
"""


def classify(row, sources, tested, triv):
    kind, file, name, sig = row["kind"], row["file"], row["name"], row["signature"]
    if kind == "macro" and name in NATIVE:
        return "implemented", "native HLSL"
    if file not in sources:
        return "missing", "file not in varc"
    files = closure(sources, file)
    if kind == "include":
        return ("implemented", "") if name in files else ("missing", "not included")
    if kind == "macro":
        m = re.match(r"\w+\s*\(([^)]*)\)", sig)
        arity = None if not m else len(split_top(m.group(1)))
        found = [d for f in files for d in sources[f].macros.get(name, [])]
        if any(d[0] == arity for d in found):
            if arity is None or name in tested or triv.defs([d for d in found if d[0] == arity]):
                return "implemented", ""
            return "declared", "not value-tested"
        if arity is not None:
            funcs = [d for f in files for d in sources[f].functions.get(name, [])]
            if any(len(d[0]) == arity for d in funcs):
                return ("implemented" if name in tested else "declared"), "as a function"
        if found:
            return "missing", "other parameter list"
        if arity is None and any(name in sources[f].variables for f in files):
            return "implemented", "as a variable"
        funcs = [d for f in files for d in sources[f].functions.get(name, [])]
        if arity is None and funcs:  # e.g. a name Unity re-#defines to another function
            if name in tested or triv.defs(funcs):
                return "implemented", "as a function"
            return "declared", "as a function, not value-tested"
        return "missing", ""
    if kind == "function":
        want = tsv_params(sig)
        found = [d for f in files for d in sources[f].functions.get(name, [])]
        match = [d for d in found if same_params(d[0], want)]
        if match:
            if name in tested or triv.defs(match):
                return "implemented", ""
            return "declared", "not value-tested"
        macros = [d for f in files for d in sources[f].macros.get(name, [])]
        if any(d[0] == len(want) for d in macros):
            if name in tested or triv.defs([d for d in macros if d[0] == len(want)]):
                return "implemented", "as a macro"
            return "declared", "as a macro, not value-tested"
        if native_function(name, want):
            return "implemented", "native HLSL"
        if found or macros:
            return "missing", "other parameter list"
        return "missing", ""
    if kind == "variable":
        if any(name in sources[f].variables or name in sources[f].macros for f in files):
            return "implemented", ""
        return "missing", ""
    if kind == "struct":
        if name in NATIVE_TYPES:
            return "implemented", "native HLSL type"
        if any(name in sources[f].structs or name in sources[f].macros or
               name in sources[f].variables for f in files):
            return "implemented", ""
        return "missing", ""
    if kind == "member":
        struct, _, member = name.partition(".")
        member_name = re.match(r"\w+", member).group(0) if re.match(r"\w+", member) else member
        bodies = [sources[f].structs[struct] for f in files if struct in sources[f].structs]
        if not bodies:
            if struct in NATIVE_TYPES or norm_type(struct) in NATIVE_TYPES:
                return "missing", "native sampler type: no members"
            return "missing", "no struct"
        if any(re.search(r"\b%s\b" % re.escape(member_name), b) for b in bodies):
            return "implemented", ""
        return "missing", ""
    return "missing", "unknown kind"


def read_tsv(path):
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    header = lines[0].split("\t")
    rows = []
    for line in lines[1:]:
        if line:
            rows.append(dict(zip(header, line.split("\t"))))
    return header, rows


# ---------------------------------------------------------------------------------------------
# The document.
# ---------------------------------------------------------------------------------------------
def cell(text):
    return text.replace("|", "\\|").replace("`", "'")


def render(header, rows, results):
    vcols = header[5:12]
    out = []
    w = out.append
    total = collections.Counter(r for r, _ in results)
    n = len(rows)
    w("# Unity built-in include API in varc")
    w("")
    w("Generated by `scripts/builtin-api.py --write` (issue #27); the test `builtin.api-inventory` "
      "fails when this page differs from what the script computes, so no figure here is edited "
      "by hand.")
    w("")
    w("Every row of the checklist `../shared/reference/unity-builtin-api.tsv` (Unity's built-in "
      "pipeline `CGIncludes`, releases 5.6 to 2022.3: one row per include edge, macro, function "
      "signature, variable, struct and struct member) against varc's include files "
      "(`shaders/builtin/`):")
    w("")
    w("* **implemented**: defined in the include closure of the row's file (the file and what it "
      "includes) with a compatible signature (same parameter count, types equal once `half`, "
      "`fixed` and `unityShadowCoord` are read as `float`, same `out`/`inout`; a macro with the "
      "same arity), and either trivial (a constant, an alias, a declaration, a body that only "
      "returns such a thing; object-like macros) or evaluated by a value test on lavapipe "
      "against the documented formula (named on an `// api-value-tested:` line of "
      "`tests/vulkan/*.cpp`).")
    w("  Also implemented, noted *native HLSL*: rows glslang's HLSL front end provides itself "
      "(the DX9 sampler types and their `tex1D`/`tex2D`/`tex3D`/`texCUBE` intrinsics with the "
      "row's parameter list, `sampler2D_f` & co. read as `sampler2D`); `builtin.api-calls` "
      "compiles a call of each such function row.")
    w("* **declared**: defined with a compatible signature but non-trivial and not value-tested.")
    w("* **missing**: not defined, or only with another parameter list, or its file does not "
      "exist in varc.")
    w("")
    w("`builtin.api-calls` compiles a call of every implemented and declared function in the "
      "vertex stage (unless it needs derivatives or implicit-LOD sampling) and the fragment "
      "stage, and a fixed shader uses the texture and helper macros added for #27; other macros "
      "are compiled only where varc's shaders, the fixtures and the corpus use them. Versions: "
      "the releases of the checklist where the row exists (`5.6`…`2022.3`).")
    w("")
    w("## Totals")
    w("")
    w("| | implemented | declared | missing | rows |")
    w("|---|---|---|---|---|")
    for kind in KINDS:
        c = collections.Counter(r for (r, _), row in zip(results, rows) if row["kind"] == kind)
        w("| %s | %d | %d | %d | %d |" % (kind, c["implemented"], c["declared"], c["missing"],
                                         sum(c.values())))
    w("| **all** | %d (%.1f %%) | %d (%.1f %%) | %d (%.1f %%) | %d |" % (
        total["implemented"], 100.0 * total["implemented"] / n, total["declared"],
        100.0 * total["declared"] / n, total["missing"], 100.0 * total["missing"] / n, n))
    w("")
    w("## Per include file")
    w("")
    w("| file | implemented | declared | missing | rows |")
    w("|---|---|---|---|---|")
    byfile = collections.OrderedDict()
    for (res, note), row in zip(results, rows):
        byfile.setdefault(row["file"], []).append((row, res, note))
    for file, entries in byfile.items():
        c = collections.Counter(r for _, r, _ in entries)
        w("| [`%s`](#%s) | %d | %d | %d | %d |" % (file, re.sub(r"[^a-z0-9_-]", "", file.lower()),
                                                   c["implemented"], c["declared"], c["missing"],
                                                   len(entries)))
    for file, entries in byfile.items():
        c = collections.Counter(r for _, r, _ in entries)
        w("")
        w("## %s" % file)
        w("")
        w("%d implemented, %d declared, %d missing." % (c["implemented"], c["declared"],
                                                       c["missing"]))
        w("")
        w("| kind | signature | versions | status |")
        w("|---|---|---|---|")
        for row, res, note in entries:
            present = [v for v, col in zip(VERSIONS, vcols) if row[col] == "1"]
            versions = present[0] + ("–" + present[-1] if len(present) > 1 else "") \
                if present and len(present) == VERSIONS.index(present[-1]) - VERSIONS.index(present[0]) + 1 \
                else ", ".join(present)
            w("| %s | `%s` | %s | %s%s |" % (row["kind"], cell(row["signature"]), versions, res,
                                            " (%s)" % note if note else ""))
    return "\n".join(out) + "\n"


# ---------------------------------------------------------------------------------------------
# The generated call test.
# ---------------------------------------------------------------------------------------------
FRAGMENT_ONLY = re.compile(r"\b(ddx|ddy|ddx_fine|ddy_fine|fwidth|clip|discard|tex2D|tex2Dbias|"
                           r"tex2Dproj|texCUBE|texCUBEbias|texCUBEproj|tex3D|tex2Dgrad|"
                           r"UNITY_SAMPLE_TEX2D|UNITY_SAMPLE_TEXCUBE|UNITY_SAMPLE_SHADOW|"
                           r"UNITY_SAMPLE_TEX2DARRAY|UNITY_SAMPLE_TEX2D_SAMPLER|"
                           r"UNITY_SAMPLE_DEPTH|SAMPLE_DEPTH_TEXTURE|UNITY_SAMPLE_SCREENSPACE_SHADOW)\b|\.Sample\s*\(")
SAMPLERS = {"sampler1D": "sampler1D", "sampler2D": "sampler2D", "samplerCUBE": "samplerCUBE", "sampler3D": "sampler3D",
            "Texture2D": "Texture2D", "TextureCube": "TextureCube", "SamplerState": "SamplerState"}
# Resources cannot be local variables: the call test passes a global of that type instead.
# Structs holding resources (e.g. GraniteCacheTexture) cannot be either, and a global one makes
# spirv-opt's legalization (FixStorageClass) crash, so calls taking one are left to hand-written
# shaders that fill a local from separate globals (tests/builtin/shaders/*).
RESOURCE = re.compile(r"(RW)?(ByteAddressBuffer|(Structured)?Buffer|Texture\w*)\b.*")


def opaque_structs(sources):
    return {name for s in sources.values() for name, body in s.structs.items()
            if re.search(r"\b(Texture\w*|SamplerState|sampler\w*|(RW)?ByteAddressBuffer)\b", body)}


def fragment_only_names(sources):
    bodies = {}
    for s in sources.values():
        for name, defs in s.functions.items():
            bodies.setdefault(name, []).extend(d[1] for d in defs)
    frag = {n for n, bs in bodies.items() if any(FRAGMENT_ONLY.search(b) for b in bs)}
    changed = True
    while changed:
        changed = False
        for n, bs in bodies.items():
            if n not in frag and any(re.search(r"\b(%s)\s*\(" % "|".join(map(re.escape, frag)), b)
                                     for b in bs) if frag else False:
                frag.add(n)
                changed = True
    return frag


# Per include file: the pass's LightMode and the defines that make the API's full signatures
# exist (several entry points take arguments only in some variants).
CALL_PASS = {
    "UnityStandardMeta.cginc": ("Meta", ""),
    "UnityMetaPass.cginc": ("Meta", ""),
    "UnityStandardShadow.cginc": ("ShadowCaster", "#define _ALPHABLEND_ON"),
    "UnityStandardParticleShadow.cginc": ("ShadowCaster", "#define _ALPHABLEND_ON"),
    # A surface shader's include: SurfaceOutput comes from the Lighting.cginc it brings.
    "TerrainSplatmapCommon.cginc": ("", '#include "Lighting.cginc"'),
}


NUMERIC = re.compile(r"(float|int|uint|bool|vec|ivec|uvec|bvec)([1-4])?")


def numeric_part(expr, t, glsl):
    """A float expression of the first component of |expr| of numeric type |t|: every call's
    result feeds the stage's output so that no call is optimised away before validation."""
    m = NUMERIC.fullmatch(t)
    vector = m.group(2) not in (None, "1") or m.group(1) in ("vec", "ivec", "uvec", "bvec")
    first = "(%s).x" % expr if vector else "(%s)" % expr
    return ("float(%s)" if glsl else "(float)%s") % first


def write_calls(directory, rows, results, sources):
    os.makedirs(directory, exist_ok=True)
    for old in os.listdir(directory):
        if old.startswith("api-calls-"):
            os.remove(os.path.join(directory, old))
    frag = fragment_only_names(sources)
    opaque = opaque_structs(sources)
    with open(os.path.join(directory, "api-calls-native.shader"), "w", encoding="utf-8") as f:
        f.write(NATIVE_SHADER)
    with open(os.path.join(directory, "api-calls-macros.shader"), "w", encoding="utf-8") as f:
        f.write(MACRO_SHADER)
    per_file = collections.OrderedDict()
    for (res, note), row in zip(results, rows):
        if row["kind"] != "function" or res == "missing" or "macro" in note:
            continue
        want = tsv_params(row["signature"])
        files = closure(sources, row["file"])
        defs = [d for f in files for d in sources[f].functions.get(row["name"], [])
                if same_params(d[0], want)]
        if not defs and note == "native HLSL":
            defs = [(want, "", "")]
            if not row["name"].endswith("lod"):
                frag.add(row["name"])  # implicit LOD or gradients: fragment stage only
        ret = norm_type(re.match(r"\s*(.*?)\s*\b%s\s*\(" % re.escape(row["name"]),
                                 row["signature"]).group(1).split()[-1])
        per_file.setdefault(row["file"], collections.OrderedDict())[(row["name"], want)] = (
            defs[0], ret)
    written = 0
    for file, calls in per_file.items():
        globals_, stage = [], {"vertex": [], "fragment": []}
        glsl = file.endswith(".glslinc")
        for i, ((name, params), ((_, _, cond), ret)) in enumerate(calls.items()):
            args, decls, ok, sink = [], [], True, []
            for k, (direction, t) in enumerate(params):
                base = t.replace("[]", "")
                macro_arg = re.fullmatch(r"UNITY_ARGS_(\w+)\s*\(\s*\w+\s*\)", base)
                if macro_arg:
                    g = "api_%s_%d_%d" % (macro_arg.group(1), i, k)
                    globals_.append((cond, "UNITY_DECLARE_%s(%s);" % (macro_arg.group(1), g)))
                    args.append("UNITY_PASS_%s(%s)" % (macro_arg.group(1), g))
                elif base in opaque:
                    ok = False
                elif base in SAMPLERS or RESOURCE.fullmatch(base):
                    g = "api_%s_%d_%d" % (re.sub(r"\W", "_", base), i, k)
                    globals_.append((cond, "%s%s %s;" % ("uniform " if glsl else "", base, g)))
                    args.append(g)
                elif t.endswith("[]"):
                    ok = False
                elif glsl:
                    decls.append("%s a%d_%d = %s(0);" % (base, i, k, base))
                    args.append("a%d_%d" % (i, k))
                else:
                    decls.append("%s a%d_%d = (%s)0;" % (base, i, k, base))
                    args.append("a%d_%d" % (i, k))
                if direction and NUMERIC.fullmatch(base):
                    sink.append(numeric_part("a%d_%d" % (i, k), base, glsl))
            if not ok:
                continue
            expr = "%s(%s)" % (name, ", ".join(args))
            if NUMERIC.fullmatch(ret):
                call = "{ %s api_sink += %s; }" % (" ".join(decls), numeric_part(expr, ret, glsl))
            else:
                call = "{ %s %s; }" % (" ".join(decls), expr)
            if sink:
                call = call[:-1] + " api_sink += %s; }" % " + ".join(sink)
            text = ("#if %s\n        %s\n#endif" % (cond, call)) if cond else call
            stage["fragment"].append(text)
            if name not in frag:
                stage["vertex"].append(text)
        shader_name = re.sub(r"\W", "_", file)
        if glsl:
            lines = ["// Generated by scripts/builtin-api.py --calls-dir: a call of every implemented",
                     "// or declared function of %s (docs/BUILTIN_API.md)." % file,
                     'Shader "varc-api-calls/%s" {' % shader_name,
                     "    SubShader {", "        Pass {", "            GLSLPROGRAM",
                     '            #include "%s"' % file]
            for cond, g in globals_:
                lines += ["#if %s" % cond, g, "#endif"] if cond else [g]
            lines += ["            #ifdef VERTEX", "            void main() {", "                float api_sink = 0.0;"]
            lines += ["        " + c for c in stage["vertex"]]
            lines += ["                gl_Position = vec4(api_sink);", "            }", "            #endif",
                      "            #ifdef FRAGMENT", "            out vec4 api_color;",
                      "            void main() {", "                float api_sink = 0.0;"]
            lines += ["        " + c for c in stage["fragment"]]
            lines += ["                api_color = vec4(api_sink);", "            }", "            #endif",
                      "            ENDGLSL", "        }", "    }", "}", ""]
            with open(os.path.join(directory, "api-calls-%s.shader" % shader_name), "w",
                      encoding="utf-8") as f:
                f.write("\n".join(lines))
            written += 1
            continue
        lines = ["// Generated by scripts/builtin-api.py --calls-dir: a call of every implemented",
                 "// or declared function of %s (docs/BUILTIN_API.md)." % file,
                 'Shader "varc-api-calls/%s" {' % shader_name,
                 "    SubShader {", "        Pass {"]
        light_mode, defines = CALL_PASS.get(file, ("", ""))
        if light_mode:
            lines.append('            Tags { "LightMode" = "%s" }' % light_mode)
        lines += ["            CGPROGRAM",
                  "            #pragma vertex api_vert", "            #pragma fragment api_frag",
                  "            #pragma target 3.0"]
        if defines:
            lines.append("            " + defines)
        lines.append('            #include "%s"' % file)
        for cond, g in globals_:
            lines += ["#if %s" % cond, g, "#endif"] if cond else [g]
        lines.append("            float api_vertex_calls() {")
        lines.append("                float api_sink = 0;")
        lines += ["        " + c for c in stage["vertex"]]
        lines.append("                return api_sink;")
        lines.append("            }")
        lines.append("            float api_fragment_calls() {")
        lines.append("                float api_sink = 0;")
        lines += ["        " + c for c in stage["fragment"]]
        lines.append("                return api_sink;")
        lines.append("            }")
        lines += ["            float4 api_vert(float4 v : POSITION) : SV_POSITION { return v + api_vertex_calls(); }",
                  "            float4 api_frag() : SV_Target { return api_fragment_calls(); }",
                  "            ENDCG", "        }", "    }", "}", ""]
        with open(os.path.join(directory, "api-calls-%s.shader" % shader_name), "w",
                  encoding="utf-8") as f:
            f.write("\n".join(lines))
        written += 1
    return written


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--tsv", default=os.path.join(ROOT, "..", "shared", "reference",
                                                  "unity-builtin-api.tsv"))
    ap.add_argument("--builtin", default=os.path.join(ROOT, "shaders", "builtin"))
    ap.add_argument("--doc", default=os.path.join(ROOT, "docs", "BUILTIN_API.md"))
    ap.add_argument("--write", action="store_true")
    ap.add_argument("--check", action="store_true")
    ap.add_argument("--calls-dir")
    a = ap.parse_args()
    header, rows = read_tsv(a.tsv)
    sources = load_builtin(a.builtin)
    tested = value_tested_names()
    triv = Triviality(sources, tested)
    results = [classify(r, sources, tested, triv) for r in rows]
    doc = render(header, rows, results)
    c = collections.Counter(r for r, _ in results)
    summary = "%d rows: %d implemented, %d declared, %d missing" % (
        len(rows), c["implemented"], c["declared"], c["missing"])
    status = 0
    if a.write:
        with open(a.doc, "w", encoding="utf-8") as f:
            f.write(doc)
        print("wrote %s: %s" % (os.path.relpath(a.doc), summary))
    if a.check:
        try:
            with open(a.doc, encoding="utf-8") as f:
                current = f.read()
        except OSError:
            current = ""
        if current != doc:
            print("%s is stale: run scripts/builtin-api.py --write (%s)" % (a.doc, summary))
            status = 1
        else:
            print("%s is up to date: %s" % (a.doc, summary))
    if a.calls_dir:
        n = write_calls(a.calls_dir, rows, results, sources)
        print("wrote %d call shaders into %s" % (n, a.calls_dir))
    if not (a.write or a.check or a.calls_dir):
        print(summary)
    return status


if __name__ == "__main__":
    sys.exit(main())
