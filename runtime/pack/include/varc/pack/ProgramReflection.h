// SPDX-License-Identifier: Apache-2.0
// What a stage program exposes: uniform blocks, resources, vertex inputs, stage interface.
#pragma once

#include <compare>
#include <cstdint>
#include <string>
#include <vector>

namespace varc::pack {

// One member of a uniform or push-constant block.
struct BlockMember {
    std::string name;         // "unity_ObjectToWorld"
    uint32_t offset = 0;      // bytes from the block start
    uint32_t size = 0;        // bytes, including every array element
    std::string type;         // HLSL spelling: "float", "float4", "float4x4", "int2", ...
    uint32_t arrayCount = 0;  // 0 = not an array
    bool rowMajor = false;    // matrices only
    friend bool operator==(const BlockMember&, const BlockMember&) = default;
    friend auto operator<=>(const BlockMember&, const BlockMember&) = default;
};

struct UniformBlock {
    std::string name;  // block (cbuffer) name, e.g. "UnityPerDraw"
    uint32_t set = 0;
    uint32_t binding = 0;
    uint32_t size = 0;  // bytes
    std::vector<BlockMember> members;
    friend bool operator==(const UniformBlock&, const UniformBlock&) = default;
    friend auto operator<=>(const UniformBlock&, const UniformBlock&) = default;
};

struct PushConstantBlock {
    std::string name;
    uint32_t size = 0;  // bytes
    std::vector<BlockMember> members;
    friend bool operator==(const PushConstantBlock&, const PushConstantBlock&) = default;
    friend auto operator<=>(const PushConstantBlock&, const PushConstantBlock&) = default;
};

// Descriptor kinds other than uniform blocks (those are UniformBlock).
enum class ResourceKind : uint8_t {
    SampledImage = 0,          // Texture2D t; (separate image)
    Sampler = 1,               // SamplerState s;
    CombinedImageSampler = 2,  // sampler2D s;
    StorageImage = 3,          // RWTexture2D
    UniformTexelBuffer = 4,    // Buffer<T>
    StorageTexelBuffer = 5,    // RWBuffer<T>
    StorageBuffer = 6,         // StructuredBuffer / RWStructuredBuffer / ByteAddressBuffer
    InputAttachment = 7,
};
inline constexpr uint32_t kResourceKindCount = 8;

enum class ResourceDim : uint8_t {
    None = 0,  // samplers and storage buffers
    Dim1D = 1,
    Dim2D = 2,
    Dim3D = 3,
    Cube = 4,
    Dim1DArray = 5,
    Dim2DArray = 6,
    CubeArray = 7,
    Buffer = 8,  // texel buffers
};
inline constexpr uint32_t kResourceDimCount = 9;

struct ResourceBinding {
    std::string name;  // "_MainTex"
    ResourceKind kind = ResourceKind::CombinedImageSampler;
    ResourceDim dim = ResourceDim::Dim2D;
    uint32_t set = 0;
    uint32_t binding = 0;
    uint32_t arraySize = 1;  // descriptors; 0 = runtime-sized array
    bool multisampled = false;
    friend bool operator==(const ResourceBinding&, const ResourceBinding&) = default;
    friend auto operator<=>(const ResourceBinding&, const ResourceBinding&) = default;
};

struct VertexInput {
    std::string name;      // "v.vertex"
    std::string semantic;  // "POSITION", "NORMAL", "TEXCOORD0", ...
    uint32_t location = 0;
    std::string type;  // "float4"
    friend bool operator==(const VertexInput&, const VertexInput&) = default;
    friend auto operator<=>(const VertexInput&, const VertexInput&) = default;
};

// A stage input or output, for interface checks between consecutive stages.
struct StageVariable {
    std::string name;
    uint32_t location = 0;
    std::string type;
    friend bool operator==(const StageVariable&, const StageVariable&) = default;
    friend auto operator<=>(const StageVariable&, const StageVariable&) = default;
};

struct ProgramReflection {
    std::vector<UniformBlock> uniformBlocks;
    std::vector<ResourceBinding> resources;
    std::vector<VertexInput> vertexInputs;  // vertex programs only
    std::vector<StageVariable> inputs;
    std::vector<StageVariable> outputs;
    std::vector<PushConstantBlock> pushConstants;
    friend bool operator==(const ProgramReflection&, const ProgramReflection&) = default;
    friend auto operator<=>(const ProgramReflection&, const ProgramReflection&) = default;
};

}  // namespace varc::pack
