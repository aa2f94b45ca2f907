// SPDX-License-Identifier: Apache-2.0
// Follows the text one walk emits through its top-level blocks: which are function bodies, under
// what name, and which identifiers each holds; for the reachable-code projection.
#pragma once

#include <functional>
#include <string_view>
#include <unordered_set>
#include <vector>

#include "ConditionalText.h"

namespace varc::driver::projection {

class BlockTracker {
public:
    // A top-level `{ ... }` of the emitted text.
    struct Block {
        // The function it is the body of (`name(...) [: SEMANTIC] {`), or empty for any other
        // block (struct, cbuffer, initializer, one a macro opens): those count as always used.
        std::string_view function;
        std::vector<std::string_view> identifiers;  // a function body's identifiers
    };
    // The #define in force for a name, or nullptr.
    using Definitions = std::function<const PpLine*(std::string_view)>;

    // |braceMacros|: ConditionalText::braceMacros(), the macros whose expansion the tracker
    // follows for their braces.
    explicit BlockTracker(const std::unordered_set<std::string_view>& braceMacros)
        : mBraceMacros(braceMacros) {}

    // Follows one emitted run of text lines. Returns the block of the function body the run
    // lies wholly inside, or -1.
    int follow(const std::vector<std::string_view>& code, const Definitions& definitions);
    // The block of the function body the walk is inside now, or -1.
    int functionBody() const;

    const std::vector<Block>& blocks() const { return mBlocks; }
    // Ends the walk: a declaration still open counts as used.
    void finish();
    // The identifiers outside every function body (declarations, headers, other blocks).
    const std::vector<std::string_view>& outside() const { return mOutside; }
    // The macros whose braces were followed, once per use: their definitions shape the blocks.
    const std::vector<std::string_view>& braceMacroUses() const { return mBraceUses; }
    // False when the braces did not nest (a `}` with no block open): nothing is known.
    bool consistent() const { return mConsistent; }

private:
    void token(std::string_view token, const Definitions& definitions);
    void brace(std::string_view brace, bool fromMacro);
    void identifier(std::string_view name);
    void flushHeader(size_t skip);
    void expand(std::string_view macro, const Definitions& definitions, int depth);

    const std::unordered_set<std::string_view>& mBraceMacros;
    std::vector<Block> mBlocks;
    std::vector<std::string_view> mOutside;
    std::vector<std::string_view> mBraceUses;
    std::vector<std::string_view> mHeader;  // top-level tokens since the last `;` or block
    int mDepth = 0;
    int mCurrent = -1;     // the open top-level block, or -1
    bool mClosed = false;  // a top-level block closed during the current run
    bool mConsistent = true;
    static constexpr size_t kExpansionBudget = 1 << 16;  // tokens per use of a brace macro
    size_t mExpansionBudget = 0;
};

}  // namespace varc::driver::projection
