// SPDX-License-Identifier: Apache-2.0
// Encodes programs, their reflection and source info, and the deduplicated, compressed blobs.
#include <xxhash.h>

#include <map>
#include <unordered_map>

#include "BlobCompressor.h"
#include "PackEncoders.h"
#include "varc/core/Check.h"
#include "varc/pack/LittleEndian.h"
#include "varc/pack/PackTables.h"

namespace varc::packwriter {

namespace {

using pack::Chunk;

uint32_t count(size_t size) {
    VARC_CHECK(size < pack::kNone) << "pack table range too large: " << size;
    return static_cast<uint32_t>(size);
}

// Each encode* below appends one program's list as a run; identical lists (the same UnityPerDraw
// block in every program, say) share one run (TableBuilder::addRun).
uint32_t encodeMembers(const std::vector<pack::BlockMember>& members, TableSet& tables) {
    std::vector<uint32_t> fields;
    for (const pack::BlockMember& member : members) {
        fields.insert(fields.end(), {tables.strings().intern(member.name), member.offset,
                                     member.size, tables.strings().intern(member.type),
                                     member.arrayCount, member.rowMajor ? 1u : 0u});
    }
    return tables.table(Chunk::BlockMembers).addRun(fields);
}

// Uniform blocks and push-constant blocks share the UniformBlocks table.
template <typename Block>
uint32_t encodeBlocks(const std::vector<Block>& blocks, TableSet& tables) {
    std::vector<uint32_t> memberFirsts;
    for (const Block& block : blocks) memberFirsts.push_back(encodeMembers(block.members, tables));
    std::vector<uint32_t> fields;
    for (size_t i = 0; i < blocks.size(); ++i) {
        const Block& block = blocks[i];
        uint32_t set = 0, binding = 0;
        if constexpr (std::is_same_v<Block, pack::UniformBlock>) {
            set = block.set;
            binding = block.binding;
        }
        fields.insert(fields.end(), {tables.strings().intern(block.name), set, binding, block.size,
                                     memberFirsts[i], count(block.members.size())});
    }
    return tables.table(Chunk::UniformBlocks).addRun(fields);
}

uint32_t encodeResources(const std::vector<pack::ResourceBinding>& resources, TableSet& tables) {
    std::vector<uint32_t> fields;
    for (const pack::ResourceBinding& r : resources) {
        fields.insert(fields.end(), {tables.strings().intern(r.name), static_cast<uint32_t>(r.kind),
                                     static_cast<uint32_t>(r.dim), r.set, r.binding, r.arraySize,
                                     r.multisampled ? 1u : 0u});
    }
    return tables.table(Chunk::Resources).addRun(fields);
}

uint32_t encodeVertexInputs(const std::vector<pack::VertexInput>& inputs, TableSet& tables) {
    std::vector<uint32_t> fields;
    for (const pack::VertexInput& input : inputs) {
        fields.insert(fields.end(),
                      {tables.strings().intern(input.name), tables.strings().intern(input.semantic),
                       input.location, tables.strings().intern(input.type)});
    }
    return tables.table(Chunk::VertexInputs).addRun(fields);
}

uint32_t encodeStageVariables(const std::vector<pack::StageVariable>& vars, TableSet& tables) {
    std::vector<uint32_t> fields;
    for (const pack::StageVariable& var : vars) {
        fields.insert(fields.end(), {tables.strings().intern(var.name), var.location,
                                     tables.strings().intern(var.type)});
    }
    return tables.table(Chunk::StageVariables).addRun(fields);
}

uint32_t encodeReflection(const pack::ProgramReflection& reflection, TableSet& tables) {
    std::array<uint32_t, pack::kReflectionFieldCount> record{};
    record[pack::kReflBlockFirst] = encodeBlocks(reflection.uniformBlocks, tables);
    record[pack::kReflBlockCount] = count(reflection.uniformBlocks.size());
    record[pack::kReflResourceFirst] = encodeResources(reflection.resources, tables);
    record[pack::kReflResourceCount] = count(reflection.resources.size());
    record[pack::kReflVertexInputFirst] = encodeVertexInputs(reflection.vertexInputs, tables);
    record[pack::kReflVertexInputCount] = count(reflection.vertexInputs.size());
    record[pack::kReflInputFirst] = encodeStageVariables(reflection.inputs, tables);
    record[pack::kReflInputCount] = count(reflection.inputs.size());
    record[pack::kReflOutputFirst] = encodeStageVariables(reflection.outputs, tables);
    record[pack::kReflOutputCount] = count(reflection.outputs.size());
    record[pack::kReflPushFirst] = encodeBlocks(reflection.pushConstants, tables);
    record[pack::kReflPushCount] = count(reflection.pushConstants.size());
    return tables.table(Chunk::Reflections).add(record);
}

std::string spirvBytes(const std::vector<uint32_t>& spirv) {
    std::string bytes;
    bytes.reserve(spirv.size() * 4);
    for (uint32_t word : spirv) pack::appendU32(bytes, word);
    return bytes;
}

// Distinct SPIR-V modules in first-use order; |blobOf[i]| is program i's blob.
std::vector<std::string> collectBlobs(const ProgramTable& programs, std::vector<uint32_t>& blobOf) {
    std::vector<std::string> blobs;
    std::unordered_map<uint64_t, std::vector<uint32_t>> byHash;
    for (const pack::PackProgram* program : programs.programs()) {
        std::string bytes = spirvBytes(program->spirv);
        std::vector<uint32_t>& candidates = byHash[XXH3_64bits(bytes.data(), bytes.size())];
        uint32_t found = pack::kNone;
        for (uint32_t index : candidates) {
            if (blobs[index] == bytes) found = index;
        }
        if (found == pack::kNone) {
            found = count(blobs.size());
            candidates.push_back(found);
            blobs.push_back(std::move(bytes));
        }
        blobOf.push_back(found);
    }
    return blobs;
}

// Programs with equal reflection (common: variants that differ only in code) share a record.
class ReflectionTable {
public:
    uint32_t encode(const pack::ProgramReflection& reflection, TableSet& tables) {
        auto [it, inserted] = mKnown.try_emplace(&reflection, 0);
        if (inserted) it->second = encodeReflection(reflection, tables);
        return it->second;
    }

private:
    struct Less {
        bool operator()(const pack::ProgramReflection* a, const pack::ProgramReflection* b) const {
            return *a < *b;
        }
    };
    std::map<const pack::ProgramReflection*, uint32_t, Less> mKnown;
};

void encodeBlobs(const std::vector<std::string>& blobs, const PackWriteOptions& options,
                 TableSet& tables, PackWriteStats& stats) {
    CompressedBlobs compressed = compressBlobs(blobs, options);
    for (const StoredBlob& blob : compressed.blobs) {
        tables.table(Chunk::Blobs)
            .add({static_cast<uint32_t>(blob.codec), blob.offset, blob.size, blob.rawSize});
        stats.rawSpirvBytes += blob.rawSize;
        stats.storedBlobBytes += blob.size;
    }
    stats.blobs = blobs.size();
    stats.dictionaryBytes = compressed.dictionary.size();
    tables.raw(Chunk::BlobData) = std::move(compressed.data);
    tables.raw(Chunk::Dictionary) = std::move(compressed.dictionary);
}

}  // namespace

void encodePrograms(const ProgramTable& programs, const PackWriteOptions& options, TableSet& tables,
                    PackWriteStats& stats) {
    std::vector<uint32_t> blobOf;
    std::vector<std::string> blobs = collectBlobs(programs, blobOf);
    ReflectionTable reflections;
    for (size_t i = 0; i < programs.programs().size(); ++i) {
        const pack::PackProgram& program = *programs.programs()[i];
        std::array<uint32_t, pack::kProgramFieldCount> record{};
        record[pack::kProgramStage] = static_cast<uint32_t>(program.stage);
        record[pack::kProgramEntry] = tables.strings().intern(program.entryPoint);
        record[pack::kProgramBlob] = blobOf[i];
        record[pack::kProgramReflection] = reflections.encode(program.reflection, tables);
        record[pack::kProgramSourceFile] = tables.strings().intern(program.source.file);
        record[pack::kProgramSourceLine] = program.source.line;
        TableBuilder& lists = tables.table(Chunk::StringLists);
        record[pack::kProgramDependencyFirst] = lists.size();
        for (const std::string& dependency : program.source.dependencies) {
            lists.add({tables.strings().intern(dependency)});
        }
        record[pack::kProgramDependencyCount] = count(program.source.dependencies.size());
        tables.table(Chunk::Programs).add(record);
    }
    stats.programs = programs.programs().size();
    encodeBlobs(blobs, options, tables, stats);
}

}  // namespace varc::packwriter
