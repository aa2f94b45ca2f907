// SPDX-License-Identifier: Apache-2.0
// BuildManifest: (de)serialising the record of a build's file-system questions, and checking it.
#include "varc/cli/BuildManifest.h"

#include <xxhash.h>

#include <charconv>

#include "varc/core/HexText.h"

namespace varc::cli {

namespace {

constexpr std::string_view kHeader = "varc-manifest 1\n";
constexpr std::string_view kChecksumTag = "sum ";

std::string_view kindTag(FileQueryKind kind) {
    switch (kind) {
        case FileQueryKind::IsFile:
            return "isfile";
        case FileQueryKind::List:
            return "list";
        case FileQueryKind::Read:
            break;
    }
    return "read";
}

std::optional<FileQueryKind> kindOf(std::string_view tag) {
    for (FileQueryKind kind : {FileQueryKind::Read, FileQueryKind::IsFile, FileQueryKind::List}) {
        if (tag == kindTag(kind)) return kind;
    }
    return std::nullopt;
}

bool isHexDigest(std::string_view text) {
    return text.size() == 32 && text.find_first_not_of("0123456789abcdef") == std::string::npos;
}

// Whether |answer| is one a |kind| question can have.
bool validAnswer(FileQueryKind kind, std::string_view answer) {
    if (kind == FileQueryKind::IsFile) return answer == "0" || answer == "1";
    return isHexDigest(answer) || (kind == FileQueryKind::Read && answer == "-");
}

// "word rest" -> {word, rest}; rest is empty when there is no space.
std::pair<std::string_view, std::string_view> splitWord(std::string_view line) {
    size_t space = line.find(' ');
    if (space == std::string_view::npos) return {line, {}};
    return {line.substr(0, space), line.substr(space + 1)};
}

// Reads one body line into |manifest|; false when it is not one a manifest holds.
bool parseLine(std::string_view line, BuildManifest& manifest) {
    auto [tag, rest] = splitWord(line);
    if (tag == "dep" && !rest.empty()) {
        manifest.dependencies.emplace_back(rest);
        return true;
    }
    if (std::optional<FileQueryKind> kind = kindOf(tag)) {
        auto [answer, path] = splitWord(rest);
        if (!validAnswer(*kind, answer) || path.empty()) return false;
        manifest.queries.push_back({*kind, std::string(path), std::string(answer)});
        return true;
    }
    return false;
}

// "key HEX" then "pack HEX BYTES" into |manifest|.
bool parseHead(std::string_view keyLine, std::string_view packLine, BuildManifest& manifest) {
    auto [keyTag, key] = splitWord(keyLine);
    auto [packTag, pack] = splitWord(packLine);
    auto [digest, bytes] = splitWord(pack);
    if (keyTag != "key" || !isHexDigest(key) || packTag != "pack" || !isHexDigest(digest)) {
        return false;
    }
    auto [end, error] =
        std::from_chars(bytes.data(), bytes.data() + bytes.size(), manifest.packBytes);
    if (error != std::errc() || end != bytes.data() + bytes.size() || bytes.empty()) return false;
    manifest.key = key;
    manifest.packDigest = digest;
    return true;
}

// The lines of |body| (each ending in '\n'); nullopt when the last one does not.
std::optional<std::vector<std::string_view>> splitLines(std::string_view body) {
    std::vector<std::string_view> lines;
    while (!body.empty()) {
        size_t end = body.find('\n');
        if (end == std::string_view::npos) return std::nullopt;
        lines.push_back(body.substr(0, end));
        body.remove_prefix(end + 1);
    }
    return lines;
}

}  // namespace

std::string contentDigest(std::string_view bytes) {
    XXH128_hash_t hash = XXH3_128bits(bytes.data(), bytes.size());
    return hex64(hash.high64) + hex64(hash.low64);
}

std::string answerQuery(const includes::FileSystem& fileSystem, FileQueryKind kind,
                        const std::string& path) {
    switch (kind) {
        case FileQueryKind::IsFile:
            return fileSystem.isFile(path) ? "1" : "0";
        case FileQueryKind::List: {
            std::string names;
            for (const std::string& name : fileSystem.fileNames(path)) names += name + '\n';
            return contentDigest(names);
        }
        case FileQueryKind::Read:
            break;
    }
    std::optional<std::string> bytes = fileSystem.read(path);
    return bytes ? contentDigest(*bytes) : "-";
}

std::optional<std::string> serializeManifest(const BuildManifest& manifest) {
    std::string text(kHeader);
    text += "key " + manifest.key + "\n";
    text += "pack " + manifest.packDigest + " " + std::to_string(manifest.packBytes) + "\n";
    for (const std::string& dependency : manifest.dependencies) {
        if (dependency.find('\n') != std::string::npos || dependency.empty()) return std::nullopt;
        text += "dep " + dependency + "\n";
    }
    for (const FileQuery& query : manifest.queries) {
        if (query.path.find('\n') != std::string::npos || query.path.empty()) return std::nullopt;
        text += std::string(kindTag(query.kind)) + " " + query.answer + " " + query.path + "\n";
    }
    text += std::string(kChecksumTag) + hex64(XXH64(text.data(), text.size(), 0)) + "\n";
    return text;
}

std::optional<BuildManifest> parseManifest(std::string_view text, std::string_view expectedKey) {
    // The checksum line: "sum " + 16 hex digits + "\n", over everything before it.
    constexpr size_t kChecksumLine = 4 + 16 + 1;
    if (text.size() < kHeader.size() + kChecksumLine || text.substr(0, kHeader.size()) != kHeader)
        return std::nullopt;
    std::string_view body = text.substr(0, text.size() - kChecksumLine);
    std::string_view checksum = text.substr(body.size());
    if (checksum != std::string(kChecksumTag) + hex64(XXH64(body.data(), body.size(), 0)) + "\n")
        return std::nullopt;
    std::optional<std::vector<std::string_view>> lines = splitLines(body.substr(kHeader.size()));
    BuildManifest manifest;
    if (!lines || lines->size() < 2 || !parseHead((*lines)[0], (*lines)[1], manifest) ||
        manifest.key != expectedKey) {
        return std::nullopt;
    }
    for (size_t i = 2; i < lines->size(); ++i) {
        if (!parseLine((*lines)[i], manifest)) return std::nullopt;
    }
    return manifest;
}

std::optional<std::string> firstChangedQuery(const BuildManifest& manifest,
                                             const includes::FileSystem& fileSystem) {
    for (const FileQuery& query : manifest.queries) {
        if (answerQuery(fileSystem, query.kind, query.path) != query.answer) return query.path;
    }
    return std::nullopt;
}

}  // namespace varc::cli
