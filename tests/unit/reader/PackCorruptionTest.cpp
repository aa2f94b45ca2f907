// SPDX-License-Identifier: Apache-2.0
// The reader rejects every truncation and every single-byte corruption of a valid pack, cleanly.
#include <gtest/gtest.h>

#include <string>

#include "PackTestData.h"
#include "varc/pack/PackFormat.h"
#include "varc/packwriter/PackWriter.h"
#include "varc/reader/Pack.h"
#include "varc/reader/PackDecoder.h"
#include "varc/reader/PassView.h"

namespace varc {
namespace {

using reader::Pack;

// Small on purpose: every byte position is tried.
const std::string& samplePack() {
    static const std::string bytes = packwriter::serializePack(
        packtest::makeSampleContents(), {.dictionary = packwriter::PackDictionary::Always});
    return bytes;
}

std::string errorOf(const std::string& bytes) {
    Result<Pack> pack = Pack::fromBytes(bytes);
    return pack.ok() ? "" : pack.error().detail;
}

// Uses everything a pack offers, so that a pack accepted by open() is exercised fully.
void touchEverything(const Pack& pack) {
    for (size_t s = 0; s < pack.shaderCount(); ++s) {
        reader::ShaderView shader = pack.shader(s);
        (void)pack.findShader(shader.name());
        for (size_t p = 0; p < shader.passCount(); ++p) {
            reader::PassView pass = *shader.pass(p);
            (void)pass.renderState();
            for (auto policy :
                 {variants::SelectionPolicy::Exact, variants::SelectionPolicy::Closest,
                  variants::SelectionPolicy::First, variants::SelectionPolicy::Strict}) {
                (void)pass.lookup(std::vector<std::string>{"DIRECTIONAL", "SPOT"}, policy);
            }
            for (size_t v = 0; v < pass.variantCount(); ++v) (void)pass.variant(v).describe();
        }
    }
    (void)reader::decodePack(pack);
}

TEST(PackCorruption, ValidPackOpens) { EXPECT_EQ(errorOf(samplePack()), ""); }

TEST(PackCorruption, EveryTruncatedPrefixIsRejected) {
    const std::string& bytes = samplePack();
    for (size_t size = 0; size < bytes.size(); ++size) {
        Result<Pack> pack = Pack::fromBytes(bytes.substr(0, size));
        ASSERT_FALSE(pack.ok()) << "prefix of " << size << " bytes was accepted";
        EXPECT_EQ(pack.error().code, ErrorCode::InvalidInput);
        EXPECT_NE(pack.error().detail.find("truncated"), std::string::npos)
            << size << ": " << pack.error().detail;
    }
}

TEST(PackCorruption, EverySingleByteCorruptionIsRejected) {
    const std::string& original = samplePack();
    for (int mask : {0x01, 0xff, 0x80}) {
        for (size_t i = 0; i < original.size(); ++i) {
            std::string bytes = original;
            bytes[i] = static_cast<char>(bytes[i] ^ mask);
            Result<Pack> pack = Pack::fromBytes(bytes);
            ASSERT_FALSE(pack.ok()) << "byte " << i << " ^ " << mask << " was accepted";
            EXPECT_NE(pack.error().code, ErrorCode::Internal);
        }
    }
}

TEST(PackCorruption, TrailingBytesAreRejected) {
    EXPECT_NE(errorOf(samplePack() + std::string(8, '\0')).find("trailing"), std::string::npos);
}

// Without checksums, corruptions reach the structural checks and the accessors: whatever is
// accepted must be usable without crashing (run under ASan/UBSan to make this meaningful).
TEST(PackCorruption, WithoutChecksumsCorruptionsNeverCrash) {
    const std::string& original = samplePack();
    size_t accepted = 0;
    for (int mask : {0x01, 0xff}) {
        for (size_t i = 0; i < original.size(); ++i) {
            std::string bytes = original;
            bytes[i] = static_cast<char>(bytes[i] ^ mask);
            Result<Pack> pack = Pack::fromBytes(bytes, {.verifyChecksums = false});
            if (!pack.ok()) continue;
            ++accepted;
            touchEverything(*pack);
        }
    }
    EXPECT_GT(accepted, 0u);  // e.g. changes inside string bytes or SPIR-V
}

TEST(PackCorruption, ErrorNamesBadMagic) {
    std::string bytes = samplePack();
    bytes[0] = 'X';
    EXPECT_NE(errorOf(bytes).find("bad magic"), std::string::npos);
    EXPECT_NE(errorOf("hello").find("bad magic"), std::string::npos);
    EXPECT_NE(errorOf("").find("truncated"), std::string::npos);
}

TEST(PackCorruption, ErrorNamesUnsupportedVersion) {
    std::string bytes = samplePack();
    bytes[pack::kHeaderMajor] = 2;
    Result<Pack> pack = Pack::fromBytes(bytes);
    ASSERT_FALSE(pack.ok());
    EXPECT_EQ(pack.error().code, ErrorCode::Unsupported);
    EXPECT_NE(pack.error().detail.find("unsupported pack version 2." +
                                       std::to_string(pack::kVersionMinor)),
              std::string::npos)
        << pack.error().detail;
}

TEST(PackCorruption, NewerMinorVersionIsReadWhenChecksumsMatch) {
    std::string bytes = samplePack();
    bytes[pack::kHeaderMinor] = static_cast<char>(pack::kVersionMinor + 1);
    // Only the header checksum changes; a reader of 1.n reads 1.(n+1).
    EXPECT_NE(errorOf(bytes).find("checksum mismatch in the pack header"), std::string::npos);
    EXPECT_TRUE(Pack::fromBytes(bytes, {.verifyChecksums = false}).ok());
}

TEST(PackCorruption, ErrorNamesTruncation) {
    std::string bytes = samplePack();
    std::string detail = errorOf(bytes.substr(0, bytes.size() - 1));
    EXPECT_NE(detail.find("truncated pack: " + std::to_string(bytes.size() - 1) + " bytes"),
              std::string::npos)
        << detail;
}

TEST(PackCorruption, ErrorNamesChecksumMismatchAndChunk) {
    std::string bytes = samplePack();
    bytes[bytes.size() - 1] ^= 0x01;  // inside the last chunk
    EXPECT_NE(errorOf(bytes).find("checksum mismatch in chunk"), std::string::npos);
    std::string header = samplePack();
    header[pack::kHeaderInputsHash] ^= 0x01;
    EXPECT_NE(errorOf(header).find("checksum mismatch in the pack header"), std::string::npos);
}

TEST(PackCorruption, OpenNamesThePathAndMissingFiles) {
    Result<Pack> missing = Pack::open("/nonexistent/dir/x.vpk");
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().code, ErrorCode::IoError);
    EXPECT_NE(missing.error().detail.find("/nonexistent/dir/x.vpk"), std::string::npos);
}

}  // namespace
}  // namespace varc
