// SPDX-License-Identifier: Apache-2.0
// Merges equal programs and renumbers them in first-use order, so the pack is deterministic.
#pragma once

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "varc/pack/PackModel.h"

namespace varc::packwriter {

class ProgramTable {
public:
    // Walks shaders, passes, variants (enumeration order) and stage slots; the first use of a
    // program (by content: stage, entry point, SPIR-V) gets the next index. Aborts through
    // VARC_CHECK on an index out of range or a program in the wrong stage slot.
    explicit ProgramTable(const pack::PackContents& contents);

    // The pack index of |contents.programs[original]|, or kNoProgram for kNoProgram.
    uint32_t remap(uint32_t original) const;

    // The distinct programs in pack order (pointers into the contents given).
    const std::vector<const pack::PackProgram*>& programs() const { return mPrograms; }

private:
    uint32_t use(const pack::PackContents& contents, uint32_t original, size_t slot);

    std::vector<uint32_t> mRemap;  // per original index; kNoProgram until first use
    std::vector<const pack::PackProgram*> mPrograms;
    std::unordered_map<uint64_t, std::vector<uint32_t>> mByHash;  // content hash -> pack indices
};

}  // namespace varc::packwriter
