// SPDX-License-Identifier: Apache-2.0
// Loads a .shader file: ShaderLab parse, include expansion and keyword model for every pass.
#include "varc/frontend/ShaderLoader.h"

#include "varc/core/SaturatingMath.h"
#include "varc/shaderlab/ShaderLabParser.h"
#include "varc/variants/PragmaParser.h"

namespace varc::compiler {

namespace {

// Forwards diagnostics to |inner|, appending a note that names the pass being loaded.
class PassContextSink final : public DiagnosticSink {
public:
    PassContextSink(DiagnosticSink& inner, SourceLocation passLocation, std::string description)
        : mInner(inner), mPassLocation(passLocation), mDescription(std::move(description)) {}

    void report(Diagnostic diagnostic) override {
        if (diagnostic.severity != Severity::Note) {
            diagnostic.notes.push_back({mPassLocation, "while loading " + mDescription});
        }
        mInner.report(std::move(diagnostic));
    }

private:
    DiagnosticSink& mInner;
    SourceLocation mPassLocation;
    std::string mDescription;
};

std::vector<includes::SourceText> passRoots(const shaderlab::Pass& pass) {
    std::vector<includes::SourceText> roots;
    for (const shaderlab::ProgramBlock& block : pass.includeBlocks) {
        roots.push_back({block.text, block.origin});
    }
    roots.push_back({pass.program->text, pass.program->origin});
    return roots;
}

bool loadPass(LoadedPass& loaded, includes::IncludeResolver& resolver, DiagnosticSink& sink) {
    auto expanded = resolver.expand(passRoots(*loaded.pass), sink);
    if (!expanded) return false;
    loaded.source = std::move(*expanded);
    auto keywords = variants::parsePragmas(loaded.source.pragmas, sink);
    if (!keywords) return false;
    loaded.keywords = std::move(*keywords);
    loaded.space = variants::VariantSpace::build(loaded.keywords, sink);
    return loaded.space.has_value();
}

}  // namespace

uint64_t LoadedShader::variantCount() const {
    uint64_t total = 0;
    for (const LoadedPass& pass : passes) {
        total = saturatingAdd(total, pass.space->count());
    }
    return total;
}

std::string describePass(const shaderlab::ShaderFile& shader, const shaderlab::Pass& pass,
                         size_t index) {
    std::string text = "pass " + std::to_string(index);
    if (!pass.name.empty()) text += " \"" + pass.name + "\"";
    std::string lightMode = pass.lightMode();
    if (!lightMode.empty()) text += " (LightMode " + lightMode + ")";
    return text + " of shader \"" + shader.name + "\"";
}

std::optional<LoadedShader> loadShader(const std::string& path,
                                       const includes::FileSystem& fileSystem,
                                       includes::SourceMap& sourceMap,
                                       const includes::IncludeOptions& includeOptions,
                                       DiagnosticSink& sink) {
    std::optional<std::string> text = fileSystem.read(path);
    if (!text) {
        sink.error({}, "cannot read shader file '" + path + "'");
        return std::nullopt;
    }
    LoadedShader shader;
    shader.path = path;
    shader.file = sourceMap.addFile(path, *text);
    auto ast = shaderlab::parseShaderLab(sourceMap.contents(shader.file), shader.file, sink);
    if (!ast) return std::nullopt;
    shader.ast = std::move(*ast);

    includes::IncludeResolver resolver(fileSystem, sourceMap, includeOptions);
    bool ok = true;
    size_t index = 0;
    for (const shaderlab::SubShader& subShader : shader.ast.subShaders) {
        for (const shaderlab::Pass& pass : subShader.passes) {
            size_t passIndex = index++;
            if (!pass.program) continue;
            LoadedPass loaded;
            loaded.index = passIndex;
            loaded.pass = &pass;
            PassContextSink passSink(sink, pass.location,
                                     describePass(shader.ast, pass, passIndex));
            if (loadPass(loaded, resolver, passSink)) {
                shader.passes.push_back(std::move(loaded));
            } else {
                ok = false;
            }
        }
    }
    if (!ok) return std::nullopt;
    return shader;
}

}  // namespace varc::compiler
