// SPDX-License-Identifier: Apache-2.0
// BuildManifest: what `varc build --direct` records about a build so a later one can reuse its
// pack.
//
// ccache's direct mode for packs: a manifest is stored in the cache under the build's key (the
// tool, the options, the inputs and their digests; DirectMode.h) and lists every question the
// build asked the file system with the answer it got: each file read with the digest of its bytes
// (or "absent"), each "is this a file?" probe of the include search (so an include created
// earlier on the search path, which would now shadow the one read, is seen), and each folder
// listing. When every answer still holds, the build's output is the pack the manifest names,
// stored in the cache under the digest of its bytes.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "varc/includes/FileSystem.h"

namespace varc::cli {

enum class FileQueryKind { Read, IsFile, List };

// One question asked of the file system and its answer: for Read the content digest or "-" when
// the file could not be read, for IsFile "1" or "0", for List the digest of the sorted names.
struct FileQuery {
    FileQueryKind kind = FileQueryKind::Read;
    std::string path;
    std::string answer;
    bool operator==(const FileQuery&) const = default;
};

struct BuildManifest {
    std::string key;                        // 32 hex digits: the entry's own key
    std::string packDigest;                 // contentDigest() of the pack's bytes
    uint64_t packBytes = 0;                 // their count
    std::vector<std::string> dependencies;  // what --depfile lists, in order
    std::vector<FileQuery> queries;         // in the order first asked, each once
    bool operator==(const BuildManifest&) const = default;
};

// XXH3-128 of |bytes| as 32 lowercase hex digits.
std::string contentDigest(std::string_view bytes);

// The answer |fileSystem| gives now to a |kind| question about |path| (see FileQuery).
std::string answerQuery(const includes::FileSystem& fileSystem, FileQueryKind kind,
                        const std::string& path);

// Line-based text ending in an XXH64 checksum line, e.g.
//   varc-manifest 1 / key 0123...ef / pack 89ab...01 40960 / dep a.shader /
//   read 4567...89 inc/Light.cginc / isfile 0 inc/Shadow.cginc / list 0123...45 builtin / sum ...
// nullopt when a path holds a line break (such a build is not recorded).
std::optional<std::string> serializeManifest(const BuildManifest& manifest);

// The manifest |text| holds, or nullopt when it is damaged in any way (truncated, altered, a
// checksum that does not match) or was written for a key other than |expectedKey|.
std::optional<BuildManifest> parseManifest(std::string_view text, std::string_view expectedKey);

// The first query |fileSystem| now answers differently (its path), or nullopt when all still
// hold, so the recorded build's pack is this build's pack.
std::optional<std::string> firstChangedQuery(const BuildManifest& manifest,
                                             const includes::FileSystem& fileSystem);

}  // namespace varc::cli
