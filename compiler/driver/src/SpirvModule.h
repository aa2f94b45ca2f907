// SPDX-License-Identifier: Apache-2.0
// A read-only index over a SPIR-V binary: names, decorations, types, variables, entry points.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace varc::driver {

// SPIR-V enumerants this index uses (from the SPIR-V 1.0 specification).
namespace spv_consts {
inline constexpr uint32_t kMagic = 0x07230203;
enum Op : uint32_t {
    OpName = 5,
    OpMemberName = 6,
    OpEntryPoint = 15,
    OpTypeVoid = 19,
    OpTypeBool = 20,
    OpTypeInt = 21,
    OpTypeFloat = 22,
    OpTypeVector = 23,
    OpTypeMatrix = 24,
    OpTypeImage = 25,
    OpTypeSampler = 26,
    OpTypeSampledImage = 27,
    OpTypeArray = 28,
    OpTypeRuntimeArray = 29,
    OpTypeStruct = 30,
    OpTypePointer = 32,
    OpConstant = 43,
    OpVariable = 59,
    OpDecorate = 71,
    OpMemberDecorate = 72,
    OpDecorateString = 5632,
    OpMemberDecorateString = 5633,
};
enum Decoration : uint32_t {
    Block = 2,
    BufferBlock = 3,
    RowMajor = 4,
    ColMajor = 5,
    ArrayStride = 6,
    MatrixStride = 7,
    BuiltIn = 11,
    Location = 30,
    Binding = 33,
    DescriptorSet = 34,
    Offset = 35,
    UserSemantic = 5635,
};
enum StorageClass : uint32_t {
    UniformConstant = 0,
    Input = 1,
    Uniform = 2,
    Output = 3,
    PushConstant = 9,
    StorageBuffer = 12,
};
}  // namespace spv_consts

// One instruction's decorations: decoration -> its first literal (or the string for strings).
struct Decorations {
    std::map<uint32_t, uint32_t> values;
    std::map<uint32_t, std::string> strings;
    bool has(uint32_t decoration) const { return values.count(decoration) > 0; }
    uint32_t get(uint32_t decoration, uint32_t fallback = 0) const;
};

struct SpirvType {
    uint32_t op = 0;
    std::vector<uint32_t> operands;  // the instruction's words after the result id
};

struct SpirvVariable {
    uint32_t id = 0;
    uint32_t pointerType = 0;
    uint32_t storageClass = 0;
};

// Parses once; queries are by result id. Malformed binaries give nullopt from parse().
class SpirvModule {
public:
    static std::optional<SpirvModule> parse(std::span<const uint32_t> words);

    std::string name(uint32_t id) const;
    std::string memberName(uint32_t structId, uint32_t member) const;
    const Decorations& decorations(uint32_t id) const;
    const Decorations& memberDecorations(uint32_t structId, uint32_t member) const;
    const SpirvType* type(uint32_t id) const;
    std::optional<uint32_t> constant(uint32_t id) const;  // 32-bit scalar constants
    const std::vector<SpirvVariable>& variables() const { return mVariables; }
    // The type a pointer type points to, or 0.
    uint32_t pointee(uint32_t pointerType) const;

private:
    void record(uint32_t op, std::span<const uint32_t> operands);

    std::map<uint32_t, std::string> mNames;
    std::map<std::pair<uint32_t, uint32_t>, std::string> mMemberNames;
    std::map<uint32_t, Decorations> mDecorations;
    std::map<std::pair<uint32_t, uint32_t>, Decorations> mMemberDecorations;
    std::map<uint32_t, SpirvType> mTypes;
    std::map<uint32_t, uint32_t> mConstants;
    std::vector<SpirvVariable> mVariables;
};

}  // namespace varc::driver
