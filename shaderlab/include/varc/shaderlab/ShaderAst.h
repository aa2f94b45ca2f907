// SPDX-License-Identifier: Apache-2.0
// The parsed form of a .shader file: properties, subshaders, passes and program blocks.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "varc/core/SourceLocation.h"
#include "varc/shaderlab/RenderState.h"

namespace varc::shaderlab {

// "Key" = "Value" pairs in declaration order (Tags { "LightMode" = "ForwardBase" }).
using Tags = std::vector<std::pair<std::string, std::string>>;
// Value of |key| (case-insensitive) in |tags|, or "" when absent.
std::string findTag(const Tags& tags, const std::string& key);

enum class PropertyType { Color, Vector, Float, Int, Integer, Range, Texture2D, Texture3D, Cube,
                          Texture2DArray, CubeArray, Any };

struct Property {
    std::vector<std::string> attributes;  // "Gamma", "Toggle(_FOO_ON)", "HDR", ... as written
    std::string name;                     // "_MainTex"
    std::string displayName;              // "Albedo"
    PropertyType type = PropertyType::Float;
    float rangeMin = 0, rangeMax = 0;     // Range(min, max)
    std::string defaultValue;             // source as written: "(1, 1, 1, 1)", "\"white\" {}"
    SourceLocation location;              // of the property name
};

enum class ProgramLanguage { Cg, Hlsl, Glsl };

// A CGPROGRAM/HLSLPROGRAM/GLSLPROGRAM block, or a CGINCLUDE/HLSLINCLUDE/GLSLINCLUDE block.
struct ProgramBlock {
    ProgramLanguage language = ProgramLanguage::Cg;
    std::string text;        // between the opening keyword and END*, verbatim
    SourceLocation origin;   // location of text[0]
};

// Where a pass came from: written in the shader itself, or borrowed from another shader by
// `UsePass "Shader/PASS"` or (shadow casters) through the `Fallback` chain.
struct PassOrigin {
    enum class Kind { Own, UsePass, Fallback };
    Kind kind = Kind::Own;
    std::string shader;          // name of the shader the pass was written in; "" when Own
    SourceLocation reference;    // the `UsePass` or `Fallback` that brought it in
};

// The options of `#pragma surface FUNC MODEL [options]` (docs/SURFACE_SHADERS.md). Options
// varc accepts without acting on them (meta pass, interpolation hints) are not kept.
struct SurfaceOptions {
    enum class Alpha { Off, Blend, Fade, Premultiply };
    enum class Decal { None, Add, Blend };
    std::string vertexFunction;      // `vertex:FN`
    std::string finalColorFunction;  // `finalcolor:FN`
    std::string alphaTestProperty;   // `alphatest:PROP`
    Alpha alpha = Alpha::Off;        // `alpha`, `alpha:blend|fade|premul`
    Decal decal = Decal::None;       // `decal:add|blend`
    bool keepAlpha = false;
    bool addShadow = false;
    bool fullForwardShadows = false;
    bool noForwardAdd = false;
    bool noAmbient = false;
    bool noVertexLights = false;
    bool noFog = false;
    bool noShadow = false;
    bool ditherCrossFade = false;    // `dithercrossfade`: LOD_FADE_CROSSFADE variants, dithered
    bool excludeForward = false;     // `exclude_path:forward`
    // The options that remove keywords of the forward shortcuts (`nolightmap`, `nodirlightmap`,
    // `nodynlightmap`, `noshadowmask`, `novertexlights`, `noshadow`), in the order written.
    std::vector<std::string> shortcutOptions;
};

// A CG/HLSL program written directly in a SubShader with `#pragma surface`: the compiler turns
// it into ForwardBase, ForwardAdd (and, with `addshadow`, ShadowCaster) passes.
struct SurfaceProgram {
    ProgramBlock block;
    std::string function;       // FUNC: `void FUNC(Input IN, inout SurfaceOutputX o)`
    std::string lightingModel;  // MODEL: `Lighting<MODEL>` is the lighting function
    SurfaceOptions options;
    SourceLocation pragma;      // of the `#` of `#pragma surface`
};

// Code varc wrote around a pass's program (the passes of a surface program): |before| is
// spliced before the *INCLUDE blocks and the program, |after| after the program. Every line of
// both maps to |location| (the `#pragma surface`) in diagnostics.
struct GeneratedCode {
    std::string before;
    std::string after;
    SourceLocation location;
};

struct Pass {
    std::string name;        // from `Name "..."`, "" if none
    Tags tags;               // own tags; then the SubShader's LightMode when the pass sets none
    RenderState state;       // effective: SubShader/Category state already inherited
    std::optional<ProgramBlock> program;
    // Shared *INCLUDE blocks in scope (shader, category, subshader, pass level) in file order;
    // Unity prepends these to the program text. A block applies to every pass of its scope,
    // also to passes written before it.
    std::vector<ProgramBlock> includeBlocks;
    std::string usePass;     // `UsePass "Shader/PASSNAME"`: a reference instead of a pass body
    SourceLocation location; // of the `Pass`/`UsePass` keyword
    PassOrigin origin;       // Own as parsed; set when the compiler resolves a reference
    // Set for the placeholder of a surface program as parsed (no |program|); the compiler
    // replaces the placeholder by the passes it generates, which carry |generated|.
    std::optional<SurfaceProgram> surface;
    std::optional<GeneratedCode> generated;

    std::string lightMode() const { return findTag(tags, "LightMode"); }
};

struct SubShader {
    Tags tags;                 // own tags, then an enclosing Category's that are not overridden
    int lod = 0;               // `LOD n`; when 0, the enclosing Category's LOD
    std::vector<Pass> passes;  // `Pass` and `UsePass` in file order; `GrabPass` is not listed
    SourceLocation location;   // of the `SubShader` keyword
};

struct ShaderFile {
    std::string name;                    // `Shader "Custom/Name"`
    std::vector<Property> properties;
    std::vector<SubShader> subShaders;
    std::optional<std::string> fallback; // `Fallback "VertexLit"`; nullopt for none or Off
    bool fallbackOff = false;            // `Fallback Off` written explicitly
    SourceLocation fallbackLocation;     // of the `Fallback` keyword
    std::string customEditor;
    // `Dependency "BaseMapShader" = "Name"` pairs in declaration order.
    std::vector<std::pair<std::string, std::string>> dependencies;
    SourceLocation location;             // of the `Shader` keyword
};

}  // namespace varc::shaderlab
