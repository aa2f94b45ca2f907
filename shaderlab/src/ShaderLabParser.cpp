// SPDX-License-Identifier: Apache-2.0
// Parses ShaderLab text (.shader files) into a ShaderFile.
#include "varc/shaderlab/ShaderLabParser.h"

#include "ShaderParser.h"
#include "lex/Lexer.h"
#include "lex/TokenCursor.h"

namespace varc::shaderlab {
namespace {

// Forwards diagnostics and counts errors, so the parser's result and the sink always agree.
class ErrorCountingSink final : public DiagnosticSink {
public:
    explicit ErrorCountingSink(DiagnosticSink& inner) : mInner(inner) {}
    void report(Diagnostic diagnostic) override {
        if (diagnostic.severity == Severity::Error) ++mErrors;
        mInner.report(std::move(diagnostic));
    }
    size_t errors() const { return mErrors; }

private:
    DiagnosticSink& mInner;
    size_t mErrors = 0;
};

}  // namespace

std::optional<ShaderFile> parseShaderLab(std::string_view text, FileId file, DiagnosticSink& sink) {
    ErrorCountingSink counting(sink);
    Lexer lexer(text, file, counting);
    TokenCursor cursor(lexer, counting);
    ShaderFile shader;
    bool ok = ShaderParser(cursor).parse(shader);
    if (!ok && counting.errors() == 0) {
        // A parse function failed without reporting: a varc bug, but never a silent failure.
        counting.error(cursor.peek().location, "internal error: ShaderLab parse failed silently");
    }
    if (!ok || counting.errors() > 0) return std::nullopt;
    return shader;
}

}  // namespace varc::shaderlab
