// SPDX-License-Identifier: Apache-2.0
// Helpers the libFuzzer targets share: bytes as text, and bytes as a small file tree.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace varc::fuzz {

inline std::string_view asText(const uint8_t* data, size_t size) {
    return {reinterpret_cast<const char*>(data), size};
}

// Splits |input| into files at each line "//@@file" (the dictionaries hold that token, so the
// fuzzer can add and remove files): the first part is the root, the others are "f1.h",
// "f2.h", ... An input without the marker is one file.
inline std::vector<std::string> splitFiles(std::string_view input) {
    constexpr std::string_view kMarker = "\n//@@file\n";
    std::vector<std::string> files;
    size_t start = 0;
    for (size_t at = input.find(kMarker); at != std::string_view::npos;
         at = input.find(kMarker, start)) {
        files.emplace_back(input.substr(start, at - start));
        start = at + kMarker.size();
    }
    files.emplace_back(input.substr(start));
    return files;
}

inline std::string includeName(size_t index) { return "f" + std::to_string(index) + ".h"; }

}  // namespace varc::fuzz
