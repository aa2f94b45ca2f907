// SPDX-License-Identifier: Apache-2.0
// A read-only variant pack: opened through mmap, validated up front, looked up without copies.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "varc/core/Result.h"
#include "varc/pack/PackModel.h"
#include "varc/reader/ProgramView.h"
#include "varc/reader/ShaderView.h"

namespace varc::reader {

namespace detail {
class PackImage;
}

struct OpenOptions {
    // Verify the XXH3 checksums of the header and of every chunk (reads every byte once).
    // Structure is always validated; turning this off only serves fuzzing the structural checks.
    bool verifyChecksums = true;
    // Build a hash index over the keys of every pass with 64 or more variants (16 bytes per
    // variant), so exact lookups take one probe instead of a binary search. Off: less memory.
    bool indexKeys = true;
    // Accept a partial pack (`varc build --shard K/N`, PartialPack.h), whose placeholder programs
    // are not SPIR-V: only for `varc merge`. Off: a part is rejected with an error that says so.
    bool acceptPartial = false;
};

// Thread-safety contract: a Pack and every view obtained from it are immutable after open()
// returns; any number of threads may look up variants and read SPIR-V, reflection and render
// state concurrently without locking. Lazily built data (decompressed blobs, enumeration-order
// keys for non-exact lookups) is built exactly once under std::call_once and never changes
// afterwards. Views and spans stay valid while the Pack lives (moving the Pack keeps them
// valid); none survive its destruction.
//
// Allocation contract: exact hits of PassView::lookup(VariantKey or keyword names) and every
// accessor returning a view, string_view or span allocate nothing; misses allocate (for
// the error message, or the first enumeration-order key list of a pass), as do light lookups
// (variants::lightKeywords returns a vector) and accessors returning pack:: structs.
class Pack {
public:
    // Maps |path| read-only and validates it completely: magic, version, size against the
    // header ("truncated"), header and chunk checksums, chunk layout, every table field, index,
    // range and string, key order, blob bounds. After success no accessor can fail on the pack's
    // structure; blob decompression (lazy) is the only remaining failure. Errors name |path| and
    // the problem: "pack.vpk: bad magic: not a varc pack", "...: unsupported pack version 2.0",
    // "...: truncated pack: 100 bytes, but the header's file size needs 4096",
    // "...: checksum mismatch in chunk PASS", "...: a partial pack (shard 2/4 of `varc build
    // --shard`): join the parts with `varc merge`". IoError when the file cannot be opened or
    // mapped.
    static Result<Pack> open(const std::string& path, const OpenOptions& options = {});

    // As open(), from bytes in memory, which are copied (into 8-aligned storage). For tests and
    // fuzzing.
    static Result<Pack> fromBytes(std::span<const std::byte> bytes,
                                  const OpenOptions& options = {});
    static Result<Pack> fromBytes(std::string_view bytes, const OpenOptions& options = {});

    Pack(Pack&& other) noexcept;
    Pack& operator=(Pack&& other) noexcept;
    ~Pack();

    uint16_t formatMajor() const;
    uint16_t formatMinor() const;
    uint64_t inputsHash() const;
    size_t byteSize() const;
    std::vector<pack::ToolVersion> toolchain() const;

    size_t shaderCount() const;
    // Shader |index| < shaderCount() (checked with VARC_CHECK).
    ShaderView shader(size_t index) const;
    // The shader called |name| (binary search over the name index); the first one when names
    // repeat; nullopt when absent.
    std::optional<ShaderView> findShader(std::string_view name) const;

    size_t programCount() const;
    // Program |index| < programCount() (checked with VARC_CHECK).
    ProgramView program(size_t index) const;

private:
    explicit Pack(std::unique_ptr<detail::PackImage> image);
    static Result<Pack> load(std::unique_ptr<detail::PackImage> image, const OpenOptions& options);

    std::unique_ptr<detail::PackImage> mImage;
};

}  // namespace varc::reader
