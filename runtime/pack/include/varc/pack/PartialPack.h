// SPDX-License-Identifier: Apache-2.0
// Partial packs: what `varc build --shard K/N` writes and `varc merge` joins (docs/PACK_FORMAT.md).
//
// A partial pack is an ordinary pack in layout, with two marks:
//  * its toolchain list ends with the tool kShardTool, version "K/N level=L" (the shard and the
//    zstd level the parts were built for), which Pack::open refuses unless told to accept parts;
//  * the stages of the variants another shard builds (a shard takes whole variants) name a
//    placeholder program: kPlaceholderWords words {kPlaceholderMagic0, kPlaceholderMagic1, stage
//    slot}, never valid SPIR-V (whose first word is 0x07230203), so a placeholder can be neither
//    mistaken for a module nor merged with one.
// Every part holds every shader, pass and variant, so merging takes each variant's program per
// stage from the one part that built it, and merges the programs equal in SPIR-V bytes that
// several parts compiled.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace varc::pack {

inline constexpr std::string_view kShardTool = "varc-shard";
inline constexpr uint32_t kPlaceholderMagic0 = 0x43524156u;  // "VARC" little-endian
inline constexpr uint32_t kPlaceholderMagic1 = 0x54524150u;  // "PART"
inline constexpr size_t kPlaceholderWords = 3;

// The placeholder numbered |number| (distinct numbers give distinct placeholders).
inline std::vector<uint32_t> placeholderSpirv(uint32_t number) {
    return {kPlaceholderMagic0, kPlaceholderMagic1, number};
}

inline bool isPlaceholderSpirv(std::span<const uint32_t> words) {
    return words.size() == kPlaceholderWords && words[0] == kPlaceholderMagic0 &&
           words[1] == kPlaceholderMagic1;
}

}  // namespace varc::pack
