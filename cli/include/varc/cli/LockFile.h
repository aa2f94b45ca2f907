// SPDX-License-Identifier: Apache-2.0
// The variant-count lock file: what `varc lock` writes and `varc check` compares against.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "varc/core/Result.h"
#include "varc/frontend/ShaderLoader.h"

namespace varc::cli {

// One declared keyword set, as the lock records it: "multi_compile" + {"_", "VERTEXLIGHT_ON"}.
struct LockedSet {
    std::string directive;
    std::vector<std::string> keywords;  // "_" for the no-keyword entry
    friend bool operator==(const LockedSet&, const LockedSet&) = default;
};

// Unity's staged counts when a project chose the variants (--project): declared -> materials
// and collections -> Graphics Settings stripping -> the user's strip rules (= variants).
struct LockedStages {
    uint64_t declared = 0, materials = 0, settings = 0, rules = 0;
    friend bool operator==(const LockedStages&, const LockedStages&) = default;
};

struct LockedPass {
    size_t index = 0;
    std::string name;
    std::string lightMode;
    uint64_t variants = 0;              // what ships (with a project: stages->rules)
    std::optional<LockedStages> stages;  // with a project only
    std::vector<LockedSet> sets;
    std::vector<std::string> skipped;  // skip_variants keywords, sorted
};

struct LockedShader {
    std::string name;  // the key: shaders are matched by name, so files may move
    std::string file;  // relative to the lock file's directory, for readers
    uint64_t variants = 0;
    std::vector<LockedPass> passes;
};

// Lock file format, version 1 (JSON, stable key order, shaders sorted by name):
//   {"version":1,"shaders":[{"name":"Custom/X","file":"shaders/x.shader","variants":7,
//     "passes":[{"index":0,"name":"","lightmode":"ForwardBase","variants":2,
//       "sets":[{"directive":"multi_compile","keywords":["_","VERTEXLIGHT_ON"]}],
//       "skipped":[]}]}]}
// With --project each pass also has "stages":{"declared":D,"materials":M,"settings":S,"rules":R}
// (optional, so version 1 files without it still read).
struct LockFile {
    static constexpr int kVersion = 1;
    std::vector<LockedShader> shaders;
};

// Records |shaders|; file paths are made relative to |lockDirectory|.
LockFile makeLock(const std::vector<frontend::LoadedShader>& shaders,
                  const std::string& lockDirectory);
LockedPass makeLockedPass(const frontend::LoadedPass& pass);

std::string serializeLock(const LockFile& lock);
// Rejects malformed JSON, a missing or newer version, and wrongly typed fields, naming |path|.
Result<LockFile> parseLock(const std::string& text, const std::string& path);

}  // namespace varc::cli
