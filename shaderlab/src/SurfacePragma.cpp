// SPDX-License-Identifier: Apache-2.0
// Reads `#pragma surface FUNC MODEL [options]` out of a SubShader's program block.
#include "SurfacePragma.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace varc::shaderlab {

namespace {

struct Word {
    std::string_view text;
    uint32_t column;  // of text[0]
};

// The whitespace-separated words of |text| up to a `//` comment, with their columns from |at|.
std::vector<Word> wordsOf(std::string_view text, SourceLocation at) {
    size_t comment = text.find("//");
    if (comment != std::string_view::npos) text = text.substr(0, comment);
    std::vector<Word> words;
    size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() && (text[i] == ' ' || text[i] == '\t' || text[i] == '\r')) ++i;
        size_t start = i;
        while (i < text.size() && text[i] != ' ' && text[i] != '\t' && text[i] != '\r') ++i;
        if (i > start) {
            words.push_back(
                {text.substr(start, i - start), at.column + static_cast<uint32_t>(start)});
        }
    }
    return words;
}

// Options varc accepts and does not act on: lightmaps, meta passes, instancing, interpolation
// and code-size hints, the deferred and legacy paths varc generates no pass for.
constexpr std::array<std::string_view, 9> kIgnoredOptions = {
    "nometa",     "noinstancing", "nolppv",         "halfasview", "interpolateview",
    "approxview", "dualforward",  "softvegetation", "addprepass"};

// Options that remove keywords of the forward shortcuts (docs/KEYWORDS.md §4): passed on to them.
constexpr std::array<std::string_view, 6> kShortcutOptions = {
    "nolightmap", "nodirlightmap", "nodynlightmap", "noshadowmask", "novertexlights", "noshadow"};

bool isIgnored(std::string_view name) {
    return std::find(kIgnoredOptions.begin(), kIgnoredOptions.end(), name) != kIgnoredOptions.end();
}

struct Flag {
    std::string_view word;
    bool SurfaceOptions::*member;
};

// Applies a flag option (no value). Returns false when |name| is no known flag.
bool applyFlag(std::string_view name, SurfaceOptions& options) {
    if (std::find(kShortcutOptions.begin(), kShortcutOptions.end(), name) !=
        kShortcutOptions.end()) {
        options.shortcutOptions.emplace_back(name);
    }
    static constexpr std::array<Flag, 9> kFlags = {{
        {"keepalpha", &SurfaceOptions::keepAlpha},
        {"addshadow", &SurfaceOptions::addShadow},
        {"fullforwardshadows", &SurfaceOptions::fullForwardShadows},
        {"noforwardadd", &SurfaceOptions::noForwardAdd},
        {"noambient", &SurfaceOptions::noAmbient},
        {"novertexlights", &SurfaceOptions::noVertexLights},
        {"nofog", &SurfaceOptions::noFog},
        {"noshadow", &SurfaceOptions::noShadow},
        {"dithercrossfade", &SurfaceOptions::ditherCrossFade},
    }};
    for (const Flag& flag : kFlags) {
        if (flag.word == name) {
            options.*flag.member = true;
            return true;
        }
    }
    if (name == "alpha") {
        options.alpha = SurfaceOptions::Alpha::Blend;
        return true;
    }
    return isIgnored(name) || std::find(kShortcutOptions.begin(), kShortcutOptions.end(), name) !=
                                  kShortcutOptions.end();
}

// Options with a value that varc accepts with a warning: they change nothing it generates.
bool isUnsupportedValueOption(std::string_view name) {
    return name == "tessellate" || name == "tessphong" || name == "finalgbuffer" ||
           name == "finalprepass";
}

// Applies `name:value`. Returns an error message, or "" when applied.
std::string applyValue(std::string_view name, std::string_view value, SurfaceOptions& options) {
    if (name == "vertex")
        options.vertexFunction = std::string(value);
    else if (name == "finalcolor")
        options.finalColorFunction = std::string(value);
    else if (name == "alphatest")
        options.alphaTestProperty = std::string(value);
    else if (name == "alpha") {
        if (value == "blend" || value == "auto")
            options.alpha = SurfaceOptions::Alpha::Blend;
        else if (value == "fade")
            options.alpha = SurfaceOptions::Alpha::Fade;
        else if (value == "premul")
            options.alpha = SurfaceOptions::Alpha::Premultiply;
        else
            return "unknown value '" + std::string(value) + "' of 'alpha' (blend, fade, premul)";
    } else if (name == "decal") {
        if (value == "add")
            options.decal = SurfaceOptions::Decal::Add;
        else if (value == "blend")
            options.decal = SurfaceOptions::Decal::Blend;
        else
            return "unknown value '" + std::string(value) + "' of 'decal' (add, blend)";
    } else if (name == "exclude_path") {
        if (value == "forward")
            options.excludeForward = true;
        else if (value != "deferred" && value != "prepass") {
            return "unknown value '" + std::string(value) +
                   "' of 'exclude_path' (deferred, forward, prepass)";
        }
    } else {
        return "unknown surface shader option '" + std::string(name) + ":" + std::string(value) +
               "'";
    }
    return "";
}

}  // namespace

std::optional<SourceLocation> findSurfacePragma(const ProgramBlock& block) {
    std::string_view text = block.text;
    SourceLocation location = block.origin;
    size_t lineStart = 0;
    while (lineStart <= text.size()) {
        size_t end = std::min(text.find('\n', lineStart), text.size());
        std::string_view line = text.substr(lineStart, end - lineStart);
        size_t hash = line.find_first_not_of(" \t\r");
        if (hash != std::string_view::npos && line[hash] == '#') {
            std::string_view rest = line.substr(hash + 1);
            rest.remove_prefix(std::min(rest.find_first_not_of(" \t"), rest.size()));
            if (rest.starts_with("pragma")) {
                rest.remove_prefix(6);
                rest.remove_prefix(std::min(rest.find_first_not_of(" \t"), rest.size()));
                if (rest.starts_with("surface") &&
                    (rest.size() == 7 || rest[7] == ' ' || rest[7] == '\t' || rest[7] == '\r')) {
                    uint32_t column = static_cast<uint32_t>(hash) + 1;
                    if (location.line == block.origin.line) column += block.origin.column - 1;
                    return SourceLocation{location.file, location.line, column};
                }
            }
        }
        lineStart = end + 1;
        ++location.line;
    }
    return std::nullopt;
}

bool parseSurfaceOptions(std::string_view text, SourceLocation at, SurfaceProgram& out,
                         DiagnosticSink& sink) {
    std::vector<Word> words = wordsOf(text, at);
    if (words.size() < 2) {
        sink.error(at,
                   "'#pragma surface' needs a surface function and a lighting model: "
                   "'#pragma surface FUNC MODEL [options]'");
        return false;
    }
    out.function = std::string(words[0].text);
    out.lightingModel = std::string(words[1].text);
    for (size_t i = 2; i < words.size(); ++i) {
        const Word& word = words[i];
        SourceLocation where{at.file, at.line, word.column};
        size_t colon = word.text.find(':');
        std::string message;
        if (colon == std::string_view::npos) {
            if (!applyFlag(word.text, out.options)) {
                message = "unknown surface shader option '" + std::string(word.text) + "'";
            }
        } else if (colon + 1 == word.text.size()) {
            message = "surface shader option '" + std::string(word.text) + "' has no value";
        } else if (isUnsupportedValueOption(word.text.substr(0, colon))) {
            sink.warning(where, "surface shader option '" + std::string(word.text) +
                                    "' is accepted and not acted on: varc generates no "
                                    "tessellation, G-buffer or prepass code");
        } else {
            message =
                applyValue(word.text.substr(0, colon), word.text.substr(colon + 1), out.options);
        }
        if (!message.empty()) {
            sink.error(where, message);
            return false;
        }
    }
    return true;
}

std::optional<SurfaceProgram> parseSurfaceProgram(const ProgramBlock& block, SourceLocation pragma,
                                                  DiagnosticSink& sink) {
    // The pragma's line within the block, and the column where the line starts.
    std::string_view text = block.text;
    size_t lineStart = 0;
    for (uint32_t line = block.origin.line; line < pragma.line; ++line) {
        lineStart = text.find('\n', lineStart) + 1;
    }
    size_t end = std::min(text.find('\n', lineStart), text.size());
    std::string_view line = text.substr(lineStart, end - lineStart);
    uint32_t firstColumn = pragma.line == block.origin.line ? block.origin.column : 1;
    size_t keyword = line.find("surface");
    SurfaceProgram program;
    program.block = block;
    program.pragma = pragma;
    SourceLocation after{pragma.file, pragma.line,
                         firstColumn + static_cast<uint32_t>(keyword + 7)};
    if (!parseSurfaceOptions(line.substr(keyword + 7), after, program, sink)) {
        return std::nullopt;
    }
    return program;
}

}  // namespace varc::shaderlab
