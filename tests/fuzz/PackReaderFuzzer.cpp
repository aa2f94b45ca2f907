// SPDX-License-Identifier: Apache-2.0
// libFuzzer target for the pack reader: any bytes must give a Pack or an Error, never a crash.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "varc/reader/Pack.h"
#include "varc/reader/PackDecoder.h"
#include "varc/reader/PassView.h"

namespace {

using varc::reader::Pack;

// Uses every accessor of an accepted pack, so that a structural hole shows up as a crash.
void exercise(const Pack& pack) {
    for (size_t s = 0; s < pack.shaderCount(); ++s) {
        varc::reader::ShaderView shader = pack.shader(s);
        (void)pack.findShader(shader.name());
        (void)shader.pass("ForwardBase");
        for (size_t p = 0; p < shader.passCount(); ++p) {
            varc::reader::PassView pass = *shader.pass(p);
            (void)pass.renderState();
            (void)pass.describe();
            for (auto policy :
                 {varc::variants::SelectionPolicy::Exact, varc::variants::SelectionPolicy::Closest,
                  varc::variants::SelectionPolicy::First,
                  varc::variants::SelectionPolicy::Strict}) {
                (void)pass.lookup(std::vector<std::string>{"DIRECTIONAL", "SPOT"}, policy);
                (void)pass.lookup(varc::variants::LightDescription{}, policy);
            }
            for (size_t v = 0; v < pass.variantCount(); ++v) {
                varc::reader::VariantView variant = pass.variant(v);
                (void)variant.describe();
                (void)variant.spirv(varc::Stage::Vertex);
            }
        }
    }
    for (size_t i = 0; i < pack.programCount(); ++i) (void)pack.program(i).describe();
    (void)varc::reader::decodePack(pack);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(data), size);
    // The production path: checksums make almost every mutation fail early, cleanly.
    (void)Pack::fromBytes(bytes);
    // Without checksums mutations reach the structural checks and, when accepted, the accessors.
    varc::Result<Pack> pack = Pack::fromBytes(bytes, {.verifyChecksums = false});
    if (pack.ok()) exercise(*pack);
    return 0;
}
