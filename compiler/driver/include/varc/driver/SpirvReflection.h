// SPDX-License-Identifier: Apache-2.0
// Reflection of a compiled stage program from its SPIR-V: blocks, resources, stage interface.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>

#include "varc/pack/ProgramReflection.h"

namespace varc::driver {

// Reflects |optimized| (the module that ships). HLSL semantics (POSITION, TEXCOORD0, ...) are
// read from |withSemantics|, the module before optimisation, which still carries glslang's
// SPV_GOOGLE_hlsl_functionality1 decorations; they are matched by input location. Built-in
// variables (gl_Position, SV_Position) are not listed as stage inputs/outputs. Lists are sorted
// (blocks and resources by set and binding, interface variables by location) so equal modules
// give equal reflection. Returns nullopt for a malformed module.
std::optional<pack::ProgramReflection> reflectSpirv(std::span<const uint32_t> optimized,
                                                    std::span<const uint32_t> withSemantics,
                                                    bool isVertexStage);

// HLSL semantic names by input/output location, e.g. {0: "POSITION", 1: "TEXCOORD0"}.
using SemanticsByLocation = std::map<uint32_t, std::string>;

// The semantics glslang recorded in |withSemantics|; nullopt for a malformed module.
std::optional<SemanticsByLocation> hlslSemantics(std::span<const uint32_t> withSemantics);

// reflectSpirv with the semantics already read (e.g. kept in the program cache).
std::optional<pack::ProgramReflection> reflectSpirv(std::span<const uint32_t> optimized,
                                                    const SemanticsByLocation& semantics,
                                                    bool isVertexStage);

}  // namespace varc::driver
