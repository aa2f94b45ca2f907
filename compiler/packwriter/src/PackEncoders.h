// SPDX-License-Identifier: Apache-2.0
// The encoding steps of serializePack(): shaders and passes, then programs and blobs.
#pragma once

#include "ProgramTable.h"
#include "TableSet.h"
#include "varc/pack/PackModel.h"
#include "varc/packwriter/PackWriter.h"

namespace varc::packwriter {

// Fills Tools, Shaders, ShaderNames, Passes, Tags, StringLists (keyword tables and sets),
// KeywordSets, RenderStates, VariantKeys, VariantPrograms and VariantOrder. Aborts through
// VARC_CHECK on malformed passes (see serializePack()).
void encodeShaders(const pack::PackContents& contents, const ProgramTable& programs,
                   TableSet& tables);

// Fills Programs, Reflections and the reflection tables, Blobs, BlobData and Dictionary.
void encodePrograms(const ProgramTable& programs, const PackWriteOptions& options, TableSet& tables,
                    PackWriteStats& stats);

}  // namespace varc::packwriter
