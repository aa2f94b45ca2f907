// SPDX-License-Identifier: Apache-2.0
// The shader stages of a rasterisation pass: one vocabulary from pragmas to packs to pipelines.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

namespace varc {

// A program stage. The values are the stage slots of a variant and the stage ids stored in
// packs (docs/PACK_FORMAT.md), so they never change.
enum class Stage : uint8_t { Vertex = 0, Fragment = 1, Geometry = 2, Hull = 3, Domain = 4 };
inline constexpr size_t kStageCount = 5;
inline constexpr std::array<Stage, kStageCount> kStages = {
    Stage::Vertex, Stage::Fragment, Stage::Geometry, Stage::Hull, Stage::Domain};

constexpr size_t stageIndex(Stage stage) { return static_cast<size_t>(stage); }

// "vertex", "fragment", "geometry", "hull", "domain": the names of pragmas (`#pragma hull`),
// keyword suffixes (`multi_compile_fragment`), reports and extracted file names.
constexpr const char* stageName(Stage stage) {
    constexpr const char* kNames[kStageCount] = {"vertex", "fragment", "geometry", "hull",
                                                 "domain"};
    return kNames[stageIndex(stage)];
}

// The stage of a slot number; nullopt past the last stage (e.g. a corrupt pack field).
constexpr std::optional<Stage> stageFromIndex(size_t index) {
    if (index >= kStageCount) return std::nullopt;
    return static_cast<Stage>(index);
}

// A set of stages, one bit per Stage: bit stageIndex(s).
using StageMask = uint32_t;
constexpr StageMask stageBit(Stage stage) { return StageMask{1} << stageIndex(stage); }
inline constexpr StageMask kAllStages = (StageMask{1} << kStageCount) - 1;
constexpr bool hasStage(StageMask mask, Stage stage) { return (mask & stageBit(stage)) != 0; }

}  // namespace varc
