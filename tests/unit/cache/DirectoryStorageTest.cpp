// SPDX-License-Identifier: Apache-2.0
// DirectoryStorage: values round-trip through files, and stats/clear touch only varc's entries.
#include <gtest/gtest.h>

#include <filesystem>
#include <cstdio>
#include <fstream>
#include <iterator>

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

// Keys as ProgramCache names them, |n| distinct.
std::string keyNumber(int n) {
    char hex[33];
    std::snprintf(hex, sizeof(hex), "%032x", n);
    return std::string(hex) + ".program";
}

std::vector<CacheEntry> manyEntries(int count) {
    std::vector<CacheEntry> entries;
    for (int n = 0; n < count; ++n) entries.push_back({keyNumber(n), "value " + std::to_string(n)});
    return entries;
}

size_t filesUnder(const fs::path& dir) {
    size_t files = 0;
    for (const auto& entry : fs::recursive_directory_iterator(dir)) files += entry.is_regular_file();
    return files;
}

TEST_F(DirectoryStorageTest, ManyEntriesGoToOneBundleThatAnotherBuildReads) {
    const int count = static_cast<int>(DirectoryStorage::kBundleMinEntries) + 4;
    {
        DirectoryStorage writer(mDir.string(), "file:" + mDir.string(), false);
        ASSERT_TRUE(writer.putMany(manyEntries(count)));
        EXPECT_EQ(filesUnder(mDir), 1u) << "one file, not one per entry";
        EXPECT_EQ(writer.stats().writes, static_cast<uint64_t>(count));
        EXPECT_EQ(writer.get(keyNumber(3)), "value 3") << "the writer sees its own bundle";
    }
    DirectoryStorage reader(mDir.string(), "file:" + mDir.string(), false);
    for (int n = 0; n < count; ++n) EXPECT_EQ(reader.get(keyNumber(n)), "value " + std::to_string(n));
    EXPECT_EQ(reader.get(keyNumber(count)), std::nullopt);
    Result<CacheUsage> usage = reader.usage();
    ASSERT_TRUE(usage) << usage.error().detail;
    EXPECT_EQ(usage->entries, static_cast<uint64_t>(count));
    Result<uint64_t> removed = reader.clear();
    ASSERT_TRUE(removed) << removed.error().detail;
    EXPECT_EQ(*removed, static_cast<uint64_t>(count));
    EXPECT_EQ(filesUnder(mDir), 0u);
    EXPECT_EQ(reader.get(keyNumber(3)), std::nullopt);
}

TEST_F(DirectoryStorageTest, FewEntriesGetFilesOfTheirOwn) {
    DirectoryStorage storage(mDir.string(), "file:" + mDir.string(), false);
    ASSERT_TRUE(storage.putMany(manyEntries(3)));
    EXPECT_TRUE(fs::is_regular_file(storage.pathOf(keyNumber(2))));
    EXPECT_FALSE(fs::exists(mDir / "bundles"));
}

TEST_F(DirectoryStorageTest, ADamagedBundleIsMissesNeverACrash) {
    const int count = static_cast<int>(DirectoryStorage::kBundleMinEntries);
    {
        DirectoryStorage writer(mDir.string(), "file:" + mDir.string(), false);
        ASSERT_TRUE(writer.putMany(manyEntries(count)));
    }
    fs::path bundle = fs::directory_iterator(mDir / "bundles")->path();
    std::string bytes;
    {
        std::ifstream in(bundle, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), {});
    }
    // Cut in the values: the entries whose values are gone are misses, the others still hit.
    std::ofstream(bundle, std::ios::binary | std::ios::trunc) << bytes.substr(0, bytes.size() - 10);
    {
        DirectoryStorage reader(mDir.string(), "file:" + mDir.string(), false);
        EXPECT_EQ(reader.get(keyNumber(0)), "value 0");
        EXPECT_EQ(reader.get(keyNumber(count - 1)), std::nullopt);
    }
    // Cut in the index, then garbage of every length: never a read outside the file.
    for (size_t length : {size_t{3}, size_t{17}, size_t{40}, bytes.size() / 2}) {
        std::ofstream(bundle, std::ios::binary | std::ios::trunc) << bytes.substr(0, length);
        DirectoryStorage reader(mDir.string(), "file:" + mDir.string(), false);
        for (int n = 0; n < count; ++n) {
            std::optional<std::string> value = reader.get(keyNumber(n));
            if (value) {
                EXPECT_EQ(*value, "value " + std::to_string(n));
            }
        }
    }
    std::string garbage(bytes.size(), '\xff');
    garbage.replace(0, 8, "VARCBDL1");
    std::ofstream(bundle, std::ios::binary | std::ios::trunc) << garbage;
    DirectoryStorage reader(mDir.string(), "file:" + mDir.string(), false);
    EXPECT_EQ(reader.get(keyNumber(0)), std::nullopt);
}

}  // namespace
}  // namespace varc::cache
