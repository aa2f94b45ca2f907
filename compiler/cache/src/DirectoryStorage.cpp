// SPDX-License-Identifier: Apache-2.0
#include "varc/cache/DirectoryStorage.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <vector>

#include "varc/core/AtomicFile.h"
#include "varc/core/FileRead.h"

namespace varc::cache {

namespace {

namespace fs = std::filesystem;

// Entries are "<32 hex>.<kind>" in a folder named after their first two characters; nothing
// else in the folder is varc's.
bool isEntry(const fs::directory_entry& entry) {
    std::string name = entry.path().filename().string();
    std::string folder = entry.path().parent_path().filename().string();
    size_t dot = name.find('.');
    return entry.is_regular_file() && dot == 32 && folder.size() == 2 &&
           name.compare(0, 2, folder) == 0 && name.find_first_not_of("0123456789abcdef") == 32 &&
           (name.substr(dot) == ".program" || name.substr(dot) == ".source" ||
            name.substr(dot) == ".manifest" || name.substr(dot) == ".pack");
}

// Bundles are "<16 hex>.bundle" directly in the bundles folder.
bool isBundle(const fs::directory_entry& entry) {
    std::string name = entry.path().filename().string();
    return entry.is_regular_file() && name.size() == 16 + 7 &&
           name.find_first_not_of("0123456789abcdef") == 16 && name.substr(16) == ".bundle";
}

// The bundle files in |folder|, sorted (so every process reads them in the same order).
std::vector<std::string> bundlesIn(const std::string& folder) {
    std::vector<std::string> paths;
    std::error_code error;
    for (fs::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
        if (isBundle(*it)) paths.push_back(it->path().string());
    }
    std::sort(paths.begin(), paths.end());
    return paths;
}

// Reads |length| bytes at |offset| of |path|; nullopt when the file is shorter or unreadable.
std::optional<std::string> readAt(const std::string& path, uint64_t offset, uint64_t length) {
    int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return std::nullopt;
    std::string bytes(length, '\0');
    size_t done = 0;
    while (done < length) {
        ssize_t got = ::pread(fd, bytes.data() + done, length - done,
                              static_cast<off_t>(offset + done));
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) break;
        done += static_cast<size_t>(got);
    }
    ::close(fd);
    if (done != length) return std::nullopt;
    return bytes;
}

// The header and index of the bundle at |path| (empty when it is not a readable bundle).
std::vector<BundleSlot> readBundleIndex(const std::string& path) {
    std::error_code error;
    const uint64_t size = fs::file_size(path, error);
    if (error) return {};
    std::optional<std::string> header = readAt(path, 0, std::min<uint64_t>(size, kBundleHeaderBytes));
    if (!header) return {};
    const uint64_t end = bundleIndexEnd(*header);
    if (end == 0 || end > size) return {};
    std::optional<std::string> index = readAt(path, 0, end);
    if (!index) return {};
    return decodeBundleIndex(*index, size);
}

// Visits every entry under |directory|; false (with |error| set) when it cannot be read.
template <typename Visit>
bool forEachEntry(const std::string& directory, std::error_code& error, Visit visit) {
    if (!fs::exists(directory, error)) return !error;
    for (fs::recursive_directory_iterator it(directory, error), end; !error && it != end;
         it.increment(error)) {
        if (it.depth() == 1 && isEntry(*it)) visit(*it);
    }
    return !error;
}

}  // namespace

DirectoryStorage::DirectoryStorage(std::string directory, std::string name, bool readOnly)
    : CacheStorage(std::move(name), readOnly), mDirectory(std::move(directory)) {}

std::string DirectoryStorage::pathOf(std::string_view key) const {
    return mDirectory + "/" + std::string(key.substr(0, 2)) + "/" + std::string(key);
}

std::optional<std::string> DirectoryStorage::get(std::string_view key) {
    // A missing, unreadable or damaged file is a miss, never an error.
    Result<std::string> bytes = readFile(pathOf(key));
    if (!bytes) return getFromBundle(key);
    countRead(bytes->size());
    return std::move(*bytes);
}

std::optional<std::string> DirectoryStorage::getFromBundle(std::string_view key) {
    std::string path;
    BundleValue value;
    {
        std::lock_guard<std::mutex> lock(mBundleMutex);
        loadBundleIndexLocked();
        auto found = mBundleValues.find(std::string(key));
        if (found == mBundleValues.end()) return std::nullopt;
        value = found->second;
        path = mBundlePaths[value.bundle];
    }
    std::optional<std::string> bytes = readAt(path, value.offset, value.length);
    if (bytes) countRead(bytes->size());
    return bytes;
}

void DirectoryStorage::loadBundleIndexLocked() {
    if (mBundlesLoaded) return;
    mBundlesLoaded = true;
    for (const std::string& path : bundlesIn(bundleFolder())) {
        indexBundleLocked(path, readBundleIndex(path));
    }
}

void DirectoryStorage::indexBundleLocked(const std::string& path,
                                         const std::vector<BundleSlot>& slots) {
    const size_t bundle = mBundlePaths.size();
    mBundlePaths.push_back(path);
    for (const BundleSlot& slot : slots) {
        mBundleValues[slot.key] = {bundle, slot.offset, slot.length};
    }
}

Status DirectoryStorage::putMany(const std::vector<CacheEntry>& entries) {
    if (entries.size() < kBundleMinEntries) return CacheStorage::putMany(entries);
    const std::string bytes = encodeBundle(entries);
    // Named after its contents: the same write-back from two builds makes one file.
    char name[17];
    std::snprintf(name, sizeof(name), "%016llx",
                  static_cast<unsigned long long>(std::hash<std::string_view>{}(bytes)));
    const std::string path = bundleFolder() + "/" + name + ".bundle";
    std::error_code error;
    fs::create_directories(bundleFolder(), error);
    if (error) {
        return makeError(ErrorCode::IoError, "cannot create the program cache folder " +
                                                 bundleFolder() + ": " + error.message());
    }
    Status written = writeFileAtomically(path, bytes, Durability::Unsynced);
    if (!written) return written;
    for (const CacheEntry& entry : entries) countWrite(entry.value.size());
    std::lock_guard<std::mutex> lock(mBundleMutex);
    loadBundleIndexLocked();
    if (std::find(mBundlePaths.begin(), mBundlePaths.end(), path) == mBundlePaths.end()) {
        indexBundleLocked(path, decodeBundleIndex(bytes, bytes.size()));
    }
    return Ok{};
}

Status DirectoryStorage::put(std::string_view key, std::string_view value) {
    const std::string path = pathOf(key);
    std::error_code error;
    fs::create_directories(fs::path(path).parent_path(), error);
    if (error) {
        return makeError(ErrorCode::IoError, "cannot create the program cache folder for " + path +
                                                 ": " + error.message());
    }
    // No fsync: an entry a crash leaves torn fails its checksum and is a miss (ccache does the
    // same); an fsync per entry would cost more than reading the entry back saves.
    Status written = writeFileAtomically(path, value, Durability::Unsynced);
    if (written) countWrite(value.size());
    return written;
}

Result<CacheUsage> DirectoryStorage::usage() {
    CacheUsage usage;
    std::error_code error;
    if (!forEachEntry(mDirectory, error, [&](const fs::directory_entry& entry) {
            ++usage.entries;
            std::error_code sizeError;
            uintmax_t size = entry.file_size(sizeError);
            if (!sizeError) usage.bytes += size;
        })) {
        return makeError(ErrorCode::IoError, "cannot read " + mDirectory + ": " + error.message());
    }
    for (const std::string& path : bundlesIn(bundleFolder())) {
        usage.entries += readBundleIndex(path).size();
        std::error_code sizeError;
        uintmax_t size = fs::file_size(path, sizeError);
        if (!sizeError) usage.bytes += size;
    }
    return usage;
}

Result<uint64_t> DirectoryStorage::clear() {
    // Each file with the number of entries it holds.
    std::vector<std::pair<fs::path, uint64_t>> files;
    std::error_code error;
    if (!forEachEntry(mDirectory, error, [&](const fs::directory_entry& entry) {
            files.emplace_back(entry.path(), 1);
        })) {
        return makeError(ErrorCode::IoError, "cannot read " + mDirectory + ": " + error.message());
    }
    for (const std::string& path : bundlesIn(bundleFolder())) {
        files.emplace_back(path, readBundleIndex(path).size());
    }
    {
        std::lock_guard<std::mutex> lock(mBundleMutex);
        mBundlesLoaded = false;
        mBundlePaths.clear();
        mBundleValues.clear();
    }
    uint64_t removed = 0;
    for (const auto& [path, entries] : files) {
        if (!fs::remove(path, error)) {
            return makeError(ErrorCode::IoError,
                             "cannot remove " + path.string() + ": " + error.message());
        }
        removed += entries;
    }
    return removed;
}

}  // namespace varc::cache
