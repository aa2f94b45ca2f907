// SPDX-License-Identifier: Apache-2.0
// readFile: whole regular files; directories, missing files and oversized files are errors.
#include "varc/core/FileRead.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace varc {
namespace {

namespace fs = std::filesystem;

class FileReadTest : public ::testing::Test {
protected:
    void SetUp() override {
        mDir = fs::temp_directory_path() /
               ("varc-read-" + std::to_string(::getpid()) + "-" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(mDir);
        fs::create_directories(mDir);
    }
    void TearDown() override { fs::remove_all(mDir); }
    fs::path mDir;
};

TEST_F(FileReadTest, ReadsEveryByte) {
    std::string bytes("a\0b\r\n", 5);
    bytes += std::string(200000, 'x');  // several read() calls
    std::ofstream(mDir / "f.bin", std::ios::binary) << bytes;
    Result<std::string> read = readFile((mDir / "f.bin").string());
    ASSERT_TRUE(read.ok()) << read.error().detail;
    EXPECT_EQ(*read, bytes);
}

TEST_F(FileReadTest, ADirectoryIsAnErrorNotAnException) {
    Result<std::string> read = readFile(mDir.string());
    ASSERT_FALSE(read.ok());
    EXPECT_EQ(read.error().code, ErrorCode::IoError);
    EXPECT_NE(read.error().detail.find("it is a directory"), std::string::npos);
}

TEST_F(FileReadTest, AMissingFileNamesThePathAndTheReason) {
    Result<std::string> read = readFile((mDir / "missing.txt").string());
    ASSERT_FALSE(read.ok());
    EXPECT_NE(read.error().detail.find("cannot open '"), std::string::npos);
    EXPECT_NE(read.error().detail.find("missing.txt': No such file or directory"),
              std::string::npos);
}

TEST_F(FileReadTest, AFileOverTheLimitIsRefusedAtTheLimitItIsRead) {
    std::ofstream(mDir / "f.txt") << "12345";
    EXPECT_TRUE(readFile((mDir / "f.txt").string(), 5).ok());
    Result<std::string> read = readFile((mDir / "f.txt").string(), 4);
    ASSERT_FALSE(read.ok());
    EXPECT_NE(read.error().detail.find("at most 4"), std::string::npos);
}

}  // namespace
}  // namespace varc
