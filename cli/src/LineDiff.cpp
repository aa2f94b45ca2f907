// SPDX-License-Identifier: Apache-2.0
// A line diff of two texts, for `varc explain --diff`.
#include "LineDiff.h"

#include <algorithm>
#include <cstdint>
#include <sstream>

namespace varc::cli {

namespace {

constexpr size_t kMaxTableCells = size_t{1} << 22;  // 16 MiB of uint32_t

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

// LCS over a[aBegin, aEnd) and b[bBegin, bEnd), appended to |out| as -/+ lines.
void diffMiddle(const std::vector<std::string>& a, size_t aBegin, size_t aEnd,
                const std::vector<std::string>& b, size_t bBegin, size_t bEnd,
                std::vector<std::string>& out) {
    size_t n = aEnd - aBegin, m = bEnd - bBegin;
    if ((n + 1) * (m + 1) > kMaxTableCells) {
        for (size_t i = aBegin; i < aEnd; ++i) out.push_back("-" + a[i]);
        for (size_t j = bBegin; j < bEnd; ++j) out.push_back("+" + b[j]);
        return;
    }
    // table[i][j]: LCS length of a's suffix from i and b's suffix from j.
    std::vector<uint32_t> table((n + 1) * (m + 1), 0);
    auto at = [&](size_t i, size_t j) -> uint32_t& { return table[i * (m + 1) + j]; };
    for (size_t i = n; i-- > 0;) {
        for (size_t j = m; j-- > 0;) {
            at(i, j) = a[aBegin + i] == b[bBegin + j] ? at(i + 1, j + 1) + 1
                                                      : std::max(at(i + 1, j), at(i, j + 1));
        }
    }
    size_t i = 0, j = 0;
    while (i < n || j < m) {
        if (i < n && j < m && a[aBegin + i] == b[bBegin + j]) {
            ++i;
            ++j;
        } else if (i < n && (j == m || at(i + 1, j) >= at(i, j + 1))) {
            out.push_back("-" + a[aBegin + i++]);
        } else {
            out.push_back("+" + b[bBegin + j++]);
        }
    }
}

}  // namespace

std::vector<std::string> lineDiff(const std::string& a, const std::string& b) {
    std::vector<std::string> out;
    if (a == b) return out;
    std::vector<std::string> left = splitLines(a), right = splitLines(b);
    size_t prefix = 0;
    while (prefix < left.size() && prefix < right.size() && left[prefix] == right[prefix]) {
        ++prefix;
    }
    size_t suffix = 0;
    while (suffix + prefix < left.size() && suffix + prefix < right.size() &&
           left[left.size() - 1 - suffix] == right[right.size() - 1 - suffix]) {
        ++suffix;
    }
    diffMiddle(left, prefix, left.size() - suffix, right, prefix, right.size() - suffix, out);
    return out;
}

}  // namespace varc::cli
