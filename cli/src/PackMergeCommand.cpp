// SPDX-License-Identifier: Apache-2.0
// `varc merge`: the partial packs of a sharded build joined into the whole build's pack.
#include <ostream>

#include "varc/cli/PackCommands.h"
#include "varc/driver/PackMerge.h"
#include "varc/packwriter/PackWriter.h"
#include "varc/reader/Pack.h"
#include "varc/reader/PackDecoder.h"

namespace varc::cli {

int runMerge(const MergeOptions& options, std::ostream& out, std::ostream& err) {
    std::vector<driver::PartialPackInput> parts;
    reader::OpenOptions openOptions;
    openOptions.acceptPartial = true;
    for (const std::string& path : options.parts) {
        Result<reader::Pack> pack = reader::Pack::open(path, openOptions);
        if (!pack) {
            err << "varc: error: " << pack.error().detail << "\n";
            return kExitUsage;
        }
        Result<pack::PackContents> contents = reader::decodePack(*pack);
        if (!contents) {
            err << "varc: error: " << path << ": " << contents.error().detail << "\n";
            return kExitUsage;
        }
        parts.push_back({path, std::move(*contents)});
    }
    Result<driver::MergedPack> merged = driver::mergePartialPacks(std::move(parts));
    if (!merged) {
        err << "varc: error: " << merged.error().detail << "\n";
        err << "varc merge: failed; " << options.outputPath << " was not written\n";
        return kExitFailure;
    }
    for (const std::string& error : merged->errors) err << error << "\n";
    if (!merged->errors.empty()) {
        err << "varc merge: failed; " << options.outputPath << " was not written\n";
        return kExitFailure;
    }
    packwriter::PackWriteOptions writeOptions;
    writeOptions.compressionLevel = merged->compressionLevel;
    packwriter::PackWriteStats stats;
    if (Status written =
            packwriter::writePack(options.outputPath, merged->contents, writeOptions, &stats);
        !written) {
        err << "varc: error: " << written.error().detail << "\n";
        return kExitFailure;
    }
    out << "Merged " << options.parts.size() << " parts: " << stats.programs << " programs, "
        << stats.packBytes << " bytes\nwrote " << options.outputPath << "\n";
    return kExitOk;
}

}  // namespace varc::cli
