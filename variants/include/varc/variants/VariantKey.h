// SPDX-License-Identifier: Apache-2.0
// VariantKey: the canonical, order-independent form of a keyword set, as a bitmask.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>

namespace varc::variants {

// Bit i is keyword i of a pass's KeywordTable (keywords sorted by name, so iterating set bits
// yields names in sorted order). Fixed capacity keeps keys trivially copyable for the pack
// format and allocation-free lookups.
class VariantKey {
public:
    static constexpr size_t kMaxKeywords = 256;

    void set(size_t bit);
    void reset(size_t bit);
    bool test(size_t bit) const;
    size_t count() const;  // number of keywords on
    bool empty() const { return count() == 0; }

    VariantKey operator&(const VariantKey& other) const;
    VariantKey operator|(const VariantKey& other) const;
    VariantKey andNot(const VariantKey& other) const;  // this & ~other

    const std::array<uint64_t, 4>& words() const { return mWords; }
    std::array<uint64_t, 4>& words() { return mWords; }

    friend bool operator==(const VariantKey&, const VariantKey&) = default;
    // Lexicographic on words from the highest; a total order for sorted tables.
    friend bool operator<(const VariantKey& a, const VariantKey& b);
    size_t hash() const;

private:
    std::array<uint64_t, 4> mWords{};
};

}  // namespace varc::variants

template <>
struct std::hash<varc::variants::VariantKey> {
    size_t operator()(const varc::variants::VariantKey& key) const { return key.hash(); }
};
