// SPDX-License-Identifier: Apache-2.0
// A read-only variant pack: opened through mmap, validated up front, looked up without copies.
#include "varc/reader/Pack.h"

#include "PackImage.h"
#include "varc/core/Check.h"
#include "varc/pack/PackTables.h"
#include "varc/pack/PartialPack.h"

namespace varc::reader {

using pack::Chunk;

Pack::Pack(std::unique_ptr<detail::PackImage> image) : mImage(std::move(image)) {}
Pack::Pack(Pack&& other) noexcept = default;
Pack& Pack::operator=(Pack&& other) noexcept = default;
Pack::~Pack() = default;

Result<Pack> Pack::load(std::unique_ptr<detail::PackImage> image, const OpenOptions& options) {
    if (Status status = image->load(options); !status) return status.error();
    Pack pack(std::move(image));
    if (!options.acceptPartial) {
        for (const pack::ToolVersion& tool : pack.toolchain()) {
            if (tool.name != pack::kShardTool) continue;
            return makeError(ErrorCode::InvalidInput,
                             "a partial pack (shard " + tool.version.substr(0, tool.version.find(' ')) +
                                 " of `varc build --shard`): join the parts with `varc merge`");
        }
    }
    return pack;
}

Result<Pack> Pack::open(const std::string& path, const OpenOptions& options) {
    Result<detail::MappedFile> mapping = detail::MappedFile::map(path);
    if (!mapping) return mapping.error();
    Result<Pack> pack = load(std::make_unique<detail::PackImage>(std::move(*mapping)), options);
    if (!pack) return makeError(pack.error().code, path + ": " + pack.error().detail);
    return pack;
}

Result<Pack> Pack::fromBytes(std::span<const std::byte> bytes, const OpenOptions& options) {
    return load(std::make_unique<detail::PackImage>(bytes), options);
}

Result<Pack> Pack::fromBytes(std::string_view bytes, const OpenOptions& options) {
    return fromBytes(std::as_bytes(std::span<const char>(bytes.data(), bytes.size())), options);
}

uint16_t Pack::formatMajor() const { return mImage->header().major; }
uint16_t Pack::formatMinor() const { return mImage->header().minor; }
uint64_t Pack::inputsHash() const { return mImage->header().inputsHash; }
size_t Pack::byteSize() const { return mImage->bytes().size(); }

std::vector<pack::ToolVersion> Pack::toolchain() const {
    std::vector<pack::ToolVersion> tools;
    for (uint32_t i = 0; i < mImage->count(Chunk::Tools); ++i) {
        tools.push_back(
            {std::string(mImage->string(mImage->get(Chunk::Tools, i, pack::kToolName))),
             std::string(mImage->string(mImage->get(Chunk::Tools, i, pack::kToolVersion)))});
    }
    return tools;
}

size_t Pack::shaderCount() const { return mImage->count(Chunk::Shaders); }

ShaderView Pack::shader(size_t index) const {
    VARC_CHECK(index < shaderCount()) << "shader " << index << " of " << shaderCount();
    return ShaderView(mImage.get(), static_cast<uint32_t>(index));
}

std::optional<ShaderView> Pack::findShader(std::string_view name) const {
    auto nameAt = [&](uint32_t position) {
        uint32_t shader = mImage->get(Chunk::ShaderNames, position, pack::kShaderNameShader);
        return mImage->string(mImage->get(Chunk::Shaders, shader, pack::kShaderName));
    };
    uint32_t low = 0, high = mImage->count(Chunk::ShaderNames);
    while (low < high) {  // first position whose name is >= |name|
        uint32_t middle = low + (high - low) / 2;
        if (nameAt(middle) < name) {
            low = middle + 1;
        } else {
            high = middle;
        }
    }
    if (low == mImage->count(Chunk::ShaderNames) || nameAt(low) != name) return std::nullopt;
    return ShaderView(mImage.get(), mImage->get(Chunk::ShaderNames, low, pack::kShaderNameShader));
}

size_t Pack::programCount() const { return mImage->count(Chunk::Programs); }

ProgramView Pack::program(size_t index) const {
    VARC_CHECK(index < programCount()) << "program " << index << " of " << programCount();
    return ProgramView(mImage.get(), static_cast<uint32_t>(index));
}

}  // namespace varc::reader
