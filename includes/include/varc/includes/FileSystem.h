// SPDX-License-Identifier: Apache-2.0
// The file access the include resolver needs, with a disk and an in-memory implementation.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace varc::includes {

// Read-only file access. Paths are '/'-separated; implementations normalise "a/./b/../c".
class FileSystem {
public:
    virtual ~FileSystem() = default;
    // Returns the whole file, or nullopt when |path| is not a readable regular file.
    virtual std::optional<std::string> read(const std::string& path) const = 0;
    virtual bool isFile(const std::string& path) const = 0;
    // Names of the regular files directly in |dir| ("" is the current directory), sorted; empty
    // when |dir| cannot be listed.
    virtual std::vector<std::string> fileNames(const std::string& dir) const = 0;
};

// The real file system.
class DiskFileSystem final : public FileSystem {
public:
    std::optional<std::string> read(const std::string& path) const override;
    bool isFile(const std::string& path) const override;
    std::vector<std::string> fileNames(const std::string& dir) const override;
};

// Files held in memory, for tests. Example:
//   InMemoryFileSystem fs;
//   fs.add("shaders/a.shader", "...").add("inc/My Lighting.cginc", "...");
class InMemoryFileSystem final : public FileSystem {
public:
    InMemoryFileSystem& add(const std::string& path, std::string contents);
    std::optional<std::string> read(const std::string& path) const override;
    bool isFile(const std::string& path) const override;
    std::vector<std::string> fileNames(const std::string& dir) const override;

private:
    std::map<std::string, std::string> mFiles;  // keyed by normalised path
};

// "a/./b/../c.h" -> "a/c.h"; keeps a leading '/' and leading "../" segments.
std::string normalizePath(const std::string& path);
// Directory part of |path| ("a/b/c.h" -> "a/b", "c.h" -> "").
std::string parentPath(const std::string& path);
// Joins |dir| and |name| with one '/', then normalises; |name| absolute wins.
std::string joinPath(const std::string& dir, const std::string& name);

}  // namespace varc::includes
