// SPDX-License-Identifier: Apache-2.0
// One shader of an open Pack: its name and passes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "varc/pack/PackModel.h"
#include "varc/reader/PassView.h"

namespace varc::reader {

namespace detail {
class PackImage;
}

// A cheap handle (pointer + index); valid while its Pack lives. Allocation-free except
// properties().
class ShaderView {
public:
    ShaderView(const detail::PackImage* image, uint32_t index) : mImage(image), mIndex(index) {}

    uint32_t index() const { return mIndex; }
    std::string_view name() const;

    size_t passCount() const;
    // The |position|-th pass of the shader as stored (PassView::index() gives the pass's own
    // index in the source shader); nullopt when out of range.
    std::optional<PassView> pass(size_t position) const;
    // The first pass whose LightMode tag equals |lightMode| (ASCII case-insensitive, as Unity
    // compares tags); nullopt when none.
    std::optional<PassView> pass(std::string_view lightMode) const;

    // The shader's `Properties` with their defaults, in declaration order (empty for packs of
    // format 1.0, which did not store them). Engines start a material from these.
    std::vector<pack::ShaderProperty> properties() const;

    // PassView::dynamicKeywords of every pass, sorted, each once: the dynamic_branch keywords a
    // material of this shader sets per draw (Unity keeps one keyword space per shader).
    std::vector<std::string> dynamicKeywords() const;

private:
    const detail::PackImage* mImage;
    uint32_t mIndex;
};

}  // namespace varc::reader
