// SPDX-License-Identifier: Apache-2.0
// Moves textures, samplers and buffers declared in a cbuffer before the cbuffer.
//
// FXC takes a resource declared in a file-scope cbuffer as a global; glslang makes it a member,
// which Vulkan forbids. This rewrite moves each such declaration to just before the `cbuffer`
// keyword, on that line (its line breaks turned to spaces), and blanks it where it was, keeping its
// line breaks there. It never adds, removes or moves a line break, so every `#line` mapping still
// holds.
#include "HlslRewrite.h"
#include "HlslRewritePasses.h"

namespace varc::frontend::hlsl {

namespace {

using pruner::TokenKind;

class CbufferResourceHoistRewrite : public HlslRewrite {
public:
    explicit CbufferResourceHoistRewrite(RewriteState& state) : HlslRewrite(state) {}

    // `cbuffer M { sampler2D _A; float4 _S; };` -> `sampler2D _A; cbuffer M { float4 _S; };`
    // (the moved text blanked in the body, its line breaks kept): the DirectX compilers take a
    // resource declared in a cbuffer as a global, glslang makes it a member, which Vulkan forbids.
    void run() {
        for (const auto& [open, close] : mCbufferBodies) {
            size_t keyword = open;
            while (keyword > 0 && !isWord(keyword, "cbuffer") && !isWord(keyword, "tbuffer")) {
                --keyword;
            }
            std::string hoistedAll;
            size_t begin = open + 1;
            for (size_t i = open + 1; i < close; ++i) {
                if (!is(i, ';') || mDepth[i] != 1) continue;
                if (isResourceDeclaration(begin, i)) {
                    std::string declaration =
                        mTokenizer.code().substr(offsetOf(begin), endOf(i) - offsetOf(begin));
                    std::string hoisted(declaration), blank(declaration);
                    for (size_t c = 0; c < declaration.size(); ++c) {
                        bool lineBreak = declaration[c] == '\n' || declaration[c] == '\r';
                        if (lineBreak) hoisted[c] = ' ';
                        if (!lineBreak) blank[c] = ' ';
                    }
                    hoistedAll += hoisted + " ";
                    mReplacements.push_back({offsetOf(begin), declaration.size(), blank});
                }
                begin = i + 1;
            }
            if (!hoistedAll.empty()) mInsertions.push_back({offsetOf(keyword), hoistedAll});
        }
    }

private:
    // Whether the statement [begin, end) declares a texture, sampler or buffer.
    bool isResourceDeclaration(size_t begin, size_t end) const {
        size_t type = isWord(begin, "uniform") ? begin + 1 : begin;
        if (type >= end || mTokens[type].kind != TokenKind::Identifier) return false;
        std::string_view name = mTokens[type].text;
        return name.rfind("sampler", 0) == 0 || name.rfind("Texture", 0) == 0 ||
               name.rfind("SamplerState", 0) == 0 || name.rfind("SamplerComparisonState", 0) == 0 ||
               name.find("Buffer") != std::string_view::npos;
    }
};

}  // namespace

void hoistCbufferResources(RewriteState& state) { CbufferResourceHoistRewrite(state).run(); }

}  // namespace varc::frontend::hlsl
