// SPDX-License-Identifier: Apache-2.0
#include "varc/driver/ProgramCache.h"

#include <elf.h>
#include <link.h>
#include <xxhash.h>

#include <cerrno>
#include <cstring>

#include "varc/core/FileRead.h"
#include "varc/core/HexText.h"

namespace varc::driver {

namespace {

// Entry layout, little-endian: magic (8 bytes: "VARCPRG1" for programs, "VARCSRC1" for pruned
// sources), key (low, high), the payload, then the XXH64 of everything before it. A program's
// payload: u32 log bytes, u32 semantics, u32 SPIR-V words, u32 stripped words, the log, per
// semantic (u32 location, u32 length, bytes), the words, the stripped words. A source's payload:
// the pruned text.
constexpr std::string_view kProgramMagic = "VARCPRG2";
constexpr std::string_view kSourceMagic = "VARCSRC1";
constexpr size_t kEntryOverhead = 8 + 16 + 8;
constexpr uint32_t kMaxField = 1u << 30;  // no real entry comes near; bounds corrupt sizes

void putU32(std::string& out, uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
}

void putU64(std::string& out, uint64_t v) {
    putU32(out, static_cast<uint32_t>(v));
    putU32(out, static_cast<uint32_t>(v >> 32));
}

// Bounds-checked little-endian reads over an entry's bytes.
class Reader {
public:
    explicit Reader(std::string_view bytes) : mBytes(bytes) {}
    bool u32(uint32_t& v) {
        if (mBytes.size() - mOffset < 4) return false;
        v = 0;
        for (int i = 0; i < 4; ++i) {
            v |= static_cast<uint32_t>(static_cast<unsigned char>(mBytes[mOffset + i])) << (8 * i);
        }
        mOffset += 4;
        return true;
    }
    bool u64(uint64_t& v) {
        uint32_t low = 0, high = 0;
        if (!u32(low) || !u32(high)) return false;
        v = low | (static_cast<uint64_t>(high) << 32);
        return true;
    }
    bool bytes(size_t n, std::string_view& out) {
        if (mBytes.size() - mOffset < n) return false;
        out = mBytes.substr(mOffset, n);
        mOffset += n;
        return true;
    }
    size_t offset() const { return mOffset; }

private:
    std::string_view mBytes;
    size_t mOffset = 0;
};

ProgramCacheKey hash128(std::string_view bytes) {
    XXH128_hash_t hash = XXH3_128bits(bytes.data(), bytes.size());
    return {hash.low64, hash.high64};
}

// A file's bytes, or nullopt when it cannot be read (a missing, damaged or unreadable entry is
// a miss, never an error).
std::optional<std::string> readBytes(const std::string& path) {
    Result<std::string> bytes = readFile(path);
    if (!bytes) return std::nullopt;
    return std::move(*bytes);
}

// The GNU build ID the linker stamped into the main executable (a hash of its contents), or "".
std::string buildId() {
    std::string id;
    dl_iterate_phdr(
        [](dl_phdr_info* info, size_t, void* out) -> int {
            // The first object reported is the main program.
            for (ElfW(Half) i = 0; i < info->dlpi_phnum; ++i) {
                const ElfW(Phdr)& header = info->dlpi_phdr[i];
                if (header.p_type != PT_NOTE) continue;
                const char* note = reinterpret_cast<const char*>(info->dlpi_addr + header.p_vaddr);
                const char* end = note + header.p_memsz;
                while (note + sizeof(ElfW(Nhdr)) <= end) {
                    ElfW(Nhdr) n;
                    std::memcpy(&n, note, sizeof(n));
                    const char* name = note + sizeof(n);
                    const char* desc = name + ((n.n_namesz + 3) & ~3u);
                    if (desc + n.n_descsz > end) break;
                    if (n.n_type == NT_GNU_BUILD_ID && n.n_namesz == 4 &&
                        std::memcmp(name, "GNU", 4) == 0) {
                        static_cast<std::string*>(out)->assign(desc, n.n_descsz);
                        return 1;
                    }
                    note = desc + ((n.n_descsz + 3) & ~3u);
                }
            }
            return 1;
        },
        &id);
    return id;
}

// Identifies the running executable: its build ID, or else a hash of its bytes; either changes
// whenever varc (or a library it links statically) is rebuilt from other sources.
ProgramCacheKey executableHash() {
    std::string id = buildId();
    if (!id.empty()) return hash128("build-id:" + id);
    std::optional<std::string> bytes = readBytes("/proc/self/exe");
    return hash128(bytes ? *bytes : std::string("varc " VARC_VERSION));
}

}  // namespace

std::string ProgramCacheKey::hex() const { return hex64(high) + hex64(low); }

namespace {

// The payload of a sound entry for |key| (see the layout above), or nullopt.
std::optional<std::string_view> payloadOf(std::string_view bytes, const ProgramCacheKey& key,
                                          std::string_view magic) {
    if (bytes.size() < kEntryOverhead) return std::nullopt;
    std::string_view body = bytes.substr(0, bytes.size() - 8);
    Reader checksum(bytes.substr(bytes.size() - 8));
    uint64_t expected = 0;
    if (!checksum.u64(expected) || XXH64(body.data(), body.size(), 0) != expected)
        return std::nullopt;
    Reader in(body);
    std::string_view storedMagic;
    ProgramCacheKey stored;
    if (!in.bytes(magic.size(), storedMagic) || storedMagic != magic || !in.u64(stored.low) ||
        !in.u64(stored.high) || !(stored == key)) {
        return std::nullopt;
    }
    return body.substr(in.offset());
}

// A program entry's payload (see the layout above) as a CachedProgram, or nullopt.
std::optional<CachedProgram> parseProgram(std::string_view payload) {
    Reader in(payload);
    uint32_t logBytes = 0, semantics = 0, words = 0, strippedWords = 0;
    if (!in.u32(logBytes) || !in.u32(semantics) || !in.u32(words) || !in.u32(strippedWords) ||
        logBytes > kMaxField || semantics > kMaxField || words > kMaxField ||
        strippedWords > kMaxField) {
        return std::nullopt;
    }
    CachedProgram program;
    std::string_view log;
    if (!in.bytes(logBytes, log)) return std::nullopt;
    program.log = log;
    for (uint32_t i = 0; i < semantics; ++i) {
        uint32_t location = 0, length = 0;
        std::string_view name;
        if (!in.u32(location) || !in.u32(length) || !in.bytes(length, name)) return std::nullopt;
        program.semantics.emplace(location, std::string(name));
    }
    program.spirv.resize(words);
    for (uint32_t& word : program.spirv) {
        if (!in.u32(word)) return std::nullopt;
    }
    program.stripped.resize(strippedWords);
    for (uint32_t& word : program.stripped) {
        if (!in.u32(word)) return std::nullopt;
    }
    if (in.offset() != payload.size() || program.spirv.empty() || program.stripped.empty()) {
        return std::nullopt;
    }
    return program;
}

}  // namespace

ProgramCache::ProgramCache(std::shared_ptr<cache::CacheChain> chain)
    : mChain(std::move(chain)), mToolchain(executableHash()) {}

ProgramCacheKey ProgramCache::hashText(std::string_view text) { return hash128(text); }

ProgramCacheKey ProgramCache::executableKey() {
    static const ProgramCacheKey key = executableHash();
    return key;
}

ProgramCacheKey ProgramCache::keyOf(const ProgramCacheInput& input) const {
    std::string text(kProgramMagic);
    putU64(text, mToolchain.low);
    putU64(text, mToolchain.high);
    putU32(text, static_cast<uint32_t>(input.optimization));
    putU32(text, static_cast<uint32_t>(input.language));
    putU32(text, static_cast<uint32_t>(input.stage));
    putU32(text, static_cast<uint32_t>(input.entryPoint.size()));
    text += input.entryPoint;
    text += input.text;
    return hash128(text);
}

ProgramCacheKey ProgramCache::sourceKeyOf(const SourceCacheInput& input) const {
    std::string text(kSourceMagic);
    putU64(text, mToolchain.low);
    putU64(text, mToolchain.high);
    putU64(text, input.passText.low);
    putU64(text, input.passText.high);
    putU32(text, static_cast<uint32_t>(input.language));
    putU32(text, static_cast<uint32_t>(input.stage));
    putU32(text, (input.pruned ? 1 : 0) | (input.withoutUnreachable ? 2 : 0));
    putU32(text, static_cast<uint32_t>(input.entryPoint.size()));
    text += input.entryPoint;
    text += input.preamble;
    return hash128(text);
}

std::string ProgramCache::entryName(const ProgramCacheKey& key, std::string_view extension) {
    return key.hex() + std::string(extension);
}

std::vector<std::optional<std::string>> ProgramCache::loadPayloads(
    const std::vector<ProgramCacheKey>& keys, std::string_view magic,
    std::string_view extension) const {
    std::vector<std::string> names;
    names.reserve(keys.size());
    for (const ProgramCacheKey& key : keys) names.push_back(entryName(key, extension));
    std::vector<std::optional<std::string>> entries =
        mChain->getMany(names, [&](size_t k, std::string_view bytes) {
            return payloadOf(bytes, keys[k], magic).has_value();
        });
    for (size_t k = 0; k < keys.size(); ++k) {
        if (entries[k]) entries[k] = std::string(*payloadOf(*entries[k], keys[k], magic));
    }
    return entries;
}

Status ProgramCache::storePayload(const ProgramCacheKey& key, std::string_view magic,
                                  std::string_view extension, std::string_view payload) const {
    std::string bytes(magic);
    putU64(bytes, key.low);
    putU64(bytes, key.high);
    bytes += payload;
    putU64(bytes, XXH64(bytes.data(), bytes.size(), 0));
    return mChain->put(entryName(key, extension), bytes);
}

void ProgramCache::prefetch(const std::vector<ProgramCacheKey>& keys) const {
    std::vector<std::optional<std::string>> payloads =
        loadPayloads(keys, kProgramMagic, ".program");
    std::lock_guard<std::mutex> lock(mPrefetchMutex);
    for (size_t k = 0; k < keys.size(); ++k) mPrefetched[keys[k].hex()] = std::move(payloads[k]);
}

std::optional<CachedProgram> ProgramCache::load(const ProgramCacheKey& key) const {
    std::optional<std::string> payload;
    bool prefetched = false;
    {
        std::lock_guard<std::mutex> lock(mPrefetchMutex);
        if (auto it = mPrefetched.find(key.hex()); it != mPrefetched.end()) {
            prefetched = true;
            payload = std::move(it->second);
            mPrefetched.erase(it);
        }
    }
    if (!prefetched) payload = std::move(loadPayloads({key}, kProgramMagic, ".program")[0]);
    if (!payload) return std::nullopt;
    return parseProgram(*payload);
}

Status ProgramCache::store(const ProgramCacheKey& key, const CachedProgram& program) const {
    std::string payload;
    putU32(payload, static_cast<uint32_t>(program.log.size()));
    putU32(payload, static_cast<uint32_t>(program.semantics.size()));
    putU32(payload, static_cast<uint32_t>(program.spirv.size()));
    putU32(payload, static_cast<uint32_t>(program.stripped.size()));
    payload += program.log;
    for (const auto& [location, name] : program.semantics) {
        putU32(payload, location);
        putU32(payload, static_cast<uint32_t>(name.size()));
        payload += name;
    }
    for (uint32_t word : program.spirv) putU32(payload, word);
    for (uint32_t word : program.stripped) putU32(payload, word);
    return storePayload(key, kProgramMagic, ".program", payload);
}

std::optional<std::string> ProgramCache::loadSource(const ProgramCacheKey& key) const {
    return std::move(loadPayloads({key}, kSourceMagic, ".source")[0]);
}

std::vector<std::optional<std::string>> ProgramCache::loadSources(
    const std::vector<ProgramCacheKey>& keys) const {
    return loadPayloads(keys, kSourceMagic, ".source");
}

Status ProgramCache::storeSource(const ProgramCacheKey& key, std::string_view text) const {
    return storePayload(key, kSourceMagic, ".source", text);
}

}  // namespace varc::driver
