// SPDX-License-Identifier: Apache-2.0
// Path helpers, InMemoryFileSystem and DiskFileSystem (in a temporary directory).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "varc/includes/FileSystem.h"

namespace varc::includes {
namespace {

namespace fs = std::filesystem;

TEST(FileSystem, NormalizesPathsLexically) {
    EXPECT_EQ(normalizePath("a/./b/../c.h"), "a/c.h");
    EXPECT_EQ(normalizePath("a//b/"), "a/b");
    EXPECT_EQ(normalizePath("./a"), "a");
    EXPECT_EQ(normalizePath("../a/../../b"), "../../b");
    EXPECT_EQ(normalizePath("/x/../../y"), "/y");
    EXPECT_EQ(normalizePath("a/.."), ".");
    EXPECT_EQ(normalizePath("/"), "/");
    EXPECT_EQ(normalizePath("My Dir/My File.cginc"), "My Dir/My File.cginc");
    EXPECT_EQ(normalizePath(""), "");
}

TEST(FileSystem, SplitsAndJoinsPaths) {
    EXPECT_EQ(parentPath("a/b/c.h"), "a/b");
    EXPECT_EQ(parentPath("c.h"), "");
    EXPECT_EQ(parentPath("/c.h"), "/");
    EXPECT_EQ(joinPath("a/b", "../c.h"), "a/c.h");
    EXPECT_EQ(joinPath("", "c.h"), "c.h");
    EXPECT_EQ(joinPath("a", "/abs/c.h"), "/abs/c.h");
    EXPECT_EQ(joinPath("/", "c.h"), "/c.h");
}

TEST(FileSystem, InMemoryFileSystemMatchesNormalisedPaths) {
    InMemoryFileSystem files;
    files.add("inc/./My Lighting.cginc", "light").add("inc/b.h", "");
    EXPECT_EQ(files.read("inc/x/../My Lighting.cginc"), "light");
    EXPECT_TRUE(files.isFile("./inc/b.h"));
    EXPECT_EQ(files.read("inc/b.h"), "");
    EXPECT_FALSE(files.isFile("inc"));
    EXPECT_FALSE(files.read("inc/c.h").has_value());
}

TEST(FileSystem, DiskFileSystemReadsRegularFilesOnly) {
    fs::path dir = fs::temp_directory_path() / "varc-includes-disk-test";
    fs::remove_all(dir);
    fs::create_directories(dir / "sub");
    std::ofstream(dir / "My File.cginc", std::ios::binary) << std::string("a\0b\r\n", 5);
    std::ofstream(dir / "empty.h", std::ios::binary).flush();
    DiskFileSystem disk;
    std::string base = dir.string();
    EXPECT_EQ(disk.read(base + "/sub/../My File.cginc"), std::string("a\0b\r\n", 5));
    EXPECT_TRUE(disk.isFile(base + "/My File.cginc"));
    EXPECT_EQ(disk.read(base + "/empty.h"), "");
    EXPECT_FALSE(disk.isFile(base + "/sub"));
    EXPECT_FALSE(disk.read(base + "/sub").has_value());
    EXPECT_FALSE(disk.read(base + "/missing.h").has_value());
    EXPECT_FALSE(disk.isFile(""));
    fs::remove_all(dir);
}

}  // namespace
}  // namespace varc::includes
