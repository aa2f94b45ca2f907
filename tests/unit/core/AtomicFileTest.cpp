// SPDX-License-Identifier: Apache-2.0
// writeFileAtomically replaces files whole and leaves nothing behind on failure.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <thread>
#include <vector>

#include "varc/core/AtomicFile.h"

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

TEST_F(AtomicFileTest, AnUnsyncedWriteIsAsWholeAndLeavesNoTemporary) {
    fs::path path = mDir / "entry.program";
    ASSERT_TRUE(writeFileAtomically(path.string(), "old", Durability::Unsynced).ok());
    ASSERT_TRUE(writeFileAtomically(path.string(), "new contents", Durability::Unsynced).ok());
    EXPECT_EQ(readAll(path), "new contents");
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

size_t entriesIn(const fs::path& dir) {
    return static_cast<size_t>(
        std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

// The `-o /dev/null` case without touching /dev: a FIFO is written into, never replaced. The
// test holds the read end open (non-blocking) first, so the small write lands in the pipe's
// buffer and nothing can hang, whatever writeFileAtomically does.
TEST_F(AtomicFileTest, WritesIntoAFifoAndLeavesItAFifo) {
    fs::path fifo = mDir / "pipe";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    int readEnd = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
    ASSERT_GE(readEnd, 0);
    Status status = writeFileAtomically(fifo.string(), "through the pipe");
    char buffer[64] = {};
    ssize_t received = ::read(readEnd, buffer, sizeof buffer);
    ::close(readEnd);
    ASSERT_TRUE(status.ok()) << status.error().detail;
    EXPECT_EQ(std::string(buffer, received > 0 ? static_cast<size_t>(received) : 0),
              "through the pipe");
    EXPECT_TRUE(fs::is_fifo(fifo));
    EXPECT_EQ(entriesIn(mDir), 1u);  // no temporary left beside it
}

TEST_F(AtomicFileTest, ASymbolicLinkStaysALinkAndItsTargetIsReplaced) {
    fs::path target = mDir / "target.bin";
    fs::path link = mDir / "link.bin";
    ASSERT_TRUE(writeFileAtomically(target.string(), "old").ok());
    fs::create_symlink(target, link);
    ASSERT_TRUE(writeFileAtomically(link.string(), "new").ok());
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_EQ(readAll(target), "new");
    EXPECT_EQ(entriesIn(mDir), 2u);
}

TEST_F(AtomicFileTest, ADirectoryIsAnErrorAndStaysADirectory) {
    fs::path dir = mDir / "sub";
    fs::create_directories(dir);
    Status status = writeFileAtomically(dir.string(), "x");
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().detail.find("directory"), std::string::npos);
    EXPECT_TRUE(fs::is_directory(dir));
    EXPECT_EQ(entriesIn(mDir), 1u);
}

// Threads of one process writing one path never share a temporary: every write succeeds whole.
TEST_F(AtomicFileTest, ConcurrentWritersEachWriteAWholeFile) {
    fs::path path = mDir / "shared.bin";
    std::vector<std::string> contents;
    for (int i = 0; i < 8; ++i)
        contents.push_back(std::string(4096 + i, static_cast<char>('a' + i)));
    std::vector<char> ok(contents.size(), 0);  // not vector<bool>: one byte per thread
    std::vector<std::thread> writers;
    for (size_t i = 0; i < contents.size(); ++i) {
        writers.emplace_back([&, i] {
            bool all = true;
            for (int round = 0; round < 20; ++round)
                all = writeFileAtomically(path.string(), contents[i]).ok() && all;
            ok[i] = all;
        });
    }
    for (std::thread& writer : writers) writer.join();
    for (size_t i = 0; i < ok.size(); ++i) EXPECT_TRUE(ok[i]) << "writer " << i;
    std::string final = readAll(path);
    EXPECT_NE(std::find(contents.begin(), contents.end(), final), contents.end());
    EXPECT_EQ(entriesIn(mDir), 1u);
}

// A full disk, simulated with a file-size limit (SIGXFSZ ignored, so write fails with EFBIG):
// an error, the old file intact, no temporary left.
TEST_F(AtomicFileTest, AFullDiskLeavesTheOldFileAndNoTemporary) {
    fs::path path = mDir / "out.bin";
    ASSERT_TRUE(writeFileAtomically(path.string(), "old contents").ok());
    struct rlimit saved {};
    ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &saved), 0);
    auto previous = std::signal(SIGXFSZ, SIG_IGN);
    struct rlimit limited = saved;
    limited.rlim_cur = 1024;
    ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &limited), 0);
    Status status = writeFileAtomically(path.string(), std::string(64 * 1024, 'x'));
    ::setrlimit(RLIMIT_FSIZE, &saved);
    std::signal(SIGXFSZ, previous);
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().detail.find("cannot write"), std::string::npos);
    EXPECT_EQ(readAll(path), "old contents");
    EXPECT_EQ(entriesIn(mDir), 1u);
}

TEST_F(AtomicFileTest, AReadOnlyFolderIsAnErrorWithTheReason) {
    if (::geteuid() == 0) GTEST_SKIP() << "root ignores directory permissions";
    fs::permissions(mDir, fs::perms::owner_read | fs::perms::owner_exec);
    Status status = writeFileAtomically((mDir / "out.bin").string(), "x");
    fs::permissions(mDir, fs::perms::owner_all);
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().detail.find("Permission denied"), std::string::npos);
    EXPECT_EQ(entriesIn(mDir), 0u);
}

}  // namespace
}  // namespace varc
