// SPDX-License-Identifier: Apache-2.0
// Componentwise GLSL.std.450 math on matrices, split into one instruction per column.
#include "varc/driver/SpirvMatrixMath.h"

#include <spirv-tools/libspirv.h>

#include <map>
#include <optional>
#include <span>

namespace varc::driver {

namespace {

constexpr uint32_t kOpExtInst = 12;
constexpr uint32_t kOpTypeMatrix = 24;
constexpr uint32_t kOpCompositeConstruct = 80;
constexpr uint32_t kOpCompositeExtract = 81;
constexpr uint32_t kGlslMatrixInverse = 34;
constexpr size_t kHeaderWords = 5;
constexpr size_t kBoundWord = 3;

uint32_t firstWord(uint32_t wordCount, uint32_t opcode) { return wordCount << 16 | opcode; }

struct MatrixType {
    uint32_t column = 0;
    uint32_t columns = 0;
};

// What the rewrite needs of a module: each instruction's place and kind, each value's type.
struct ParsedModule {
    struct Instruction {
        size_t offset = 0, wordCount = 0;
        bool glslExtInst = false;
        uint32_t type = 0;
    };
    std::vector<Instruction> instructions;
    std::map<uint32_t, uint32_t> typeOf;
    std::map<uint32_t, MatrixType> matrices;
};

spv_result_t recordInstruction(void* user, const spv_parsed_instruction_t* parsed) {
    auto& module = *static_cast<ParsedModule*>(user);
    ParsedModule::Instruction instruction;
    instruction.wordCount = parsed->num_words;
    instruction.offset = module.instructions.empty() ? kHeaderWords
                                                     : module.instructions.back().offset +
                                                           module.instructions.back().wordCount;
    instruction.glslExtInst =
        parsed->opcode == kOpExtInst && parsed->ext_inst_type == SPV_EXT_INST_TYPE_GLSL_STD_450;
    instruction.type = parsed->type_id;
    if (parsed->result_id != 0 && parsed->type_id != 0) {
        module.typeOf[parsed->result_id] = parsed->type_id;
    }
    if (parsed->opcode == kOpTypeMatrix) {
        module.matrices[parsed->result_id] = {parsed->words[2], parsed->words[3]};
    }
    module.instructions.push_back(instruction);
    return SPV_SUCCESS;
}

std::optional<ParsedModule> parseModule(const std::vector<uint32_t>& spirv) {
    ParsedModule module;
    spv_context context = spvContextCreate(SPV_ENV_VULKAN_1_0);
    spv_result_t parsed = spvBinaryParse(context, &module, spirv.data(), spirv.size(), nullptr,
                                         recordInstruction, nullptr);
    spvContextDestroy(context);
    if (parsed != SPV_SUCCESS) return std::nullopt;
    return module;
}

class Splitter {
public:
    Splitter(const ParsedModule& module, uint32_t bound) : mModule(module), mBound(bound) {}

    // Appends |words| (one OpExtInst) to |out| split by columns; false when it is not a
    // componentwise instruction on a matrix.
    bool split(std::span<const uint32_t> words, std::vector<uint32_t>& out) {
        auto matrix = mModule.matrices.find(words[1]);
        if (matrix == mModule.matrices.end() || words[4] == kGlslMatrixInverse) return false;
        const MatrixType& type = matrix->second;
        std::span<const uint32_t> operands = words.subspan(5);
        for (uint32_t operand : operands) {
            auto operandType = mModule.typeOf.find(operand);
            if (operandType == mModule.typeOf.end() ||
                (operandType->second != words[1] && operandType->second != type.column)) {
                return false;
            }
        }
        std::vector<uint32_t> columnResults;
        for (uint32_t column = 0; column < type.columns; ++column) {
            std::vector<uint32_t> columnOperands;
            for (uint32_t operand : operands) {
                if (mModule.typeOf.at(operand) == type.column) {
                    columnOperands.push_back(operand);
                    continue;
                }
                uint32_t extracted = mBound++;
                out.insert(out.end(), {firstWord(5, kOpCompositeExtract), type.column, extracted,
                                       operand, column});
                columnOperands.push_back(extracted);
            }
            uint32_t result = mBound++;
            auto wordCount = static_cast<uint32_t>(5 + operands.size());
            out.insert(out.end(),
                       {firstWord(wordCount, kOpExtInst), type.column, result, words[3], words[4]});
            out.insert(out.end(), columnOperands.begin(), columnOperands.end());
            columnResults.push_back(result);
        }
        out.insert(out.end(),
                   {firstWord(3 + type.columns, kOpCompositeConstruct), words[1], words[2]});
        out.insert(out.end(), columnResults.begin(), columnResults.end());
        return true;
    }

    uint32_t bound() const { return mBound; }

private:
    const ParsedModule& mModule;
    uint32_t mBound;
};

}  // namespace

std::vector<uint32_t> splitMatrixExtendedMath(const std::vector<uint32_t>& spirv) {
    if (spirv.size() <= kHeaderWords) return spirv;
    std::optional<ParsedModule> module = parseModule(spirv);
    if (!module || module->matrices.empty()) return spirv;
    Splitter splitter(*module, spirv[kBoundWord]);
    std::vector<uint32_t> out(spirv.begin(), spirv.begin() + kHeaderWords);
    bool changed = false;
    for (const ParsedModule::Instruction& instruction : module->instructions) {
        std::span<const uint32_t> words(spirv.data() + instruction.offset, instruction.wordCount);
        if (instruction.glslExtInst && splitter.split(words, out)) {
            changed = true;
            continue;
        }
        out.insert(out.end(), words.begin(), words.end());
    }
    if (!changed) return spirv;
    out[kBoundWord] = splitter.bound();
    return out;
}

}  // namespace varc::driver
