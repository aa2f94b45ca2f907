// SPDX-License-Identifier: Apache-2.0
#include "varc/cache/DirectoryStorage.h"

#include <filesystem>
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
           (name.substr(dot) == ".program" || name.substr(dot) == ".source");
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
    if (!bytes) return std::nullopt;
    countRead(bytes->size());
    return std::move(*bytes);
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
    return usage;
}

Result<uint64_t> DirectoryStorage::clear() {
    std::vector<fs::path> entries;
    std::error_code error;
    if (!forEachEntry(mDirectory, error,
                      [&](const fs::directory_entry& entry) { entries.push_back(entry.path()); })) {
        return makeError(ErrorCode::IoError, "cannot read " + mDirectory + ": " + error.message());
    }
    uint64_t removed = 0;
    for (const fs::path& path : entries) {
        if (!fs::remove(path, error)) {
            return makeError(ErrorCode::IoError,
                             "cannot remove " + path.string() + ": " + error.message());
        }
        ++removed;
    }
    return removed;
}

}  // namespace varc::cache
