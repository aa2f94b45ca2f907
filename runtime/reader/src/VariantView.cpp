// SPDX-License-Identifier: Apache-2.0
// One variant of a pass: its keywords and, per stage, the program with SPIR-V and reflection.
#include "varc/reader/VariantView.h"

#include "PackImage.h"
#include "varc/pack/KeyEncoding.h"
#include "varc/pack/PackTables.h"
#include "varc/reader/PassView.h"

namespace varc::reader {

using pack::Chunk;

PassView VariantView::pass() const { return PassView(mImage, mShader, mPass); }

uint32_t VariantView::enumerationIndex() const {
    uint32_t first = mImage->get(Chunk::Passes, mPass, pack::kPassVariantFirst);
    return mImage->get(Chunk::VariantPrograms, first + mSorted, pack::kVariantOrdinal);
}

variants::VariantKey VariantView::key() const {
    uint32_t words = mImage->get(Chunk::Passes, mPass, pack::kPassKeyWords);
    size_t word = mImage->get(Chunk::Passes, mPass, pack::kPassKeyFirst) + size_t{mSorted} * words;
    return pack::loadKey(mImage->raw(Chunk::VariantKeys).data() + 8 * word, words);
}

std::vector<std::string> VariantView::keywords() const { return pass().keywordsOf(key()); }

uint32_t VariantView::programIndex(Stage stage) const {
    uint32_t first = mImage->get(Chunk::Passes, mPass, pack::kPassVariantFirst);
    return mImage->get(Chunk::VariantPrograms, first + mSorted,
                       pack::kVariantProgram + static_cast<uint32_t>(stageIndex(stage)));
}

bool VariantView::hasStage(Stage stage) const { return programIndex(stage) != pack::kNone; }

std::optional<ProgramView> VariantView::program(Stage stage) const {
    uint32_t index = programIndex(stage);
    if (index == pack::kNone) return std::nullopt;
    return ProgramView(mImage, index);
}

Result<std::span<const uint32_t>> VariantView::spirv(Stage stage) const {
    std::optional<ProgramView> stageProgram = program(stage);
    if (!stageProgram) {
        return makeError(ErrorCode::NotFound,
                         describe() + " has no " + stageName(stage) + " program");
    }
    return stageProgram->spirv();
}

pack::PackRenderState VariantView::renderState() const { return pass().renderState(); }

std::string VariantView::describe() const {
    std::string text = pass().describe() + " {";
    std::vector<std::string> names = keywords();
    for (size_t i = 0; i < names.size(); ++i) text += (i ? " " : "") + names[i];
    return text + "}";
}

}  // namespace varc::reader
