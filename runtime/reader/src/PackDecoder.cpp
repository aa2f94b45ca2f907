// SPDX-License-Identifier: Apache-2.0
// Decodes a whole open Pack back into PackContents (for tests, tools and round trips).
#include "varc/reader/PackDecoder.h"

namespace varc::reader {

namespace {

pack::PackPass decodePass(const PassView& view) {
    pack::PackPass pass;
    pass.index = view.index();
    pass.name = view.name();
    pass.lightMode = view.lightMode();
    for (size_t i = 0; i < view.tagCount(); ++i) {
        auto [key, value] = view.tag(i);
        pass.tags.emplace_back(std::string(key), std::string(value));
    }
    pass.state = view.renderState();
    for (size_t i = 0; i < view.keywordCount(); ++i)
        pass.keywordTable.emplace_back(view.keyword(i));
    for (size_t i = 0; i < view.setCount(); ++i) pass.sets.push_back(view.set(i));
    for (size_t e = 0; e < view.variantCount(); ++e) {
        VariantView variant = view.variant(e);
        pack::PackVariant out;
        out.key = variant.key();
        for (Stage stage : kStages) {
            std::optional<ProgramView> program = variant.program(stage);
            if (program) out.programs[stageIndex(stage)] = program->index();
        }
        pass.variants.push_back(out);
    }
    return pass;
}

Result<pack::PackProgram> decodeProgram(const ProgramView& view) {
    Result<std::span<const uint32_t>> words = view.spirv();
    if (!words) return words.error();
    pack::PackProgram program;
    program.stage = view.stage();
    program.entryPoint = view.entryPoint();
    program.spirv.assign(words->begin(), words->end());
    program.reflection = view.reflection();
    program.source = view.source();
    return program;
}

}  // namespace

Result<pack::PackContents> decodePack(const Pack& pack) {
    pack::PackContents contents;
    contents.toolchain = pack.toolchain();
    contents.inputsHash = pack.inputsHash();
    for (size_t s = 0; s < pack.shaderCount(); ++s) {
        ShaderView view = pack.shader(s);
        pack::PackShader shader;
        shader.name = view.name();
        for (size_t p = 0; p < view.passCount(); ++p)
            shader.passes.push_back(decodePass(*view.pass(p)));
        shader.properties = view.properties();
        contents.shaders.push_back(std::move(shader));
    }
    for (size_t i = 0; i < pack.programCount(); ++i) {
        Result<pack::PackProgram> program = decodeProgram(pack.program(i));
        if (!program) return program.error();
        contents.programs.push_back(std::move(*program));
    }
    return contents;
}

}  // namespace varc::reader
