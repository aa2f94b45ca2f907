// SPDX-License-Identifier: Apache-2.0
// The text form of `varc explain`'s report (ExplainReport.h).
#include "varc/cli/ExplainText.h"

#include <ostream>
#include <string>

namespace varc::cli {

namespace {

using Json = nlohmann::ordered_json;

constexpr size_t kListedVariants = 8;

std::string words(const Json& list, const std::string& separator = " ",
                  const std::string& none = "<no keywords>") {
    std::string text;
    for (const Json& word : list) text += (text.empty() ? "" : separator) + word.get<std::string>();
    return text.empty() ? none : text;
}

std::string plural(size_t count, const std::string& noun) {
    return std::to_string(count) + " " + noun + (count == 1 ? "" : "s");
}

std::string variantName(const Json& variant) {
    return "#" + std::to_string(variant["index"].get<size_t>()) + " " + words(variant["keywords"]);
}

void printSets(const Json& report, std::ostream& out) {
    out << "Keyword sets (the first declared varies slowest):\n";
    if (report["sets"].empty()) out << "  none\n";
    size_t index = 0;
    for (const Json& set : report["sets"]) {
        out << "  set " << index++ << ": " << set["directive"].get<std::string>()
            << (set["shortcut"].get<bool>() ? " (shortcut)" : "") << " at "
            << set["location"].get<std::string>() << "\n";
        out << "         " << words(set["keywords"]) << "\n";
        out << "         "
            << (set["stages"].empty() ? "changes no program"
                                      : "changes the " + words(set["stages"], ", ") + " program")
            << "\n";
    }
}

void printStages(const Json& report, std::ostream& out) {
    for (const Json& stage : report["stages"]) {
        out << stage["stage"].get<std::string>() << ": "
            << plural(stage["programs"].size(), "program") << "\n";
        for (const Json& program : stage["programs"]) {
            const Json& variants = program["variants"];
            out << "  program " << program["program"].get<uint32_t>() << ": "
                << plural(variants.size(), "variant") << ": ";
            for (size_t i = 0; i < variants.size() && i < kListedVariants; ++i)
                out << (i ? ", " : "") << variantName(variants[i]);
            if (variants.size() > kListedVariants)
                out << ", ... and " << variants.size() - kListedVariants << " more";
            out << "\n";
        }
    }
}

void printVariant(const Json& variant, size_t total, std::ostream& out) {
    out << "Variant #" << variant["index"].get<size_t>() << " of " << total
        << " in Unity's enumeration order: " << words(variant["keywords"]) << "\n";
    for (const Json& origin : variant["origins"]) {
        out << "  " << origin["keyword"].get<std::string>() << " from set "
            << origin["set"].get<size_t>() << ": " << origin["directive"].get<std::string>()
            << (origin["shortcut"].get<bool>() ? " (shortcut)" : "") << " at "
            << origin["location"].get<std::string>() << "\n";
    }
    for (const Json& program : variant["programs"]) {
        out << "  " << program["stage"].get<std::string>() << ": program "
            << program["program"].get<uint32_t>() << ", shared by "
            << plural(program["shared_by"].get<size_t>(), "variant") << "\n";
    }
    out << "Nearest variants (one set's choice away):\n";
    if (variant["nearest"].empty()) out << "  none\n";
    for (const Json& near : variant["nearest"]) {
        out << "  " << variantName(near) << " (set " << near["set"].get<size_t>() << "): "
            << (near["differs_in"].empty() ? "same programs"
                                           : "differs in " + words(near["differs_in"], ", "))
            << "\n";
    }
}

void printDiff(const Json& diff, std::ostream& out) {
    out << "Pruned sources of " << variantName(diff["a"]) << " (-) and " << variantName(diff["b"])
        << " (+):\n";
    for (const Json& stage : diff["stages"]) {
        out << "  " << stage["stage"].get<std::string>() << ": ";
        if (stage["same_source"].get<bool>()) {
            out << "same source\n";
            continue;
        }
        out << "sources differ"
            << (stage["same_program"].get<bool>() ? " (same SPIR-V after optimising)" : "") << "\n";
        for (const Json& line : stage["lines"]) out << "    " << line.get<std::string>() << "\n";
    }
}

}  // namespace

void printExplainText(const nlohmann::ordered_json& report, std::ostream& out) {
    std::string lightMode = report["light_mode"].get<std::string>();
    out << "Shader \"" << report["shader"].get<std::string>() << "\" pass "
        << report["pass"].get<size_t>()
        << (lightMode.empty() ? "" : " (LightMode " + lightMode + ")") << ": "
        << plural(report["variants"].get<size_t>(), "variant") << "\n";
    printSets(report, out);
    printStages(report, out);
    if (report.contains("variant")) printVariant(report["variant"], report["variants"], out);
    if (report.contains("diff")) printDiff(report["diff"], out);
}

}  // namespace varc::cli
