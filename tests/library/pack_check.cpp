// SPDX-License-Identifier: Apache-2.0
// Checks a pack written by `varc build` independently of the compiler: opens it with the runtime's
// reader (full structural and checksum validation), walks every shader, pass and variant, and
// validates each variant's vertex and fragment SPIR-V with SPIRV-Tools (Vulkan 1.0), each
// distinct program once. Prints one line per pass and a final "variants=N programs=M" line that
// build_check.sh compares with `varc variants`.
// Usage: varc_library_pack_check PACK
// Exit: 0 every variant has valid vertex and fragment programs; 1 otherwise; 2 usage or the pack
// does not open.
#include <cstdio>
#include <set>
#include <string>

#include <spirv-tools/libspirv.hpp>

#include "varc/reader/Pack.h"
#include "varc/reader/PassView.h"
#include "varc/reader/VariantView.h"

namespace {

using varc::Stage;

// Validates |view|'s program for |stage| unless already seen; returns false on a missing or
// invalid program, after printing why.
bool checkStage(const varc::reader::VariantView& view, Stage stage, spvtools::SpirvTools& tools,
                std::set<size_t>& validated, std::string& log) {
    auto program = view.program(stage);
    if (!program) {
        std::printf("FAIL: %s has no %s program\n", view.describe().c_str(),
                    varc::stageName(stage));
        return false;
    }
    if (!validated.insert(program->index()).second) return true;
    auto words = program->spirv();
    if (!words) {
        std::printf("FAIL: %s: %s\n", program->describe().c_str(), words.error().detail.c_str());
        return false;
    }
    log.clear();
    if (!tools.Validate(words->data(), words->size())) {
        std::printf("FAIL: %s (%s): invalid SPIR-V:\n%s\n", program->describe().c_str(),
                    view.describe().c_str(), log.c_str());
        return false;
    }
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s PACK\n", argv[0]);
        return 2;
    }
    auto pack = varc::reader::Pack::open(argv[1]);
    if (!pack) {
        std::printf("FAIL: %s\n", pack.error().detail.c_str());
        return 2;
    }
    std::string log;
    spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_0);
    tools.SetMessageConsumer([&log](spv_message_level_t, const char*, const spv_position_t&,
                                    const char* message) { log += std::string(message) + "\n"; });

    std::set<size_t> validated;
    size_t variants = 0;
    bool ok = true;
    for (size_t s = 0; s < pack->shaderCount(); ++s) {
        varc::reader::ShaderView shader = pack->shader(s);
        for (size_t p = 0; p < shader.passCount(); ++p) {
            auto pass = shader.pass(p);
            if (!pass) continue;
            for (size_t v = 0; v < pass->variantCount(); ++v) {
                varc::reader::VariantView view = pass->variant(v);
                ok = checkStage(view, Stage::Vertex, tools, validated, log) && ok;
                ok = checkStage(view, Stage::Fragment, tools, validated, log) && ok;
            }
            variants += pass->variantCount();
            std::printf("%s pass %u: %zu variants\n", std::string(shader.name()).c_str(),
                        pass->index(), pass->variantCount());
        }
    }
    std::printf("variants=%zu programs=%zu\n", variants, validated.size());
    return ok ? 0 : 1;
}
