// SPDX-License-Identifier: Apache-2.0
// A line diff of two texts, for `varc explain --diff`.
#pragma once

#include <string>
#include <vector>

namespace varc::cli {

// The lines that differ between |a| and |b|, in order: "-line" only in |a|, "+line" only in |b|
// (a longest common subsequence of the lines between the common prefix and suffix; when that
// middle is too big for it, all its lines of |a| then all of |b|). Empty when equal.
// Example: lineDiff("x\ny\n", "x\nz\n") == {"-y", "+z"}.
std::vector<std::string> lineDiff(const std::string& a, const std::string& b);

}  // namespace varc::cli
