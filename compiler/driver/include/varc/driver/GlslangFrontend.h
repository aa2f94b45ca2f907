// SPDX-License-Identifier: Apache-2.0
// glslang in-process: preprocess and compile one program stage to SPIR-V.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "varc/core/Stage.h"
#include "varc/shaderlab/ShaderAst.h"

namespace varc::driver {

// One stage of one program as glslang sees it.
struct FrontendInput {
    std::string_view text;  // expanded source (with `#line` directives) or its preprocessed form
    std::string_view preamble;  // `#define` lines from makePreamble()
    shaderlab::ProgramLanguage language = shaderlab::ProgramLanguage::Cg;
    Stage stage = Stage::Vertex;
    std::string_view entryPoint;
};

struct PreprocessOutput {
    bool ok = false;
    std::string text;  // macros expanded, conditionals resolved, `#line` directives kept
    std::string log;   // glslang's info log (see parseGlslangLog)
};

struct CompileOutput {
    bool ok = false;
    std::vector<uint32_t> spirv;  // unoptimised, with HLSL semantic decorations
                                  // (SPV_GOOGLE_hlsl_functionality1) for reflection
    std::string log;
};

// Initialises glslang's process state once; thread-safe and idempotent. Call before fanning out
// work to threads. Finalisation is left to process exit.
void initializeGlslang();

// Runs glslang's preprocessor only. CG/HLSL blocks use the HLSL front end in DX9-compatible
// mode (sampler2D, tex2D, tex2Dbias, ...).
PreprocessOutput preprocessProgram(const FrontendInput& input);

// Parses, links (auto-mapped bindings and locations) and generates SPIR-V 1.0 for Vulkan 1.0.
CompileOutput compileProgram(const FrontendInput& input);

// "12.0.0" — the front end's version, recorded in pack headers.
std::string glslangVersionString();

}  // namespace varc::driver
