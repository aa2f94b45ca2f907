// SPDX-License-Identifier: Apache-2.0
// Merges equal programs and renumbers them in first-use order, so the pack is deterministic.
#include "ProgramTable.h"

#include <xxhash.h>

#include "varc/core/Check.h"
#include "varc/pack/PackFormat.h"

namespace varc::packwriter {

namespace {

uint64_t contentHash(const pack::PackProgram& program) {
    uint64_t seed = XXH3_64bits(program.entryPoint.data(), program.entryPoint.size());
    seed ^= static_cast<uint64_t>(program.stage) * 0x9e3779b97f4a7c15ull;
    return XXH3_64bits_withSeed(program.spirv.data(), program.spirv.size() * sizeof(uint32_t),
                                seed);
}

bool sameContent(const pack::PackProgram& a, const pack::PackProgram& b) {
    return a.stage == b.stage && a.entryPoint == b.entryPoint && a.spirv == b.spirv;
}

}  // namespace

ProgramTable::ProgramTable(const pack::PackContents& contents)
    : mRemap(contents.programs.size(), pack::kNoProgram) {
    for (const pack::PackShader& shader : contents.shaders) {
        for (const pack::PackPass& pass : shader.passes) {
            for (const pack::PackVariant& variant : pass.variants) {
                for (size_t slot = 0; slot < kStageCount; ++slot) {
                    if (variant.programs[slot] != pack::kNoProgram) {
                        use(contents, variant.programs[slot], slot);
                    }
                }
            }
        }
    }
}

uint32_t ProgramTable::remap(uint32_t original) const {
    if (original == pack::kNoProgram) return pack::kNoProgram;
    VARC_CHECK(original < mRemap.size()) << "program index " << original << " out of range";
    return mRemap[original];
}

uint32_t ProgramTable::use(const pack::PackContents& contents, uint32_t original, size_t slot) {
    VARC_CHECK(original < contents.programs.size())
        << "variant uses program " << original << " of " << contents.programs.size();
    if (mRemap[original] != pack::kNoProgram) return mRemap[original];
    const pack::PackProgram& program = contents.programs[original];
    VARC_CHECK(stageIndex(program.stage) == slot)
        << "program " << original << " (" << stageName(program.stage) << ") is used in stage slot "
        << slot;
    VARC_CHECK(!program.spirv.empty() && program.spirv.size() <= pack::kMaxBlobBytes / 4)
        << "program " << original << " has " << program.spirv.size() << " SPIR-V words";
    std::vector<uint32_t>& candidates = mByHash[contentHash(program)];
    for (uint32_t index : candidates) {
        if (sameContent(*mPrograms[index], program)) return mRemap[original] = index;
    }
    auto index = static_cast<uint32_t>(mPrograms.size());
    mPrograms.push_back(&program);
    candidates.push_back(index);
    return mRemap[original] = index;
}

}  // namespace varc::packwriter
