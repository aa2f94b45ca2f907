// SPDX-License-Identifier: Apache-2.0
// DirectoryStorage: values round-trip through files, and stats/clear touch only varc's entries.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "varc/cache/DirectoryStorage.h"

namespace varc::cache {
namespace {

namespace fs = std::filesystem;

const std::string kKey = "0123456789abcdef0123456789abcdef.program";

class DirectoryStorageTest : public ::testing::Test {
protected:
    void SetUp() override {
        mDir = fs::temp_directory_path() /
               ("varc-dirstorage-" +
                std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(mDir);
    }
    void TearDown() override { fs::remove_all(mDir); }
    fs::path mDir;
};

TEST_F(DirectoryStorageTest, AValueRoundTripsAndIsCounted) {
    DirectoryStorage storage(mDir.string(), "file:" + mDir.string(), false);
    EXPECT_EQ(storage.get(kKey), std::nullopt);
    ASSERT_TRUE(storage.put(kKey, "bytes"));
    EXPECT_TRUE(fs::is_regular_file(mDir / "01" / kKey));
    EXPECT_EQ(storage.get(kKey), "bytes");
    CacheLevelStats stats = storage.stats();
    EXPECT_EQ(stats.bytesWritten, 5u);
    EXPECT_EQ(stats.bytesRead, 5u);
    EXPECT_EQ(stats.writes, 1u);
}

TEST_F(DirectoryStorageTest, StatsAndClearTouchOnlyVarcEntries) {
    DirectoryStorage storage(mDir.string(), "file:" + mDir.string(), false);
    ASSERT_TRUE(storage.put(kKey, "bytes"));
    ASSERT_TRUE(storage.put("ab" + kKey.substr(2, 30) + ".source", "text!!"));
    std::ofstream(mDir / "01" / "notes.txt") << "mine";
    std::ofstream(mDir / "README") << "mine";
    Result<CacheUsage> usage = storage.usage();
    ASSERT_TRUE(usage) << usage.error().detail;
    EXPECT_EQ(usage->entries, 2u);
    EXPECT_EQ(usage->bytes, 11u);
    Result<uint64_t> removed = storage.clear();
    ASSERT_TRUE(removed) << removed.error().detail;
    EXPECT_EQ(*removed, 2u);
    EXPECT_TRUE(fs::exists(mDir / "01" / "notes.txt"));
    EXPECT_TRUE(fs::exists(mDir / "README"));
    EXPECT_EQ(storage.get(kKey), std::nullopt);
}

TEST_F(DirectoryStorageTest, AMissingFolderHoldsNothing) {
    DirectoryStorage storage((mDir / "absent").string(), "file:absent", false);
    Result<CacheUsage> usage = storage.usage();
    ASSERT_TRUE(usage);
    EXPECT_EQ(usage->entries, 0u);
}

}  // namespace
}  // namespace varc::cache
