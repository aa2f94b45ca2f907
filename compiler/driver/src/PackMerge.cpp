// SPDX-License-Identifier: Apache-2.0
// `varc merge`: the parts of a sharded build joined into the pack the whole build writes.
#include "varc/driver/PackMerge.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <optional>
#include <set>

#include "varc/core/HexText.h"
#include "varc/driver/ShardPlan.h"
#include "varc/driver/StageInterfaces.h"
#include "varc/pack/PartialPack.h"

namespace varc::driver {

namespace {

struct PartMark {
    ShardSpec shard;
    int compressionLevel = 19;
};

// The part's "K/N level=L" toolchain entry, removed from |contents|; nullopt when it has none
// or it does not parse.
std::optional<PartMark> takePartMark(pack::PackContents& contents) {
    auto it =
        std::find_if(contents.toolchain.begin(), contents.toolchain.end(),
                     [](const pack::ToolVersion& tool) { return tool.name == pack::kShardTool; });
    if (it == contents.toolchain.end()) return std::nullopt;
    std::string version = it->version;
    contents.toolchain.erase(it);
    size_t space = version.find(" level=");
    if (space == std::string::npos) return std::nullopt;
    std::optional<ShardSpec> shard = parseShardSpec(std::string_view(version).substr(0, space));
    int level = 0;
    if (!shard || std::sscanf(version.c_str() + space + 7, "%d", &level) != 1) return std::nullopt;
    return PartMark{*shard, level};
}

// Equal in everything but which program a variant's stage slot names (present or not counts).
bool sameStructure(const pack::PackContents& a, const pack::PackContents& b) {
    if (a.toolchain != b.toolchain || a.inputsHash != b.inputsHash ||
        a.shaders.size() != b.shaders.size()) {
        return false;
    }
    for (size_t s = 0; s < a.shaders.size(); ++s) {
        const pack::PackShader &x = a.shaders[s], &y = b.shaders[s];
        if (x.name != y.name || x.properties != y.properties || x.passes.size() != y.passes.size())
            return false;
        for (size_t p = 0; p < x.passes.size(); ++p) {
            pack::PackPass xp = x.passes[p], yp = y.passes[p];
            if (xp.variants.size() != yp.variants.size()) return false;
            for (size_t v = 0; v < xp.variants.size(); ++v) {
                for (size_t slot = 0; slot < kStageCount; ++slot) {
                    bool xHas = xp.variants[v].programs[slot] != pack::kNoProgram;
                    bool yHas = yp.variants[v].programs[slot] != pack::kNoProgram;
                    if (xHas != yHas) return false;
                    xp.variants[v].programs[slot] = yp.variants[v].programs[slot] = 0;
                }
            }
            if (xp != yp) return false;
        }
    }
    return true;
}

// Checks that |parts| are shards 1..N of one build, each once. Sorts them by shard.
Status checkShards(std::vector<PartialPackInput>& parts, std::vector<PartMark>& marks) {
    for (size_t i = 0; i < parts.size(); ++i) {
        std::optional<PartMark> mark = takePartMark(parts[i].contents);
        if (!mark) {
            return makeError(ErrorCode::InvalidInput,
                             parts[i].path + ": not a partial pack (built without --shard)");
        }
        marks.push_back(*mark);
    }
    std::vector<size_t> order(parts.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        return marks[a].shard.index < marks[b].shard.index;
    });
    std::vector<PartialPackInput> sorted;
    std::vector<PartMark> sortedMarks;
    for (size_t i : order) {
        sorted.push_back(std::move(parts[i]));
        sortedMarks.push_back(marks[i]);
    }
    parts = std::move(sorted);
    marks = std::move(sortedMarks);
    const uint32_t count = marks[0].shard.count;
    for (size_t i = 0; i < parts.size(); ++i) {
        if (marks[i].shard.count != count ||
            marks[i].compressionLevel != marks[0].compressionLevel) {
            return makeError(ErrorCode::InvalidInput,
                             parts[i].path + ": shard " + marks[i].shard.text() + " (level " +
                                 std::to_string(marks[i].compressionLevel) + ") is not of the " +
                                 "same sharded build as " + parts[0].path + ", shard " +
                                 marks[0].shard.text() + " (level " +
                                 std::to_string(marks[0].compressionLevel) + ")");
        }
        if (i > 0 && marks[i].shard.index == marks[i - 1].shard.index) {
            return makeError(ErrorCode::InvalidInput, parts[i - 1].path + " and " + parts[i].path +
                                                          " are both shard " +
                                                          marks[i].shard.text());
        }
    }
    for (uint32_t k = 1; k <= count; ++k) {
        if (k > parts.size() || marks[k - 1].shard.index != k) {
            return makeError(ErrorCode::InvalidInput, "shard " + ShardSpec{k, count}.text() +
                                                          " is missing: give all " +
                                                          std::to_string(count) + " parts");
        }
    }
    for (size_t i = 1; i < parts.size(); ++i) {
        if (!sameStructure(parts[0].contents, parts[i].contents)) {
            return makeError(ErrorCode::InvalidInput,
                             parts[i].path + ": built from other inputs or options than " +
                                 parts[0].path + " (inputs hash " +
                                 hex64(parts[i].contents.inputsHash) + " vs " +
                                 hex64(parts[0].contents.inputsHash) + ")");
        }
    }
    return Ok{};
}

std::string describeVariant(const pack::PackShader& shader, const pack::PackPass& pass,
                            const pack::PackVariant& variant) {
    std::string keywords;
    for (size_t bit = 0; bit < pass.keywordTable.size(); ++bit) {
        if (!variant.key.test(bit)) continue;
        keywords += (keywords.empty() ? "" : " ") + pass.keywordTable[bit];
    }
    return "shader \"" + shader.name + "\" pass " + std::to_string(pass.index) +
           ", keywords: " + (keywords.empty() ? "<no keywords defined>" : keywords);
}

}  // namespace

Result<MergedPack> mergePartialPacks(std::vector<PartialPackInput> parts) {
    if (parts.empty()) return makeError(ErrorCode::InvalidInput, "no parts to merge");
    std::vector<PartMark> marks;
    if (Status checked = checkShards(parts, marks); !checked) return checked.error();
    MergedPack merged;
    merged.compressionLevel = marks[0].compressionLevel;
    pack::PackContents& out = merged.contents;
    out.toolchain = parts[0].contents.toolchain;
    out.inputsHash = parts[0].contents.inputsHash;
    out.shaders = parts[0].contents.shaders;
    // SPIR-V bytes -> merged program: the whole build interns its programs by their bytes, so a
    // program two parts both compiled (their shares shared a source) is one program, the first
    // used (the writer then renumbers in first-use order).
    std::map<std::vector<uint32_t>, uint32_t> taken;
    for (size_t s = 0; s < out.shaders.size(); ++s) {
        for (size_t p = 0; p < out.shaders[s].passes.size(); ++p) {
            pack::PackPass& pass = out.shaders[s].passes[p];
            for (size_t v = 0; v < pass.variants.size(); ++v) {
                for (size_t slot = 0; slot < kStageCount; ++slot) {
                    uint32_t& program = pass.variants[v].programs[slot];
                    if (program == pack::kNoProgram) continue;
                    std::optional<std::pair<size_t, uint32_t>> source;
                    for (size_t i = 0; i < parts.size() && !source; ++i) {
                        const pack::PackContents& part = parts[i].contents;
                        uint32_t index = part.shaders[s].passes[p].variants[v].programs[slot];
                        if (!pack::isPlaceholderSpirv(part.programs[index].spirv))
                            source = {{i, index}};
                    }
                    if (!source) {
                        return makeError(
                            ErrorCode::InvalidInput,
                            std::string("no part holds the ") +
                                stageName(static_cast<Stage>(slot)) + " program of " +
                                describeVariant(out.shaders[s], pass, pass.variants[v]));
                    }
                    const pack::PackProgram& found =
                        parts[source->first].contents.programs[source->second];
                    auto [it, inserted] =
                        taken.emplace(found.spirv, static_cast<uint32_t>(out.programs.size()));
                    if (inserted) out.programs.push_back(found);
                    program = it->second;
                }
            }
        }
    }
    std::set<std::pair<uint32_t, uint32_t>> checked;
    for (const pack::PackShader& shader : out.shaders) {
        for (const pack::PackPass& pass : shader.passes) {
            checkVariantInterfaces(
                pass.variants, out.programs, checked,
                [&](const pack::PackVariant& variant, Stage producer,
                    const pack::StageVariable& input) {
                    const pack::SourceInfo& where =
                        out.programs[variant.programs[stageIndex(Stage::Fragment)]].source;
                    merged.errors.push_back(where.file + ":" + std::to_string(where.line) +
                                            ":1: error: fragment input '" + input.name +
                                            "' (location " + std::to_string(input.location) + ", " +
                                            input.type + ") is not written by the " +
                                            stageName(producer) + " program in " +
                                            describeVariant(shader, pass, variant));
                });
        }
    }
    return merged;
}

}  // namespace varc::driver
