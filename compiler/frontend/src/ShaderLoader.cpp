// SPDX-License-Identifier: Apache-2.0
// Loads a .shader file: ShaderLab parse, include expansion and keyword model for every pass.
#include "varc/frontend/ShaderLoader.h"

#include <algorithm>

#include "varc/core/SaturatingMath.h"
#include "varc/frontend/DynamicBranchKeywords.h"
#include "varc/frontend/PassReferences.h"
#include "varc/frontend/SurfacePasses.h"
#include "varc/shaderlab/ShaderLabParser.h"
#include "varc/variants/PragmaParser.h"

namespace varc::frontend {

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

// Unity's CGPROGRAM blocks see HLSLSupport.cginc and UnityShaderVariables.cginc without
// including them (HLSLPROGRAM and GLSLPROGRAM blocks do not): shaders use `fixed4` or `_Time`
// with no #include. varc splices them first, from its built-in folder, as a file of its own.
constexpr std::string_view kImplicitCgIncludes =
    "#include \"HLSLSupport.cginc\"\n#include \"UnityShaderVariables.cginc\"\n";

// The registered file holding kImplicitCgIncludes, beside the built-in includes so they are
// found first; kNoFile without a built-in folder.
FileId implicitCgIncludesFile(const includes::IncludeOptions& options,
                              includes::SourceMap& sourceMap) {
    if (options.builtinDir.empty()) return kNoFile;
    std::string path = includes::joinPath(options.builtinDir, "<CGPROGRAM implicit includes>");
    if (std::optional<FileId> known = sourceMap.find(path)) return *known;
    return sourceMap.addFile(path, std::string(kImplicitCgIncludes));
}

// One root per line of generated |code|, each at |location|: every generated line maps to the
// `#pragma surface` in diagnostics.
void addGeneratedRoots(std::string_view code, SourceLocation location,
                       std::vector<includes::SourceText>& roots) {
    size_t start = 0;
    while (start < code.size()) {
        size_t end = std::min(code.find('\n', start), code.size());
        roots.push_back({std::string(code.substr(start, end - start)) + "\n", location});
        start = end + 1;
    }
}

std::vector<includes::SourceText> passRoots(const shaderlab::Pass& pass, FileId implicitCg,
                                            const includes::SourceMap& sourceMap) {
    std::vector<includes::SourceText> roots;
    if (implicitCg != kNoFile) roots.push_back({sourceMap.contents(implicitCg), {implicitCg, 1, 1}});
    if (pass.generated) addGeneratedRoots(pass.generated->before, pass.generated->location, roots);
    for (const shaderlab::ProgramBlock& block : pass.includeBlocks) {
        roots.push_back({block.text, block.origin});
    }
    roots.push_back({pass.program->text, pass.program->origin});
    if (pass.generated) addGeneratedRoots(pass.generated->after, pass.generated->location, roots);
    return roots;
}

// Whether |expanded| already spliced both files Unity includes implicitly into CG programs.
bool includesImplicitCgFiles(const includes::ExpandedSource& expanded) {
    auto has = [&expanded](std::string_view name) {
        return std::any_of(expanded.dependencies.begin(), expanded.dependencies.end(),
                           [name](const std::string& path) { return path.ends_with(name); });
    };
    return has("/HLSLSupport.cginc") && has("/UnityShaderVariables.cginc");
}

// Whether |roots| hold code (anything but blank lines, comments and preprocessor directives)
// before their first #include. Example: "#pragma vertex v\n#include \"UnityCG.cginc\"\nfixed4 c;"
// -> false; "fixed4 c;\n#include \"UnityCG.cginc\"" -> true.
bool codeBeforeFirstInclude(const std::vector<includes::SourceText>& roots) {
    bool inComment = false;
    for (const includes::SourceText& root : roots) {
        std::string_view text = root.text;
        while (!text.empty()) {
            size_t end = text.find('\n');
            std::string_view line = text.substr(0, end);
            text = end == std::string_view::npos ? std::string_view() : text.substr(end + 1);
            size_t first = line.find_first_not_of(" \t\r\f\v");
            if (first == std::string_view::npos) continue;
            line.remove_prefix(first);
            if (inComment) {
                size_t close = line.find("*/");
                if (close == std::string_view::npos) continue;
                inComment = false;
                line.remove_prefix(close + 2);
                first = line.find_first_not_of(" \t\r\f\v");
                if (first == std::string_view::npos) continue;
                line.remove_prefix(first);
            }
            if (line.starts_with("//")) continue;
            if (line.starts_with("/*")) {
                inComment = line.find("*/", 2) == std::string_view::npos;
                continue;
            }
            if (!line.starts_with("#")) return true;
            line.remove_prefix(1);
            line.remove_prefix(std::min(line.find_first_not_of(" \t"), line.size()));
            if (line.starts_with("include")) return false;
        }
    }
    return false;
}

// The pass's program expanded. Unity splices HLSLSupport.cginc and UnityShaderVariables.cginc
// before every CG program. Most programs include both themselves (through UnityCG.cginc) before
// any code, and are expanded as written: nothing changes for them. One that does not, or that
// has code before its first #include, is expanded again with both spliced first.
std::optional<includes::ExpandedSource> expandPass(const shaderlab::Pass& pass,
                                                   includes::IncludeResolver& resolver,
                                                   const includes::IncludeOptions& options,
                                                   includes::SourceMap& sourceMap,
                                                   DiagnosticSink& sink) {
    bool cg = pass.program->language == shaderlab::ProgramLanguage::Cg && !options.builtinDir.empty();
    DiagnosticList firstTry;
    auto expanded = resolver.expand(passRoots(pass, kNoFile, sourceMap), cg ? firstTry : sink);
    if (!cg || (expanded && includesImplicitCgFiles(*expanded) &&
                !codeBeforeFirstInclude(passRoots(pass, kNoFile, sourceMap)))) {
        for (const Diagnostic& diagnostic : firstTry.diagnostics()) sink.report(diagnostic);
        return expanded;
    }
    FileId implicitCg = implicitCgIncludesFile(options, sourceMap);
    return resolver.expand(passRoots(pass, implicitCg, sourceMap), sink);
}

// |reported|: the locations of dynamic_branch warnings already given for this shader.
bool loadPass(LoadedPass& loaded, includes::IncludeResolver& resolver,
              const includes::IncludeOptions& options, includes::SourceMap& sourceMap,
              std::vector<SourceLocation>& reported, DiagnosticSink& sink) {
    auto expanded = expandPass(*loaded.pass, resolver, options, sourceMap, sink);
    if (!expanded) return false;
    loaded.source = std::move(*expanded);
    auto keywords = variants::parsePragmas(loaded.source.pragmas, sink);
    if (!keywords) return false;
    loaded.keywords = std::move(*keywords);
    // dynamic_branch keywords become uniforms the code tests with `if`; a preprocessor test of
    // one is constant, as in Unity, and gets a warning.
    if (!loaded.keywords.dynamicBranches.empty()) {
        warnPreprocessorTestsOfDynamicBranches(
            loaded.source.text, dynamicBranchKeywords(loaded.keywords), reported, sink);
        loaded.source.text = declareDynamicBranchUniforms(loaded.source.text, loaded.keywords,
                                                          loaded.pass->program->language);
    }
    loaded.space = variants::VariantSpace::build(loaded.keywords, sink);
    return loaded.space.has_value();
}

// The text a surface program is analysed in: its program after the include files the generated
// passes include, with every #include spliced. Expansion errors are reported here once.
std::optional<std::string> surfaceAnalysisText(const shaderlab::Pass& placeholder,
                                               includes::IncludeResolver& resolver,
                                               const includes::IncludeOptions& options,
                                               includes::SourceMap& sourceMap,
                                               DiagnosticSink& sink) {
    shaderlab::Pass pass;
    pass.program = placeholder.surface->block;
    pass.includeBlocks = placeholder.includeBlocks;
    pass.generated = shaderlab::GeneratedCode{
        "#include \"HLSLSupport.cginc\"\n#include \"UnityShaderVariables.cginc\"\n"
        "#include \"UnityCG.cginc\"\n#include \"Lighting.cginc\"\n"
        "#include \"UnityPBSLighting.cginc\"\n",
        "", placeholder.surface->pragma};
    DiagnosticList diagnostics;
    auto expanded = expandPass(pass, resolver, options, sourceMap, diagnostics);
    if (expanded) return std::move(expanded->text);
    for (const Diagnostic& diagnostic : diagnostics.diagnostics()) sink.report(diagnostic);
    return std::nullopt;
}

}  // namespace

uint64_t LoadedPass::variantCount() const {
    return plan ? plan->counts.rules : space->count();
}

void LoadedPass::forEachVariant(
    const std::function<bool(const variants::VariantKey&)>& visit) const {
    if (!plan) {
        space->forEach(visit);
        return;
    }
    for (const variants::VariantKey& key : plan->keys) {
        if (!visit(key)) return;
    }
}

uint64_t LoadedShader::variantCount() const {
    uint64_t total = 0;
    for (const LoadedPass& pass : passes) total = saturatingAdd(total, pass.variantCount());
    return total;
}

std::string describePassOrigin(const shaderlab::PassOrigin& origin) {
    switch (origin.kind) {
    case shaderlab::PassOrigin::Kind::Own: return "";
    case shaderlab::PassOrigin::Kind::UsePass: return "from UsePass of \"" + origin.shader + "\"";
    case shaderlab::PassOrigin::Kind::Fallback: return "from Fallback \"" + origin.shader + "\"";
    }
    return "";
}

std::string describePass(const shaderlab::ShaderFile& shader, const shaderlab::Pass& pass,
                         size_t index) {
    std::string text = "pass " + std::to_string(index);
    if (!pass.name.empty()) text += " \"" + pass.name + "\"";
    std::string details;
    std::string lightMode = pass.lightMode();
    if (!lightMode.empty()) details = "LightMode " + lightMode;
    std::string origin = describePassOrigin(pass.origin);
    if (!origin.empty()) details += (details.empty() ? "" : ", ") + origin;
    if (!details.empty()) text += " (" + details + ")";
    return text + " of shader \"" + shader.name + "\"";
}

std::optional<LoadedShader> loadShader(const std::string& path,
                                       const includes::FileSystem& fileSystem,
                                       includes::SourceMap& sourceMap,
                                       const includes::IncludeOptions& includeOptions,
                                       DiagnosticSink& sink, ShaderCatalog* catalog) {
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
    auto surfaceText = [&](const shaderlab::Pass& placeholder) {
        return surfaceAnalysisText(placeholder, resolver, includeOptions, sourceMap, sink);
    };
    if (!generateSurfacePasses(shader.ast, surfaceText, sink)) return std::nullopt;
    if (catalog) resolvePassReferences(shader.ast, *catalog, sink);

    bool ok = true;
    size_t index = 0;
    std::vector<SourceLocation> reportedDynamicBranchTests;
    for (const shaderlab::SubShader& subShader : shader.ast.subShaders) {
        for (const shaderlab::Pass& pass : subShader.passes) {
            size_t passIndex = index++;
            if (!pass.program) continue;
            LoadedPass loaded;
            loaded.index = passIndex;
            loaded.pass = &pass;
            PassContextSink passSink(sink, pass.location,
                                     describePass(shader.ast, pass, passIndex));
            if (loadPass(loaded, resolver, includeOptions, sourceMap, reportedDynamicBranchTests,
                         passSink)) {
                shader.passes.push_back(std::move(loaded));
            } else {
                ok = false;
            }
        }
    }
    if (!ok) return std::nullopt;
    return shader;
}

}  // namespace varc::frontend
