// SPDX-License-Identifier: Apache-2.0
// A read-only index over a SPIR-V binary: names, decorations, types, variables, entry points.
#include "SpirvModule.h"

namespace varc::driver {

using namespace spv_consts;

namespace {

// A literal string occupies words from |at|: bytes in little-endian order, NUL-terminated.
std::string literalString(std::span<const uint32_t> words, size_t at) {
    std::string text;
    for (size_t i = at; i < words.size(); ++i) {
        for (int byte = 0; byte < 4; ++byte) {
            char c = static_cast<char>((words[i] >> (8 * byte)) & 0xffu);
            if (c == '\0') return text;
            text += c;
        }
    }
    return text;
}

const Decorations kNoDecorations;

bool isType(uint32_t op) { return (op >= OpTypeVoid && op <= OpTypeStruct) || op == OpTypePointer; }

}  // namespace

uint32_t Decorations::get(uint32_t decoration, uint32_t fallback) const {
    auto it = values.find(decoration);
    return it == values.end() ? fallback : it->second;
}

std::optional<SpirvModule> SpirvModule::parse(std::span<const uint32_t> words) {
    if (words.size() < 5 || words[0] != kMagic) return std::nullopt;
    SpirvModule module;
    for (size_t at = 5; at < words.size();) {
        uint32_t count = words[at] >> 16;
        uint32_t op = words[at] & 0xffffu;
        if (count == 0 || at + count > words.size()) return std::nullopt;
        module.record(op, words.subspan(at + 1, count - 1));
        at += count;
    }
    return module;
}

void SpirvModule::record(uint32_t op, std::span<const uint32_t> operands) {
    if (operands.empty()) return;
    if (op == OpName) {
        mNames[operands[0]] = literalString(operands, 1);
    } else if (op == OpMemberName && operands.size() >= 2) {
        mMemberNames[{operands[0], operands[1]}] = literalString(operands, 2);
    } else if (op == OpDecorate && operands.size() >= 2) {
        mDecorations[operands[0]].values[operands[1]] = operands.size() > 2 ? operands[2] : 1;
    } else if (op == OpMemberDecorate && operands.size() >= 3) {
        mMemberDecorations[{operands[0], operands[1]}].values[operands[2]] =
            operands.size() > 3 ? operands[3] : 1;
    } else if (op == OpDecorateString && operands.size() >= 2) {
        mDecorations[operands[0]].strings[operands[1]] = literalString(operands, 2);
    } else if (op == OpMemberDecorateString && operands.size() >= 3) {
        mMemberDecorations[{operands[0], operands[1]}].strings[operands[2]] =
            literalString(operands, 3);
    } else if (isType(op)) {
        mTypes[operands[0]] = {op, {operands.begin() + 1, operands.end()}};
    } else if (op == OpConstant && operands.size() >= 3) {
        mConstants[operands[1]] = operands[2];
    } else if (op == OpVariable && operands.size() >= 3) {
        mVariables.push_back({operands[1], operands[0], operands[2]});
    }
}

std::string SpirvModule::name(uint32_t id) const {
    auto it = mNames.find(id);
    return it == mNames.end() ? std::string() : it->second;
}

std::string SpirvModule::memberName(uint32_t structId, uint32_t member) const {
    auto it = mMemberNames.find({structId, member});
    return it == mMemberNames.end() ? std::string() : it->second;
}

const Decorations& SpirvModule::decorations(uint32_t id) const {
    auto it = mDecorations.find(id);
    return it == mDecorations.end() ? kNoDecorations : it->second;
}

const Decorations& SpirvModule::memberDecorations(uint32_t structId, uint32_t member) const {
    auto it = mMemberDecorations.find({structId, member});
    return it == mMemberDecorations.end() ? kNoDecorations : it->second;
}

const SpirvType* SpirvModule::type(uint32_t id) const {
    auto it = mTypes.find(id);
    return it == mTypes.end() ? nullptr : &it->second;
}

std::optional<uint32_t> SpirvModule::constant(uint32_t id) const {
    auto it = mConstants.find(id);
    if (it == mConstants.end()) return std::nullopt;
    return it->second;
}

uint32_t SpirvModule::pointee(uint32_t pointerType) const {
    const SpirvType* pointer = type(pointerType);
    if (!pointer || pointer->op != OpTypePointer || pointer->operands.size() < 2) return 0;
    return pointer->operands[1];
}

}  // namespace varc::driver
