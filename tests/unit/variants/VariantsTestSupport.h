// SPDX-License-Identifier: Apache-2.0
// Helpers shared by the variants tests: pragma lines from strings, spaces, variant listings.
#pragma once

#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

#include "varc/core/Diagnostic.h"
#include "varc/core/PragmaLine.h"
#include "varc/variants/PragmaParser.h"
#include "varc/variants/VariantSpace.h"

namespace varc::variants::testing {

// One PragmaLine per text: file 7, line i + 1, '#' at column |hashColumn|.
inline std::vector<PragmaLine> pragmaLines(const std::vector<std::string>& texts,
                                           uint32_t hashColumn = 1) {
    std::vector<PragmaLine> lines;
    for (size_t i = 0; i < texts.size(); ++i) {
        lines.push_back({texts[i], SourceLocation{7, static_cast<uint32_t>(i + 1), hashColumn}});
    }
    return lines;
}

// Parses |texts| as one program block's pragmas; diagnostics go to |sink|.
inline std::optional<PassKeywords> parse(const std::vector<std::string>& texts,
                                         DiagnosticList& sink) {
    return parsePragmas(pragmaLines(texts), sink);
}

// Parses and builds; fails the calling test (and returns nullopt) on any error.
inline std::optional<VariantSpace> spaceOf(const std::vector<std::string>& texts) {
    DiagnosticList sink;
    std::optional<PassKeywords> keywords = parse(texts, sink);
    EXPECT_TRUE(keywords.has_value())
        << (sink.diagnostics().empty() ? std::string("no diagnostic")
                                       : sink.diagnostics()[0].message);
    if (!keywords) return std::nullopt;
    std::optional<VariantSpace> space = VariantSpace::build(*keywords, sink);
    EXPECT_TRUE(space.has_value());
    return space;
}

// One line per variant in enumeration order: its keywords sorted and space-separated ("" for
// none), as Unity's "Show variants" prints them.
inline std::vector<std::string> listing(const VariantSpace& space) {
    std::vector<std::string> lines;
    space.forEach([&](const VariantKey& key) {
        std::string line;
        for (const std::string& name : space.table().namesOf(key)) {
            line += (line.empty() ? "" : " ") + name;
        }
        lines.push_back(line);
        return true;
    });
    return lines;
}

// The messages of |sink|'s diagnostics of |severity|.
inline std::vector<std::string> messages(const DiagnosticList& sink, Severity severity) {
    std::vector<std::string> result;
    for (const Diagnostic& diagnostic : sink.diagnostics()) {
        if (diagnostic.severity == severity) result.push_back(diagnostic.message);
    }
    return result;
}

}  // namespace varc::variants::testing
