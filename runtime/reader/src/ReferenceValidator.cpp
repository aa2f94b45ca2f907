// SPDX-License-Identifier: Apache-2.0
// Cross-table checks of a pack: strings, name index, keyword tables, variant index, blobs.
#include <zstd.h>

#include <array>
#include <string>
#include <vector>

#include "PackImage.h"
#include "PackValidator.h"
#include "varc/pack/KeyEncoding.h"
#include "varc/pack/PackTables.h"

namespace varc::reader::detail {

namespace {

using pack::Chunk;

Error corrupt(const std::string& detail) {
    return makeError(ErrorCode::InvalidInput, "corrupt pack: " + detail);
}

Status validateStrings(const PackImage& image) {
    uint64_t size = image.raw(Chunk::StringBytes).size();
    for (uint32_t id = 0; id < image.count(Chunk::Strings); ++id) {
        uint64_t offset = image.get(Chunk::Strings, id, pack::kStringOffset);
        uint64_t length = image.get(Chunk::Strings, id, pack::kStringLength);
        if (offset + length > size) return corrupt("string " + std::to_string(id) + " overflows");
    }
    return Ok{};
}

// ShaderNames lists every shader once, sorted by name (ties in any order).
Status validateShaderNames(const PackImage& image) {
    uint32_t shaders = image.count(Chunk::Shaders);
    if (image.count(Chunk::ShaderNames) != shaders) return corrupt("shader name index size");
    std::vector<bool> seen(shaders);
    for (uint32_t i = 0; i < shaders; ++i) {
        uint32_t shader = image.get(Chunk::ShaderNames, i, pack::kShaderNameShader);
        if (seen[shader]) return corrupt("shader name index repeats a shader");
        seen[shader] = true;
        if (i == 0) continue;
        uint32_t previous = image.get(Chunk::ShaderNames, i - 1, pack::kShaderNameShader);
        if (image.string(image.get(Chunk::Shaders, shader, pack::kShaderName)) <
            image.string(image.get(Chunk::Shaders, previous, pack::kShaderName))) {
            return corrupt("shader name index is not sorted");
        }
    }
    return Ok{};
}

Status validateKeywordTable(const PackImage& image, uint32_t pass) {
    uint32_t first = image.get(Chunk::Passes, pass, pack::kPassKeywordFirst);
    uint32_t count = image.get(Chunk::Passes, pass, pack::kPassKeywordCount);
    if (count > variants::VariantKey::kMaxKeywords ||
        image.get(Chunk::Passes, pass, pack::kPassKeyWords) != pack::keyWordCount(count)) {
        return corrupt("pass " + std::to_string(pass) + " keyword table size");
    }
    for (uint32_t i = 0; i < count; ++i) {
        std::string_view name = image.listString(first + i);
        if (name.empty() || (i > 0 && !(image.listString(first + i - 1) < name))) {
            return corrupt("pass " + std::to_string(pass) + " keyword table is not sorted");
        }
    }
    return Ok{};
}

// The common case (at most 64 keywords), kept tight: it runs over every variant at open.
Status validateOneWordKeys(const std::byte* keys, uint64_t count, uint32_t keywords,
                           uint32_t pass) {
    uint64_t allowed = pack::allowedBits(keywords, 0);
    uint64_t previous = 0;
    for (uint64_t v = 0; v < count; ++v) {
        uint64_t key = pack::loadU64(keys + 8 * v);
        if ((key & ~allowed) != 0 || (v > 0 && key <= previous)) {
            return corrupt("pass " + std::to_string(pass) + " keys unsorted or outside the table");
        }
        previous = key;
    }
    return Ok{};
}

// Keys inside VariantKeys, strictly increasing (so binary search finds each exactly once) and
// using only bits of the keyword table.
Status validateKeys(const PackImage& image, uint32_t pass) {
    uint32_t words = image.get(Chunk::Passes, pass, pack::kPassKeyWords);
    uint64_t keyFirst = image.get(Chunk::Passes, pass, pack::kPassKeyFirst);
    uint64_t count = image.get(Chunk::Passes, pass, pack::kPassVariantCount);
    uint32_t keywords = image.get(Chunk::Passes, pass, pack::kPassKeywordCount);
    if (keyFirst + count * words > image.raw(Chunk::VariantKeys).size() / 8) {
        return corrupt("pass " + std::to_string(pass) + " keys overflow VKEY");
    }
    const std::byte* keys = image.raw(Chunk::VariantKeys).data() + 8 * keyFirst;
    if (words == 1) return validateOneWordKeys(keys, count, keywords, pass);
    std::array<uint64_t, pack::kMaxKeyWords> previous{}, current{};
    for (uint64_t v = 0; v < count; ++v) {
        for (uint32_t w = 0; w < words; ++w) {
            current[w] = pack::loadU64(keys + 8 * (v * words + w));
            if ((current[w] & ~pack::allowedBits(keywords, w)) != 0) {
                return corrupt("pass " + std::to_string(pass) + " key outside its keyword table");
            }
        }
        if (v > 0 && pack::compareKeyWords(previous.data(), current.data(), words) >= 0) {
            return corrupt("pass " + std::to_string(pass) + " keys are not strictly sorted");
        }
        previous = current;
    }
    return Ok{};
}

// VariantOrder maps enumeration index -> sorted position and each VariantPrograms ordinal maps
// back; checking order[ordinal[s]] == s for every s proves both are permutations. |stages|
// holds each program's stage.
Status validateVariants(const PackImage& image, uint32_t pass, const std::vector<uint8_t>& stages) {
    uint32_t first = image.get(Chunk::Passes, pass, pack::kPassVariantFirst);
    uint32_t count = image.get(Chunk::Passes, pass, pack::kPassVariantCount);
    const TableView& programs = image.table(Chunk::VariantPrograms);
    for (uint32_t s = 0; s < count; ++s) {
        uint32_t ordinal = programs.get(first + s, pack::kVariantOrdinal);
        if (ordinal >= count ||
            image.get(Chunk::VariantOrder, first + ordinal, pack::kOrderPosition) != s) {
            return corrupt("pass " + std::to_string(pass) + " variant order");
        }
        for (uint32_t slot = 0; slot < kStageCount; ++slot) {
            uint32_t program = programs.get(first + s, pack::kVariantProgram + slot);
            if (program != pack::kNone && stages[program] != slot) {
                return corrupt("program " + std::to_string(program) + " in the wrong stage slot");
            }
        }
    }
    return Ok{};
}

Status validatePasses(const PackImage& image) {
    if (image.count(Chunk::VariantOrder) != image.count(Chunk::VariantPrograms)) {
        return corrupt("VORD and VPRG differ in size");
    }
    std::vector<uint8_t> stages(image.count(Chunk::Programs));
    for (uint32_t p = 0; p < stages.size(); ++p) {
        stages[p] = static_cast<uint8_t>(image.get(Chunk::Programs, p, pack::kProgramStage));
    }
    for (uint32_t pass = 0; pass < image.count(Chunk::Passes); ++pass) {
        if (Status s = validateKeywordTable(image, pass); !s) return s;
        if (Status s = validateKeys(image, pass); !s) return s;
        if (Status s = validateVariants(image, pass, stages); !s) return s;
    }
    return Ok{};
}

Status validateBlob(const PackImage& image, uint32_t blob) {
    auto codec = static_cast<pack::BlobCodec>(image.get(Chunk::Blobs, blob, pack::kBlobCodecField));
    uint64_t offset = image.get(Chunk::Blobs, blob, pack::kBlobOffset);
    uint64_t size = image.get(Chunk::Blobs, blob, pack::kBlobSize);
    uint32_t rawSize = image.get(Chunk::Blobs, blob, pack::kBlobRawSize);
    std::span<const std::byte> data = image.raw(Chunk::BlobData);
    std::string name = "blob " + std::to_string(blob);
    if (offset % pack::kBlobAlignment != 0 || offset + size > data.size()) {
        return corrupt(name + " lies outside BDAT");
    }
    if (rawSize == 0 || rawSize % 4 != 0 || rawSize > pack::kMaxBlobBytes) {
        return corrupt(name + " has a bad size");
    }
    if (codec == pack::BlobCodec::Stored) {
        return size == rawSize ? Status(Ok{}) : Status(corrupt(name + " has a bad stored size"));
    }
    if (codec == pack::BlobCodec::ZstdDictionary && image.raw(Chunk::Dictionary).empty()) {
        return corrupt(name + " needs the missing dictionary");
    }
    if (ZSTD_getFrameContentSize(data.data() + offset, size) != rawSize) {
        return corrupt(name + " is not a zstd frame of its recorded size");
    }
    return Ok{};
}

}  // namespace

Status validateReferences(const PackImage& image) {
    if (Status s = validateStrings(image); !s) return s;
    if (Status s = validateShaderNames(image); !s) return s;
    if (Status s = validatePasses(image); !s) return s;
    for (uint32_t blob = 0; blob < image.count(Chunk::Blobs); ++blob) {
        if (Status s = validateBlob(image, blob); !s) return s;
    }
    return Ok{};
}

}  // namespace varc::reader::detail
