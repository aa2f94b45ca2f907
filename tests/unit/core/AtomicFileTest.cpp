// SPDX-License-Identifier: Apache-2.0
// writeFileAtomically replaces files whole and leaves nothing behind on failure.
#include "varc/core/AtomicFile.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace varc {
namespace {

namespace fs = std::filesystem;

std::string readAll(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

class AtomicFileTest : public ::testing::Test {
protected:
    void SetUp() override {
        mDir = fs::temp_directory_path() /
               ("varc-atomic-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(mDir);
        fs::create_directories(mDir);
    }
    void TearDown() override { fs::remove_all(mDir); }
    fs::path mDir;
};

TEST_F(AtomicFileTest, ReplacesExistingContentsWhole) {
    fs::path path = mDir / "out.bin";
    ASSERT_TRUE(writeFileAtomically(path.string(), "old contents").ok());
    ASSERT_TRUE(writeFileAtomically(path.string(), std::string("new\0data", 8)).ok());
    EXPECT_EQ(readAll(path), std::string("new\0data", 8));
    EXPECT_EQ(std::distance(fs::directory_iterator(mDir), fs::directory_iterator()), 1);
}

TEST_F(AtomicFileTest, FailsWithPathInMessageAndLeavesNoFile) {
    fs::path path = mDir / "missing-dir" / "out.bin";
    Status status = writeFileAtomically(path.string(), "x");
    ASSERT_FALSE(status.ok());
    EXPECT_EQ(status.error().code, ErrorCode::IoError);
    EXPECT_NE(status.error().detail.find("missing-dir"), std::string::npos);
    EXPECT_FALSE(fs::exists(path));
}

}  // namespace
}  // namespace varc
