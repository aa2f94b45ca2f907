// SPDX-License-Identifier: Apache-2.0
#include "varc/render/VertexLayout.h"

#include <cstddef>
#include <optional>
#include <string>

#include "varc/core/AsciiCase.h"

namespace varc::render {

namespace {

struct Stream {
    uint32_t offset;
    VkFormat format;
};

// The stream a semantic (or GLSL legacy name) reads; nullopt when the mesh has no such data.
std::optional<Stream> streamFor(const pack::VertexInput& input) {
    std::string key = toAsciiUpper(input.semantic.empty() ? input.name : input.semantic);
    auto is = [&](std::string_view prefix) { return key.rfind(prefix, 0) == 0; };
    if (is("POSITION") || key == "VARC_VERTEX" || is("SV_POSITION")) {
        return Stream{offsetof(MeshVertex, position), VK_FORMAT_R32G32B32_SFLOAT};
    }
    if (is("NORMAL") || key == "VARC_NORMAL")
        return Stream{offsetof(MeshVertex, normal), VK_FORMAT_R32G32B32_SFLOAT};
    if (is("TANGENT")) return Stream{offsetof(MeshVertex, tangent), VK_FORMAT_R32G32B32A32_SFLOAT};
    if (is("TEXCOORD") || is("VARC_MULTITEXCOORD"))
        return Stream{offsetof(MeshVertex, uv), VK_FORMAT_R32G32_SFLOAT};
    if (is("COLOR") || key == "VARC_COLOR")
        return Stream{offsetof(MeshVertex, color), VK_FORMAT_R32G32B32A32_SFLOAT};
    return std::nullopt;
}

}  // namespace

Result<VertexInputLayout> vertexInputLayout(const std::vector<pack::VertexInput>& inputs) {
    VertexInputLayout layout;
    layout.binding = {0, sizeof(MeshVertex), VK_VERTEX_INPUT_RATE_VERTEX};
    for (const pack::VertexInput& input : inputs) {
        std::optional<Stream> stream = streamFor(input);
        if (!stream) {
            return makeError(
                ErrorCode::InvalidInput,
                "vertex input '" + input.name + "' (semantic '" + input.semantic +
                    "') has no mesh data; supported: POSITION, NORMAL, TANGENT, TEXCOORDn, COLOR");
        }
        layout.attributes.push_back({input.location, 0, stream->format, stream->offset});
    }
    return layout;
}

}  // namespace varc::render
