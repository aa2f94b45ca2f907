// SPDX-License-Identifier: Apache-2.0
#include "varc/driver/SpirvImageOffsets.h"

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <map>
#include <optional>
#include <span>

namespace varc::driver {

namespace {

constexpr size_t kHeaderWords = 5, kBoundWord = 3;
constexpr uint32_t kMagic = 0x07230203;

// Opcodes (SPIR-V specification).
enum : uint32_t {
    kOpTypeInt = 21,
    kOpTypeFloat = 22,
    kOpTypeVector = 23,
    kOpConstant = 43,
    kOpConstantComposite = 44,
    kOpConstantNull = 46,
    kOpFunction = 54,
    kOpCompositeConstruct = 80,
    kOpConvertFToS = 110,
    kOpConvertSToF = 111,
    kOpSNegate = 126,
    kOpFNegate = 127,
    kOpIAdd = 128,
    kOpFAdd = 129,
    kOpISub = 130,
    kOpFSub = 131,
    kOpIMul = 132,
    kOpFMul = 133,
};

// Image operand bits, in the order their operands follow the mask.
constexpr uint32_t kBias = 0x1, kLod = 0x2, kGrad = 0x4, kConstOffset = 0x8, kOffset = 0x10;

// The word index (from the opcode word) of the image-operands mask of the non-gather image
// instructions that may carry an offset, or 0 for every other opcode.
size_t maskWordOf(uint32_t opcode) {
    switch (opcode) {
        case 87:
        case 88:
        case 91:
        case 92:
        case 95:
        case 98:  // Sample*, Proj*, Fetch, Read
        case 305:
        case 306:
        case 309:
        case 310:
        case 313:  // their Sparse forms
            return 5;
        case 89:
        case 90:
        case 93:
        case 94:  // SampleDref*, ProjDref*
        case 307:
        case 308:
        case 311:
        case 312:
            return 6;
        default:
            return 0;
    }
}

using Values = std::vector<double>;

// The module's instructions by result id, and the constant value of an id where the chain of
// arithmetic behind it (after unrolling: constants, vector construction, integer and float
// add/sub/mul/negate, int<->float conversion) makes it one.
class ConstantEvaluator {
public:
    explicit ConstantEvaluator(std::span<const uint32_t> spirv) : mSpirv(spirv) {}

    // Records the instruction at |at| if it is one the evaluator reads: a scalar or vector type
    // (result id in word 1), or a constant or an operation it can fold (result id in word 2).
    void add(size_t at) {
        uint32_t opcode = mSpirv[at] & 0xffffu, words = mSpirv[at] >> 16;
        bool type = opcode == kOpTypeInt || opcode == kOpTypeFloat || opcode == kOpTypeVector;
        bool foldable = opcode == kOpConstant || opcode == kOpConstantComposite ||
                        opcode == kOpConstantNull || opcode == kOpCompositeConstruct ||
                        opcode == kOpConvertFToS || opcode == kOpConvertSToF ||
                        (opcode >= kOpSNegate && opcode <= kOpFMul);
        if (type && words >= (opcode == kOpTypeFloat ? 3u : 4u)) mDefinitions[mSpirv[at + 1]] = at;
        if (foldable && words >= 4) mDefinitions[mSpirv[at + 2]] = at;
    }

    // The values of |id|, component by component, or nullopt.
    std::optional<Values> evaluate(uint32_t id, int depth = 0) {
        if (depth > 64) return std::nullopt;
        if (auto known = mMemo.find(id); known != mMemo.end()) return known->second;
        std::optional<Values> values = compute(id, depth);
        mMemo[id] = values;
        return values;
    }

    // The scalar type (OpTypeInt or OpTypeFloat) of |type|'s components, and their count.
    std::optional<std::pair<uint32_t, uint32_t>> componentsOf(uint32_t type) const {
        const uint32_t* definition = find(type);
        if (!definition) return std::nullopt;
        uint32_t opcode = definition[0] & 0xffffu;
        if (opcode == kOpTypeVector) return std::pair{definition[2], definition[3]};
        if (opcode == kOpTypeInt || opcode == kOpTypeFloat) return std::pair{type, 1u};
        return std::nullopt;
    }

    bool isSignedInt(uint32_t scalarType) const {
        const uint32_t* definition = find(scalarType);
        return definition && (definition[0] & 0xffffu) == kOpTypeInt && definition[2] == 32 &&
               definition[3] == 1;
    }

    // The type id of |id|'s result, or 0.
    uint32_t typeOf(uint32_t id) const {
        const uint32_t* definition = find(id);
        return definition ? definition[1] : 0;
    }

private:
    const uint32_t* find(uint32_t id) const {
        auto it = mDefinitions.find(id);
        return it == mDefinitions.end() ? nullptr : mSpirv.data() + it->second;
    }

    std::optional<Values> compute(uint32_t id, int depth) {
        const uint32_t* words = find(id);
        if (!words) return std::nullopt;
        uint32_t opcode = words[0] & 0xffffu, count = words[0] >> 16;
        auto components = componentsOf(words[1]);
        if (!components) return std::nullopt;
        const uint32_t* scalar = find(components->first);
        if (!scalar || scalar[2] != 32) return std::nullopt;
        bool isFloat = (scalar[0] & 0xffffu) == kOpTypeFloat;
        switch (opcode) {
            case kOpConstant: {
                if (count != 4) return std::nullopt;
                if (isFloat) return Values{std::bit_cast<float>(words[3])};
                return Values{scalar[3] ? double(static_cast<int32_t>(words[3])) : words[3]};
            }
            case kOpConstantNull:
                return Values(components->second, 0.0);
            case kOpConstantComposite:
            case kOpCompositeConstruct: {
                Values all;
                for (uint32_t i = 3; i < count; ++i) {
                    std::optional<Values> part = evaluate(words[i], depth + 1);
                    if (!part) return std::nullopt;
                    all.insert(all.end(), part->begin(), part->end());
                }
                if (all.size() != components->second) return std::nullopt;
                return all;
            }
            case kOpConvertFToS:
            case kOpConvertSToF:
            case kOpSNegate:
            case kOpFNegate: {
                std::optional<Values> operand = evaluate(words[3], depth + 1);
                if (!operand) return std::nullopt;
                for (double& v : *operand) {
                    v = opcode == kOpConvertFToS ? std::trunc(v)
                                                 : (opcode == kOpConvertSToF ? v : -v);
                }
                return operand;
            }
            case kOpIAdd:
            case kOpFAdd:
            case kOpISub:
            case kOpFSub:
            case kOpIMul:
            case kOpFMul: {
                std::optional<Values> a = evaluate(words[3], depth + 1);
                std::optional<Values> b = evaluate(words[4], depth + 1);
                if (!a || !b || a->size() != b->size()) return std::nullopt;
                for (size_t i = 0; i < a->size(); ++i) {
                    double& v = (*a)[i];
                    if (opcode == kOpIAdd || opcode == kOpFAdd) v += (*b)[i];
                    if (opcode == kOpISub || opcode == kOpFSub) v -= (*b)[i];
                    if (opcode == kOpIMul || opcode == kOpFMul) v *= (*b)[i];
                }
                return a;
            }
            default:
                return std::nullopt;
        }
    }

    std::span<const uint32_t> mSpirv;
    std::map<uint32_t, size_t> mDefinitions;  // result id (or type id) -> word offset
    std::map<uint32_t, std::optional<Values>> mMemo;
};

// New OpConstant/OpConstantComposite instructions for folded offsets, under fresh ids.
class NewConstants {
public:
    explicit NewConstants(uint32_t bound) : mBound(bound) {}

    // The id of a new constant of |type| (a signed 32-bit int or a vector of them) = |values|.
    uint32_t add(uint32_t type, uint32_t scalarType, const Values& values) {
        std::vector<uint32_t> scalars;
        for (double value : values) {
            uint32_t id = mBound++;
            append(kOpConstant,
                   {scalarType, id, static_cast<uint32_t>(static_cast<int32_t>(value))});
            scalars.push_back(id);
        }
        if (values.size() == 1) return scalars[0];
        uint32_t id = mBound++;
        std::vector<uint32_t> operands{type, id};
        operands.insert(operands.end(), scalars.begin(), scalars.end());
        append(kOpConstantComposite, operands);
        return id;
    }

    const std::vector<uint32_t>& words() const { return mWords; }
    uint32_t bound() const { return mBound; }

private:
    void append(uint32_t opcode, const std::vector<uint32_t>& operands) {
        mWords.push_back(static_cast<uint32_t>((operands.size() + 1) << 16) | opcode);
        mWords.insert(mWords.end(), operands.begin(), operands.end());
    }

    uint32_t mBound;
    std::vector<uint32_t> mWords;
};

}  // namespace

std::vector<uint32_t> markConstantImageOffsets(const std::vector<uint32_t>& spirv) {
    if (spirv.size() <= kHeaderWords || spirv[0] != kMagic) return spirv;
    ConstantEvaluator evaluator(spirv);
    std::vector<size_t> starts;
    size_t firstFunction = spirv.size();
    for (size_t at = kHeaderWords; at < spirv.size();) {
        uint32_t wordCount = spirv[at] >> 16;
        if (wordCount == 0 || at + wordCount > spirv.size()) return spirv;
        starts.push_back(at);
        evaluator.add(at);
        if ((spirv[at] & 0xffffu) == kOpFunction && firstFunction == spirv.size())
            firstFunction = at;
        at += wordCount;
    }
    std::vector<uint32_t> out = spirv;
    NewConstants constants(spirv[kBoundWord]);
    bool changed = false;
    for (size_t at : starts) {
        uint32_t wordCount = spirv[at] >> 16;
        size_t maskWord = maskWordOf(spirv[at] & 0xffffu);
        if (maskWord == 0 || maskWord >= wordCount) continue;
        uint32_t mask = spirv[at + maskWord];
        if (!(mask & kOffset) || (mask & kConstOffset)) continue;
        size_t offsetWord =
            maskWord + 1 + std::popcount(mask & (kBias | kLod)) + 2 * std::popcount(mask & kGrad);
        if (offsetWord >= wordCount) continue;
        uint32_t offset = spirv[at + offsetWord];
        std::optional<Values> values = evaluator.evaluate(offset);
        uint32_t type = evaluator.typeOf(offset);
        auto components = evaluator.componentsOf(type);
        if (!values || !components || !evaluator.isSignedInt(components->first)) continue;
        out[at + offsetWord] = constants.add(type, components->first, *values);
        out[at + maskWord] = (mask & ~kOffset) | kConstOffset;
        changed = true;
    }
    if (!changed) return spirv;
    out.insert(out.begin() + static_cast<std::ptrdiff_t>(firstFunction), constants.words().begin(),
               constants.words().end());
    out[kBoundWord] = constants.bound();
    return out;
}

}  // namespace varc::driver
