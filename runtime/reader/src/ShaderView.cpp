// SPDX-License-Identifier: Apache-2.0
// One shader of an open Pack: its name and passes.
#include "varc/reader/ShaderView.h"

#include <algorithm>
#include <bit>

#include "PackImage.h"
#include "varc/core/AsciiCase.h"
#include "varc/pack/PackTables.h"

namespace varc::reader {

using pack::Chunk;

std::string_view ShaderView::name() const {
    return mImage->string(mImage->get(Chunk::Shaders, mIndex, pack::kShaderName));
}

size_t ShaderView::passCount() const {
    return mImage->get(Chunk::Shaders, mIndex, pack::kShaderPassCount);
}

std::optional<PassView> ShaderView::pass(size_t position) const {
    if (position >= passCount()) return std::nullopt;
    uint32_t first = mImage->get(Chunk::Shaders, mIndex, pack::kShaderPassFirst);
    return PassView(mImage, mIndex, first + static_cast<uint32_t>(position));
}

std::vector<std::string> ShaderView::dynamicKeywords() const {
    std::vector<std::string> names;
    for (size_t i = 0; i < passCount(); ++i) {
        for (std::string& name : pass(i)->dynamicKeywords()) names.push_back(std::move(name));
    }
    std::sort(names.begin(), names.end());
    names.erase(std::unique(names.begin(), names.end()), names.end());
    return names;
}

std::optional<PassView> ShaderView::pass(std::string_view lightMode) const {
    for (size_t i = 0; i < passCount(); ++i) {
        PassView candidate = *pass(i);
        if (equalsIgnoreAsciiCase(candidate.lightMode(), lightMode)) return candidate;
    }
    return std::nullopt;
}

std::vector<pack::ShaderProperty> ShaderView::properties() const {
    std::vector<pack::ShaderProperty> properties;
    for (uint32_t record = 0; record < mImage->count(Chunk::Properties); ++record) {
        if (mImage->get(Chunk::Properties, record, pack::kPropertyShader) != mIndex) continue;
        pack::ShaderProperty property;
        property.name = mImage->string(mImage->get(Chunk::Properties, record, pack::kPropertyName));
        property.kind = static_cast<pack::PropertyKind>(
            mImage->get(Chunk::Properties, record, pack::kPropertyKind));
        for (uint32_t i = 0; i < 4; ++i) {
            property.value[i] =
                std::bit_cast<float>(mImage->get(Chunk::Properties, record, pack::kPropertyX + i));
        }
        property.texture =
            mImage->string(mImage->get(Chunk::Properties, record, pack::kPropertyTexture));
        properties.push_back(std::move(property));
    }
    return properties;
}

}  // namespace varc::reader
