// SPDX-License-Identifier: Apache-2.0
// One stage program of an open Pack: SPIR-V (decompressed lazily), reflection, source info.
#include "varc/reader/ProgramView.h"

#include "PackImage.h"
#include "ReflectionDecoder.h"
#include "varc/pack/PackTables.h"

namespace varc::reader {

using pack::Chunk;

uint32_t ProgramView::field(uint32_t field) const {
    return mImage->get(Chunk::Programs, mIndex, field);
}

Stage ProgramView::stage() const { return static_cast<Stage>(field(pack::kProgramStage)); }

std::string_view ProgramView::entryPoint() const {
    return mImage->string(field(pack::kProgramEntry));
}

size_t ProgramView::spirvByteSize() const {
    return mImage->get(Chunk::Blobs, field(pack::kProgramBlob), pack::kBlobRawSize);
}

Result<std::span<const uint32_t>> ProgramView::spirv() const {
    Result<std::span<const uint32_t>> words = mImage->blobWords(field(pack::kProgramBlob));
    if (!words) return makeError(words.error().code, describe() + ": " + words.error().detail);
    return words;
}

pack::ProgramReflection ProgramView::reflection() const {
    return detail::decodeReflection(*mImage, field(pack::kProgramReflection));
}

pack::SourceInfo ProgramView::source() const {
    pack::SourceInfo info;
    info.file = sourceFile();
    info.line = sourceLine();
    uint32_t first = field(pack::kProgramDependencyFirst);
    uint32_t count = field(pack::kProgramDependencyCount);
    for (uint32_t i = 0; i < count; ++i)
        info.dependencies.emplace_back(mImage->listString(first + i));
    return info;
}

std::string_view ProgramView::sourceFile() const {
    return mImage->string(field(pack::kProgramSourceFile));
}

uint32_t ProgramView::sourceLine() const { return field(pack::kProgramSourceLine); }

std::string ProgramView::describe() const {
    return std::string(sourceFile()) + ":" + std::to_string(sourceLine()) + " (" +
           stageName(stage()) + " program '" + std::string(entryPoint()) + "')";
}

}  // namespace varc::reader
