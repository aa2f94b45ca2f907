// SPDX-License-Identifier: Apache-2.0
// One variant of a pass: its keywords and, per stage, the program with SPIR-V and reflection.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "varc/core/Result.h"
#include "varc/pack/PackModel.h"
#include "varc/reader/ProgramView.h"
#include "varc/variants/VariantKey.h"

namespace varc::reader {

namespace detail {
class PackImage;
}
class PassView;

// A cheap handle; valid while its Pack lives. See Pack for the thread-safety contract.
class VariantView {
public:
    VariantView(const detail::PackImage* image, uint32_t shader, uint32_t pass, uint32_t sorted,
                bool exact)
        : mImage(image), mShader(shader), mPass(pass), mSorted(sorted), mExact(exact) {}

    PassView pass() const;              // include varc/reader/PassView.h to use it
    uint32_t enumerationIndex() const;  // position in Unity's enumeration order
    // True when the lookup that produced this view found the requested keywords exactly
    // (always true for PassView::variant()).
    bool exact() const { return mExact; }
    variants::VariantKey key() const;
    std::vector<std::string> keywords() const;  // sorted; allocates

    bool hasStage(Stage stage) const;
    std::optional<ProgramView> program(Stage stage) const;
    // The stage's SPIR-V (see ProgramView::spirv); NotFound when the variant has no program
    // for |stage|.
    Result<std::span<const uint32_t>> spirv(Stage stage) const;
    pack::PackRenderState renderState() const;  // the pass's

    // "shader 'Custom/Lit' pass 0 'FORWARD' (LightMode ForwardBase) {DIRECTIONAL FOG_EXP}".
    std::string describe() const;

private:
    uint32_t programIndex(Stage stage) const;

    const detail::PackImage* mImage;
    uint32_t mShader;
    uint32_t mPass;    // Passes record
    uint32_t mSorted;  // VariantPrograms record, relative to the pass's first
    bool mExact;
};

}  // namespace varc::reader
