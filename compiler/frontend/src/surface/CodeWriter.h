// SPDX-License-Identifier: Apache-2.0
// CodeWriter: collects generated code line by line.
#pragma once

#include <string>
#include <string_view>
#include <utility>

namespace varc::frontend::surface {

// The text of a generated program, one line() at a time.
class CodeWriter {
public:
    void line(std::string_view text) {
        mText.append(text);
        mText.push_back('\n');
    }
    std::string take() { return std::move(mText); }

private:
    std::string mText;
};

}  // namespace varc::frontend::surface
