// SPDX-License-Identifier: Apache-2.0
// Encodes shaders, passes, keyword tables, render states and the sorted variant index.
#include <algorithm>
#include <bit>
#include <map>
#include <numeric>

#include "PackEncoders.h"
#include "varc/core/Check.h"
#include "varc/pack/KeyEncoding.h"
#include "varc/pack/PackTables.h"

namespace varc::packwriter {

namespace {

using pack::Chunk;

// Appends |names| to StringLists; returns the first record.
uint32_t encodeStringList(const std::vector<std::string>& names, TableSet& tables) {
    TableBuilder& list = tables.table(Chunk::StringLists);
    uint32_t first = list.size();
    for (const std::string& name : names) list.add({tables.strings().intern(name)});
    return first;
}

uint32_t count(size_t size) {
    VARC_CHECK(size < pack::kNone) << "pack table range too large: " << size;
    return static_cast<uint32_t>(size);
}

// RenderStates records are shared by equal states; |known| maps a record to its index.
uint32_t encodeRenderState(const pack::PackRenderState& state, TableSet& tables,
                           std::map<std::vector<uint32_t>, uint32_t>& known) {
    std::vector<uint32_t> record(pack::kRenderStateFieldCount);
    record[pack::kRsBlendEnabled] = state.blendEnabled ? 1 : 0;
    record[pack::kRsStencilEnabled] = state.stencilEnabled ? 1 : 0;
    pack::forEachStateField(state, [&](uint32_t slot, const auto& field) {
        record[pack::renderStateValueField(slot)] = pack::stateValueBits(field.value);
        record[pack::renderStatePropertyField(slot)] = tables.strings().intern(field.property);
    });
    auto [it, inserted] = known.try_emplace(record, 0);
    if (inserted) it->second = tables.table(Chunk::RenderStates).add(record);
    return it->second;
}

void checkKeywordTable(const pack::PackPass& pass) {
    const auto& table = pass.keywordTable;
    VARC_CHECK(table.size() <= variants::VariantKey::kMaxKeywords)
        << "pass '" << pass.name << "' has " << table.size() << " keywords";
    for (size_t i = 0; i < table.size(); ++i) {
        VARC_CHECK(!table[i].empty()) << "pass '" << pass.name << "' has an empty keyword";
        VARC_CHECK(i == 0 || table[i - 1] < table[i])
            << "keyword table of pass '" << pass.name << "' is not sorted and unique at '"
            << table[i] << "'";
    }
}

// Variant indices of |pass| sorted by key (the order of the binary-searchable index).
std::vector<uint32_t> sortedOrder(const pack::PackPass& pass, uint32_t keyWords) {
    std::vector<uint32_t> order(pass.variants.size());
    std::iota(order.begin(), order.end(), 0u);
    auto keyOf = [&](uint32_t i) { return pass.variants[i].key.words().data(); };
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        return pack::compareKeyWords(keyOf(a), keyOf(b), keyWords) < 0;
    });
    for (size_t i = 1; i < order.size(); ++i) {
        VARC_CHECK(pack::compareKeyWords(keyOf(order[i - 1]), keyOf(order[i]), keyWords) != 0)
            << "pass '" << pass.name << "' has two variants with the same key";
    }
    return order;
}

// VariantKeys, VariantPrograms (sorted order) and VariantOrder for |pass|. Returns the first
// VariantPrograms record; |keyFirst| receives the first key word.
uint32_t encodeVariants(const pack::PackPass& pass, const ProgramTable& programs, TableSet& tables,
                        uint32_t& keyFirst) {
    uint32_t keyWords = pack::keyWordCount(pass.keywordTable.size());
    std::string& keys = tables.raw(Chunk::VariantKeys);
    keyFirst = count(keys.size() / 8);
    TableBuilder& variantPrograms = tables.table(Chunk::VariantPrograms);
    uint32_t first = variantPrograms.size();
    std::vector<uint32_t> order = sortedOrder(pass, keyWords);
    std::vector<uint32_t> position(order.size());
    for (uint32_t sorted = 0; sorted < order.size(); ++sorted) {
        const pack::PackVariant& variant = pass.variants[order[sorted]];
        VARC_CHECK(pack::keyFitsTable(variant.key, pass.keywordTable.size()))
            << "a variant of pass '" << pass.name << "' uses a bit outside its keyword table";
        pack::appendKey(keys, variant.key, keyWords);
        std::array<uint32_t, pack::kVariantProgramFieldCount> record{};
        for (size_t slot = 0; slot < kStageCount; ++slot) {
            record[pack::kVariantProgram + slot] = programs.remap(variant.programs[slot]);
        }
        record[pack::kVariantOrdinal] = order[sorted];
        variantPrograms.add(record);
        position[order[sorted]] = sorted;
    }
    for (uint32_t sorted : position) tables.table(Chunk::VariantOrder).add({sorted});
    return first;
}

uint32_t encodeSets(const pack::PackPass& pass, TableSet& tables) {
    TableBuilder& sets = tables.table(Chunk::KeywordSets);
    uint32_t first = sets.size();
    for (const pack::DeclaredSet& set : pass.sets) {
        uint32_t directive = tables.strings().intern(set.directive);
        uint32_t keywordFirst = encodeStringList(set.keywords, tables);
        sets.add({directive, keywordFirst, count(set.keywords.size())});
    }
    return first;
}

uint32_t encodeTags(const pack::PackPass& pass, TableSet& tables) {
    TableBuilder& tags = tables.table(Chunk::Tags);
    uint32_t first = tags.size();
    for (const auto& [key, value] : pass.tags) {
        tags.add({tables.strings().intern(key), tables.strings().intern(value)});
    }
    return first;
}

void encodePass(const pack::PackPass& pass, const ProgramTable& programs, TableSet& tables,
                std::map<std::vector<uint32_t>, uint32_t>& renderStates) {
    checkKeywordTable(pass);
    std::array<uint32_t, pack::kPassFieldCount> record{};
    record[pack::kPassIndex] = pass.index;
    record[pack::kPassName] = tables.strings().intern(pass.name);
    record[pack::kPassLightMode] = tables.strings().intern(pass.lightMode);
    record[pack::kPassTagFirst] = encodeTags(pass, tables);
    record[pack::kPassTagCount] = count(pass.tags.size());
    record[pack::kPassRenderState] = encodeRenderState(pass.state, tables, renderStates);
    record[pack::kPassKeywordFirst] = encodeStringList(pass.keywordTable, tables);
    record[pack::kPassKeywordCount] = count(pass.keywordTable.size());
    record[pack::kPassSetFirst] = encodeSets(pass, tables);
    record[pack::kPassSetCount] = count(pass.sets.size());
    record[pack::kPassKeyWords] = pack::keyWordCount(pass.keywordTable.size());
    record[pack::kPassVariantFirst] =
        encodeVariants(pass, programs, tables, record[pack::kPassKeyFirst]);
    record[pack::kPassVariantCount] = count(pass.variants.size());
    tables.table(Chunk::Passes).add(record);
}

void encodeShaderNames(const pack::PackContents& contents, TableSet& tables) {
    std::vector<uint32_t> byName(contents.shaders.size());
    std::iota(byName.begin(), byName.end(), 0u);
    std::stable_sort(byName.begin(), byName.end(), [&](uint32_t a, uint32_t b) {
        return contents.shaders[a].name < contents.shaders[b].name;
    });
    for (uint32_t shader : byName) tables.table(Chunk::ShaderNames).add({shader});
}

}  // namespace

void encodeShaders(const pack::PackContents& contents, const ProgramTable& programs,
                   TableSet& tables) {
    for (const pack::ToolVersion& tool : contents.toolchain) {
        tables.table(Chunk::Tools)
            .add({tables.strings().intern(tool.name), tables.strings().intern(tool.version)});
    }
    std::map<std::vector<uint32_t>, uint32_t> renderStates;
    for (const pack::PackShader& shader : contents.shaders) {
        uint32_t name = tables.strings().intern(shader.name);
        uint32_t passFirst = tables.table(Chunk::Passes).size();
        for (const pack::PackPass& pass : shader.passes) {
            encodePass(pass, programs, tables, renderStates);
        }
        uint32_t shaderIndex =
            tables.table(Chunk::Shaders).add({name, passFirst, count(shader.passes.size())});
        for (const pack::ShaderProperty& property : shader.properties) {
            tables.table(Chunk::Properties)
                .add({shaderIndex, tables.strings().intern(property.name),
                      static_cast<uint32_t>(property.kind),
                      std::bit_cast<uint32_t>(property.value[0]),
                      std::bit_cast<uint32_t>(property.value[1]),
                      std::bit_cast<uint32_t>(property.value[2]),
                      std::bit_cast<uint32_t>(property.value[3]),
                      tables.strings().intern(property.texture)});
        }
    }
    encodeShaderNames(contents, tables);
}

}  // namespace varc::packwriter
