// SPDX-License-Identifier: Apache-2.0
// Decodes a Reflections record and the tables it points into back to ProgramReflection.
#include "ReflectionDecoder.h"

#include "PackImage.h"
#include "varc/pack/PackTables.h"

namespace varc::reader::detail {

namespace {

using pack::Chunk;

std::vector<pack::BlockMember> decodeMembers(const PackImage& image, uint32_t first,
                                             uint32_t count) {
    std::vector<pack::BlockMember> members;
    for (uint32_t r = first; r < first + count; ++r) {
        auto get = [&](uint32_t f) { return image.get(Chunk::BlockMembers, r, f); };
        members.push_back({std::string(image.string(get(pack::kMemberName))),
                           get(pack::kMemberOffset), get(pack::kMemberSize),
                           std::string(image.string(get(pack::kMemberType))),
                           get(pack::kMemberArrayCount), get(pack::kMemberRowMajor) != 0});
    }
    return members;
}

template <typename Block>
std::vector<Block> decodeBlocks(const PackImage& image, uint32_t first, uint32_t count) {
    std::vector<Block> blocks;
    for (uint32_t r = first; r < first + count; ++r) {
        auto get = [&](uint32_t f) { return image.get(Chunk::UniformBlocks, r, f); };
        Block block;
        block.name = image.string(get(pack::kBlockName));
        if constexpr (std::is_same_v<Block, pack::UniformBlock>) {
            block.set = get(pack::kBlockSet);
            block.binding = get(pack::kBlockBinding);
        }
        block.size = get(pack::kBlockSize);
        block.members =
            decodeMembers(image, get(pack::kBlockMemberFirst), get(pack::kBlockMemberCount));
        blocks.push_back(std::move(block));
    }
    return blocks;
}

std::vector<pack::ResourceBinding> decodeResources(const PackImage& image, uint32_t first,
                                                   uint32_t count) {
    std::vector<pack::ResourceBinding> resources;
    for (uint32_t r = first; r < first + count; ++r) {
        auto get = [&](uint32_t f) { return image.get(Chunk::Resources, r, f); };
        resources.push_back({std::string(image.string(get(pack::kResourceName))),
                             static_cast<pack::ResourceKind>(get(pack::kResourceKind)),
                             static_cast<pack::ResourceDim>(get(pack::kResourceDim)),
                             get(pack::kResourceSet), get(pack::kResourceBinding),
                             get(pack::kResourceArraySize), get(pack::kResourceMultisampled) != 0});
    }
    return resources;
}

std::vector<pack::VertexInput> decodeVertexInputs(const PackImage& image, uint32_t first,
                                                  uint32_t count) {
    std::vector<pack::VertexInput> inputs;
    for (uint32_t r = first; r < first + count; ++r) {
        auto get = [&](uint32_t f) { return image.get(Chunk::VertexInputs, r, f); };
        inputs.push_back({std::string(image.string(get(pack::kVertexInputName))),
                          std::string(image.string(get(pack::kVertexInputSemantic))),
                          get(pack::kVertexInputLocation),
                          std::string(image.string(get(pack::kVertexInputType)))});
    }
    return inputs;
}

std::vector<pack::StageVariable> decodeStageVariables(const PackImage& image, uint32_t first,
                                                      uint32_t count) {
    std::vector<pack::StageVariable> vars;
    for (uint32_t r = first; r < first + count; ++r) {
        auto get = [&](uint32_t f) { return image.get(Chunk::StageVariables, r, f); };
        vars.push_back({std::string(image.string(get(pack::kStageVarName))),
                        get(pack::kStageVarLocation),
                        std::string(image.string(get(pack::kStageVarType)))});
    }
    return vars;
}

}  // namespace

pack::ProgramReflection decodeReflection(const PackImage& image, uint32_t record) {
    auto get = [&](uint32_t f) { return image.get(Chunk::Reflections, record, f); };
    pack::ProgramReflection reflection;
    reflection.uniformBlocks = decodeBlocks<pack::UniformBlock>(image, get(pack::kReflBlockFirst),
                                                                get(pack::kReflBlockCount));
    reflection.resources =
        decodeResources(image, get(pack::kReflResourceFirst), get(pack::kReflResourceCount));
    reflection.vertexInputs = decodeVertexInputs(image, get(pack::kReflVertexInputFirst),
                                                 get(pack::kReflVertexInputCount));
    reflection.inputs =
        decodeStageVariables(image, get(pack::kReflInputFirst), get(pack::kReflInputCount));
    reflection.outputs =
        decodeStageVariables(image, get(pack::kReflOutputFirst), get(pack::kReflOutputCount));
    reflection.pushConstants = decodeBlocks<pack::PushConstantBlock>(
        image, get(pack::kReflPushFirst), get(pack::kReflPushCount));
    return reflection;
}

}  // namespace varc::reader::detail
