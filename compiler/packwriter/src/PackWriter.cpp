// SPDX-License-Identifier: Apache-2.0
// serializePack() and writePack(): PackContents to the bytes of docs/PACK_FORMAT.md.
#include "varc/packwriter/PackWriter.h"

#include "ChunkAssembler.h"
#include "PackEncoders.h"
#include "ProgramTable.h"
#include "TableSet.h"
#include "varc/core/AtomicFile.h"

namespace varc::packwriter {

std::string serializePack(const pack::PackContents& contents, const PackWriteOptions& options,
                          PackWriteStats* stats) {
    ProgramTable programs(contents);
    TableSet tables;
    PackWriteStats local;
    encodeShaders(contents, programs, tables);
    encodePrograms(programs, options, tables, local);
    std::string bytes = assembleChunks(tables.finish(), contents.inputsHash);
    local.packBytes = bytes.size();
    if (stats) *stats = local;
    return bytes;
}

Status writePack(const std::string& path, const pack::PackContents& contents,
                 const PackWriteOptions& options, PackWriteStats* stats) {
    return writeFileAtomically(path, serializePack(contents, options, stats));
}

}  // namespace varc::packwriter
