// SPDX-License-Identifier: Apache-2.0
#include "varc/render/UniformBlockWriter.h"

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace varc::render {

namespace {

// The shape of a member's type spelling: "float3" -> {float, 1 vector of 3}, "float4x4" ->
// {float, 4 columns of 4} (SPIR-V names matrices columns x rows).
struct MemberShape {
    enum class Scalar { Float, Int, Uint } scalar = Scalar::Float;
    uint32_t vectors = 1;     // columns for matrices
    uint32_t components = 1;  // rows for matrices
    bool matrix = false;
};

MemberShape shapeOf(const std::string& type) {
    MemberShape shape;
    std::string_view rest = type;
    if (rest.starts_with("uint")) {
        shape.scalar = MemberShape::Scalar::Uint;
        rest.remove_prefix(4);
    } else if (rest.starts_with("int")) {
        shape.scalar = MemberShape::Scalar::Int;
        rest.remove_prefix(3);
    } else if (rest.starts_with("bool")) {
        shape.scalar = MemberShape::Scalar::Uint;
        rest.remove_prefix(4);
    } else if (rest.starts_with("float") || rest.starts_with("half")) {
        rest.remove_prefix(rest.starts_with("float") ? 5 : 4);
    }
    if (rest.size() == 1 && rest[0] >= '1' && rest[0] <= '4') {
        shape.components = static_cast<uint32_t>(rest[0] - '0');
    } else if (rest.size() == 3 && rest[1] == 'x') {
        shape.matrix = true;
        shape.vectors = static_cast<uint32_t>(rest[0] - '0');
        shape.components = static_cast<uint32_t>(rest[2] - '0');
    }
    return shape;
}

void writeScalar(std::byte* at, float value, MemberShape::Scalar scalar) {
    switch (scalar) {
        case MemberShape::Scalar::Float:
            std::memcpy(at, &value, 4);
            break;
        case MemberShape::Scalar::Int: {
            auto integer = static_cast<int32_t>(value);
            std::memcpy(at, &integer, 4);
            break;
        }
        case MemberShape::Scalar::Uint: {
            auto integer = static_cast<uint32_t>(std::max(value, 0.0f));
            std::memcpy(at, &integer, 4);
            break;
        }
    }
}

// Writes one element (a scalar, vector or matrix) of |value| at |at|; |vectorStride| separates
// matrix columns.
void writeElement(std::byte* at, const MemberShape& shape, uint32_t vectorStride,
                  const float* value, uint32_t valueWidth) {
    if (!shape.matrix) {
        for (uint32_t c = 0; c < std::min(shape.components, valueWidth); ++c) {
            writeScalar(at + 4 * c, value[c], shape.scalar);
        }
        return;
    }
    if (valueWidth != 16) return;  // only a 4x4 value fills a matrix member
    for (uint32_t column = 0; column < shape.vectors; ++column) {
        for (uint32_t row = 0; row < shape.components; ++row) {
            writeScalar(at + column * vectorStride + 4 * row, value[column * 4 + row],
                        shape.scalar);
        }
    }
}

}  // namespace

BlockWriteReport writeUniformBlock(const pack::UniformBlock& block, ValueLayers layers,
                                   std::vector<std::byte>& bytes) {
    BlockWriteReport report;
    bytes.assign(block.size, std::byte{0});
    for (const pack::BlockMember& member : block.members) {
        const ShaderValue* value = nullptr;
        for (const ShaderValues* layer : layers) {
            if (layer && (value = layer->find(member.name))) break;
        }
        if (!value || value->data.empty()) {
            report.missing.push_back(member.name);
            continue;
        }
        MemberShape shape = shapeOf(member.type);
        uint32_t elements = std::max<uint32_t>(member.arrayCount, 1);
        uint32_t stride = member.size / elements;
        uint32_t vectorStride = shape.matrix ? stride / shape.vectors : 0;
        uint32_t count = std::min<uint32_t>(elements, static_cast<uint32_t>(value->elements()));
        for (uint32_t e = 0; e < count; ++e) {
            uint64_t offset = uint64_t{member.offset} + uint64_t{e} * stride;
            if (offset + stride > bytes.size()) break;  // never write past the block
            writeElement(bytes.data() + offset, shape, vectorStride,
                         value->data.data() + e * value->width, value->width);
        }
    }
    return report;
}

}  // namespace varc::render
