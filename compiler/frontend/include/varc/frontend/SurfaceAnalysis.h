// SPDX-License-Identifier: Apache-2.0
// What the pass generator of a surface program needs to know about the user's code.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "varc/core/Diagnostic.h"
#include "varc/shaderlab/ShaderAst.h"

namespace varc::frontend {

// How the lighting function `Lighting<MODEL>` takes its light (docs/SURFACE_SHADERS.md):
// Gi: (s, gi); GiViewDir: (s, viewDir, gi); Legacy: (s, lightDir, atten);
// LegacyViewDir: (s, lightDir, viewDir, atten).
enum class LightingShape { Gi, GiViewDir, Legacy, LegacyViewDir };

struct SurfaceFacts {
    std::vector<std::string> inputMembers;  // member names of `struct Input`, in order
    bool inputHasInternalData = false;      // `INTERNAL_DATA` written in Input
    // The Input member declared with the face semantic (`fixed facing : VFACE`, or
    // `bool facing : SV_IsFrontFace`), which the fragment program fills from the rasteriser:
    // +1 / -1 for VFACE, true / false for SV_IsFrontFace. Empty when there is none.
    std::string faceMember;
    std::string faceSemantic;                  // "VFACE" or "SV_IsFrontFace"
    bool faceIsBool = false;                   // the member is declared `bool`
    std::string outputType = "SurfaceOutput";  // the surface function's second parameter type
    std::vector<std::string> outputMembers;    // member names of outputType, when found
    bool writesNormal = false;                 // the surface function assigns o.Normal
    bool surfaceDiscards = false;              // the surface function calls clip() or discards
    std::string vertexInputType = "appdata_full";
    std::vector<std::string> vertexInputMembers;  // member names of vertexInputType
    bool vertexWritesInput = false;  // vertex:FN has the (inout T v, out Input o) shape
    LightingShape lighting = LightingShape::Gi;
    bool hasGiFunction = false;  // `Lighting<MODEL>_GI` is defined
    std::string programText;     // the analysed text, comments and #pragma
                                 // lines blanked

    bool hasInputMember(std::string_view name) const;
    // Whether |name| appears as a whole word in the analysed text outside comments and
    // #pragma lines (`_MainTex_ST`).
    bool mentions(std::string_view name) const;
};

// The parameter list of the first definition of function |name| in |text| (a `name(...)`
// followed by `{`), split at top-level commas and trimmed; nullopt when none is defined.
// Example: "void surf (Input IN, inout SurfaceOutput o) {" ->
// {"Input IN", "inout SurfaceOutput o"}.
std::optional<std::vector<std::string>> functionParameters(std::string_view text,
                                                           std::string_view name);

// The member names of the first `struct |name| { ... }` in |text| (preprocessor lines
// skipped, semantics and array sizes dropped); nullopt when no such struct is defined.
// Example: "struct Input { float2 uv_MainTex : TEXCOORD0; float3 viewDir; };" ->
// {"uv_MainTex", "viewDir"}.
std::optional<std::vector<std::string>> structMembers(std::string_view text, std::string_view name);

// |text| with // and /* */ comments replaced by spaces (newlines kept).
std::string withoutComments(std::string_view text);

// Reads the facts of |program| from |text| (its program with includes spliced, or at least its
// own text). Reports at |program.pragma| and returns nullopt when the surface function or the
// lighting function `Lighting<MODEL>` is not defined, or has a shape varc cannot call.
std::optional<SurfaceFacts> analyzeSurface(const shaderlab::SurfaceProgram& program,
                                           std::string_view text, DiagnosticSink& sink);

}  // namespace varc::frontend
