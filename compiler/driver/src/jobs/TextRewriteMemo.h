// SPDX-License-Identifier: Apache-2.0
// Rewrites of a pass's text that depend on the text alone, not on the variant (the DirectX
// compilers' wide hex literals, empty macro arguments): computed once per text and shared by the
// preprocessing of every variant on every worker thread. A pass of 1536 variants used to
// rewrite its 200 KB text 3072 times, a third of its build.
#pragma once

#include <compare>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <utility>

namespace varc::driver::detail {

class TextRewriteMemo {
public:
    using Rewrite = std::function<std::string(std::string_view)>;

    // |rewrite|(|text|), computed on the first call for this |name| and text. |rewrite| must be
    // a pure function of its argument, so the result is the same whichever thread asks first.
    // The reference stays valid as long as the memo.
    const std::string& apply(std::string_view name, const std::string& text,
                             const Rewrite& rewrite);

private:
    struct Key {
        std::string name;
        uint64_t low = 0, high = 0;  // 128-bit hash of the text
        size_t size = 0;
        auto operator<=>(const Key&) const = default;
    };

    std::mutex mMutex;
    std::map<Key, std::unique_ptr<const std::string>> mResults;
};

}  // namespace varc::driver::detail
