// SPDX-License-Identifier: Apache-2.0
// yaml-cpp behind a no-throw boundary, and typed accessors for UnityYAML objects.
#include "UnityYaml.h"

#include <algorithm>
#include <charconv>

namespace varc::project {

namespace {

constexpr size_t kBinaryProbeBytes = 64;

bool isAllUnderscores(std::string_view token) {
    return std::all_of(token.begin(), token.end(), [](char c) { return c == '_'; });
}

void appendKeywords(std::string_view text, std::vector<std::string>& out) {
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find_first_of(" \t\r\n", start);
        if (end == std::string_view::npos) end = text.size();
        std::string_view token = text.substr(start, end - start);
        if (!token.empty() && !isAllUnderscores(token)) out.emplace_back(token);
        start = end + 1;
    }
}

}  // namespace

bool isBinaryAsset(std::string_view text) {
    std::string_view head = text.substr(0, std::min(text.size(), kBinaryProbeBytes));
    return head.find('\0') != std::string_view::npos;
}

std::optional<std::vector<YAML::Node>> parseUnityYaml(std::string_view text,
                                                      const std::filesystem::path& file,
                                                      LoadContext& context) {
    if (isBinaryAsset(text)) {
        context.warn(file,
                     "binary-serialised Unity asset, not read (varc reads text assets: Asset "
                     "Serialization 'Force Text')");
        return std::nullopt;
    }
    try {
        return YAML::LoadAll(std::string(text));
    } catch (const YAML::Exception& error) {
        auto line = static_cast<uint32_t>(std::max(error.mark.line, 0) + 1);
        auto column = static_cast<uint32_t>(std::max(error.mark.column, 0) + 1);
        if (error.mark.is_null()) line = column = 0;
        context.warn(file, line, column, "malformed YAML, file not read: " + error.msg);
    } catch (const std::exception& error) {
        context.warn(file, std::string("malformed YAML, file not read: ") + error.what());
    }
    return std::nullopt;
}

std::optional<YAML::Node> findObject(const std::vector<YAML::Node>& documents,
                                     std::string_view className) {
    std::string key(className);
    for (const YAML::Node& document : documents) {
        if (auto object = field(document, key.c_str()); object && object->IsMap()) return object;
    }
    return std::nullopt;
}

std::optional<YAML::Node> field(const YAML::Node& map, const char* key) {
    if (!map.IsMap()) return std::nullopt;
    const YAML::Node& constMap = map;
    YAML::Node value = constMap[key];
    if (!value.IsDefined()) return std::nullopt;
    return value;
}

std::optional<std::string> scalarText(const YAML::Node& node) {
    if (node.IsNull()) return std::string();
    if (!node.IsScalar()) return std::nullopt;
    return node.Scalar();
}

std::optional<int64_t> integerValue(const YAML::Node& node) {
    if (!node.IsScalar()) return std::nullopt;
    const std::string& text = node.Scalar();
    int64_t value = 0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return value;
}

std::optional<AssetReference> assetReference(const YAML::Node& node) {
    auto fileId = field(node, "fileID");
    if (!fileId) return std::nullopt;
    auto id = integerValue(*fileId);
    if (!id) return std::nullopt;
    AssetReference reference;
    reference.fileId = *id;
    if (auto guid = field(node, "guid")) reference.guid = scalarText(*guid).value_or("");
    if (auto type = field(node, "type")) {
        reference.type = static_cast<int>(integerValue(*type).value_or(0));
    }
    return reference;
}

std::pair<uint32_t, uint32_t> positionOf(const YAML::Node& node) {
    YAML::Mark mark = node.Mark();
    if (mark.is_null() || mark.line < 0) return {0, 0};
    return {static_cast<uint32_t>(mark.line + 1), static_cast<uint32_t>(mark.column + 1)};
}

std::vector<std::string> keywordList(const YAML::Node& node) {
    std::vector<std::string> keywords;
    if (node.IsScalar()) {
        appendKeywords(node.Scalar(), keywords);
    } else if (node.IsSequence()) {
        for (const YAML::Node& item : node) {
            if (item.IsScalar()) appendKeywords(item.Scalar(), keywords);
        }
    }
    return keywords;
}

}  // namespace varc::project
