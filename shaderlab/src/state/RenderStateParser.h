// SPDX-License-Identifier: Apache-2.0
// Parses render-state commands (Blend, ZWrite, Stencil, ...) and skips legacy fixed-function ones.
#pragma once

#include <span>
#include <string_view>

#include "lex/Token.h"
#include "lex/TokenCursor.h"
#include "varc/shaderlab/RenderState.h"

namespace varc::shaderlab {

enum class CommandResult { NotACommand, Parsed, Failed };

// Shared by Category, SubShader and Pass bodies. Later commands in one scope override earlier
// ones (`Cull Back ... Cull Off` -> Off). Values naming render target 1..7 are accepted and
// dropped; only target 0 is recorded.
class RenderStateParser {
public:
    explicit RenderStateParser(TokenCursor& cursor) : mCursor(cursor) {}

    // When the next token names a render-state command (Blend, BlendOp, ZWrite, ZTest, Cull,
    // ColorMask, Offset, AlphaToMask, Conservative, ZClip, Stencil) or a legacy fixed-function
    // command (Lighting, Material, SetTexture, Fog, AlphaTest, ...), consumes the whole command,
    // records it in |state| and returns Parsed (or Failed after reporting). Otherwise consumes
    // nothing and returns NotACommand.
    // Example: "Blend SrcAlpha OneMinusSrcAlpha" -> state.blend = {SrcAlpha, OneMinusSrcAlpha}.
    CommandResult tryParse(RenderState& state);

    // True when |token| names a command tryParse() accepts.
    static bool isCommand(const Token& token);

private:
    using Handler = bool (RenderStateParser::*)(RenderState& state);
    struct Command {
        std::string_view name;
        Handler handler;
    };
    // The non-legacy commands and their handlers.
    static std::span<const Command> commands();

    bool parseBlend(RenderState& state);
    bool parseBlendFactors(BlendState& blend);
    bool parseBlendOp(RenderState& state);
    bool parseColorMask(RenderState& state);
    bool parseOffset(RenderState& state);
    bool parseStencil(RenderState& state);
    bool parseZWrite(RenderState& state);
    bool parseZTest(RenderState& state);
    bool parseCull(RenderState& state);
    bool parseAlphaToMask(RenderState& state);
    bool parseConservative(RenderState& state);
    bool parseZClip(RenderState& state);
    bool parseRenderTarget(int& target);

    TokenCursor& mCursor;
};

}  // namespace varc::shaderlab
