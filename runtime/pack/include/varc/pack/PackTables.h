// SPDX-License-Identifier: Apache-2.0
// Record layouts of the pack's table chunks, and the schema the reader validates them against.
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "varc/pack/KeyEncoding.h"
#include "varc/pack/PackFormat.h"
#include "varc/pack/PackModel.h"
#include "varc/pack/RenderStateTable.h"
#include "varc/pack/TableSchema.h"

namespace varc::pack {

// ---- Record layouts. Each enum lists a table's fields in order; k...FieldCount is the width.

enum StringField : uint32_t { kStringOffset, kStringLength, kStringFieldCount };
inline constexpr FieldSpec kStringSchema[] = {valueField(), valueField()};

enum ToolField : uint32_t { kToolName, kToolVersion, kToolFieldCount };
inline constexpr FieldSpec kToolSchema[] = {stringField(), stringField()};

enum ShaderField : uint32_t { kShaderName, kShaderPassFirst, kShaderPassCount, kShaderFieldCount };
inline constexpr FieldSpec kShaderSchema[] = {stringField(), firstField(Chunk::Passes),
                                              countField()};

// Shader indices sorted by name (stable), for binary search by name.
enum ShaderNameField : uint32_t { kShaderNameShader, kShaderNameFieldCount };
inline constexpr FieldSpec kShaderNameSchema[] = {indexField(Chunk::Shaders)};

enum PassField : uint32_t {
    kPassIndex,
    kPassName,
    kPassLightMode,
    kPassTagFirst,
    kPassTagCount,
    kPassRenderState,
    kPassKeywordFirst,  // the keyword table, a range of StringLists
    kPassKeywordCount,
    kPassSetFirst,
    kPassSetCount,
    kPassKeyWords,      // words per key = keyWordCount(keyword count)
    kPassKeyFirst,      // first word of the pass's sorted keys in VariantKeys
    kPassVariantFirst,  // range of VariantPrograms and VariantOrder
    kPassVariantCount,
    kPassFieldCount
};
inline constexpr FieldSpec kPassSchema[] = {valueField(),
                                            stringField(),
                                            stringField(),
                                            firstField(Chunk::Tags),
                                            countField(),
                                            indexField(Chunk::RenderStates),
                                            firstField(Chunk::StringLists),
                                            countField(),
                                            firstField(Chunk::KeywordSets),
                                            countField(),
                                            belowField(kMaxKeyWords + 1),
                                            valueField(),
                                            firstField(Chunk::VariantPrograms),
                                            countField()};

enum TagField : uint32_t { kTagKey, kTagValue, kTagFieldCount };
inline constexpr FieldSpec kTagSchema[] = {stringField(), stringField()};

enum StringListField : uint32_t { kStringListString, kStringListFieldCount };
inline constexpr FieldSpec kStringListSchema[] = {stringField()};

enum KeywordSetField : uint32_t {
    kSetDirective,
    kSetKeywordFirst,
    kSetKeywordCount,
    kSetFieldCount
};
inline constexpr FieldSpec kKeywordSetSchema[] = {stringField(), firstField(Chunk::StringLists),
                                                  countField()};

// Per sorted variant: the program of each stage slot (OptIndex into Programs) and the
// variant's index in enumeration order.
enum VariantProgramField : uint32_t {
    kVariantProgram = 0,  // + stage slot, kStageCount fields
    kVariantOrdinal = kStageCount,
    kVariantProgramFieldCount
};
inline constexpr FieldSpec kVariantProgramSchema[] = {
    optIndexField(Chunk::Programs), optIndexField(Chunk::Programs), optIndexField(Chunk::Programs),
    optIndexField(Chunk::Programs), optIndexField(Chunk::Programs), valueField()};

// Per variant in enumeration order: its position in the pass's sorted index.
enum VariantOrderField : uint32_t { kOrderPosition, kOrderFieldCount };
inline constexpr FieldSpec kVariantOrderSchema[] = {valueField()};

enum ProgramField : uint32_t {
    kProgramStage,
    kProgramEntry,
    kProgramBlob,
    kProgramReflection,
    kProgramSourceFile,
    kProgramSourceLine,
    kProgramDependencyFirst,
    kProgramDependencyCount,
    kProgramFieldCount
};
inline constexpr FieldSpec kProgramSchema[] = {
    belowField(kStageCount),        stringField(), indexField(Chunk::Blobs),
    indexField(Chunk::Reflections), stringField(), valueField(),
    firstField(Chunk::StringLists), countField()};

enum ReflectionField : uint32_t {
    kReflBlockFirst,
    kReflBlockCount,
    kReflResourceFirst,
    kReflResourceCount,
    kReflVertexInputFirst,
    kReflVertexInputCount,
    kReflInputFirst,
    kReflInputCount,
    kReflOutputFirst,
    kReflOutputCount,
    kReflPushFirst,  // push-constant blocks are UniformBlocks records (set, binding unused)
    kReflPushCount,
    kReflectionFieldCount
};
inline constexpr FieldSpec kReflectionSchema[] = {firstField(Chunk::UniformBlocks),  countField(),
                                                  firstField(Chunk::Resources),      countField(),
                                                  firstField(Chunk::VertexInputs),   countField(),
                                                  firstField(Chunk::StageVariables), countField(),
                                                  firstField(Chunk::StageVariables), countField(),
                                                  firstField(Chunk::UniformBlocks),  countField()};

enum UniformBlockField : uint32_t {
    kBlockName,
    kBlockSet,
    kBlockBinding,
    kBlockSize,
    kBlockMemberFirst,
    kBlockMemberCount,
    kBlockFieldCount
};
inline constexpr FieldSpec kUniformBlockSchema[] = {
    stringField(), valueField(), valueField(), valueField(), firstField(Chunk::BlockMembers),
    countField()};

enum BlockMemberField : uint32_t {
    kMemberName,
    kMemberOffset,
    kMemberSize,
    kMemberType,
    kMemberArrayCount,
    kMemberRowMajor,
    kMemberFieldCount
};
inline constexpr FieldSpec kBlockMemberSchema[] = {stringField(), valueField(), valueField(),
                                                   stringField(), valueField(), boolField()};

enum ResourceField : uint32_t {
    kResourceName,
    kResourceKind,
    kResourceDim,
    kResourceSet,
    kResourceBinding,
    kResourceArraySize,
    kResourceMultisampled,
    kResourceFieldCount
};
inline constexpr FieldSpec kResourceSchema[] = {stringField(),
                                                belowField(kResourceKindCount),
                                                belowField(kResourceDimCount),
                                                valueField(),
                                                valueField(),
                                                valueField(),
                                                boolField()};

enum VertexInputField : uint32_t {
    kVertexInputName,
    kVertexInputSemantic,
    kVertexInputLocation,
    kVertexInputType,
    kVertexInputFieldCount
};
inline constexpr FieldSpec kVertexInputSchema[] = {stringField(), stringField(), valueField(),
                                                   stringField()};

enum StageVariableField : uint32_t {
    kStageVarName,
    kStageVarLocation,
    kStageVarType,
    kStageVarFieldCount
};
inline constexpr FieldSpec kStageVariableSchema[] = {stringField(), valueField(), stringField()};

// offset and size locate the stored bytes in BlobData; rawSize is the SPIR-V size in bytes.
enum BlobField : uint32_t {
    kBlobCodecField,
    kBlobOffset,
    kBlobSize,
    kBlobRawSize,
    kBlobFieldCount
};
inline constexpr FieldSpec kBlobSchema[] = {belowField(kBlobCodecCount), valueField(), valueField(),
                                            valueField()};

// Properties defaults (optional chunk, format 1.1): records grouped by shader, declaration order.
enum PropertyField : uint32_t {
    kPropertyShader,
    kPropertyName,
    kPropertyKind,
    kPropertyX,  // float bits
    kPropertyY,
    kPropertyZ,
    kPropertyW,
    kPropertyTexture,  // string ("" for none)
    kPropertyFieldCount
};
inline constexpr FieldSpec kPropertySchema[] = {indexField(Chunk::Shaders),
                                                stringField(),
                                                belowField(kPropertyKindCount),
                                                valueField(),
                                                valueField(),
                                                valueField(),
                                                valueField(),
                                                stringField()};

// The schema of each chunk; empty for raw chunks.
inline constexpr std::array<std::span<const FieldSpec>, kChunkCount> kTableSchemas = {{
    kStringSchema,
    {},
    kToolSchema,
    kShaderSchema,
    kShaderNameSchema,
    kPassSchema,
    kTagSchema,
    kStringListSchema,
    kKeywordSetSchema,
    kRenderStateSchema,
    {},
    kVariantProgramSchema,
    kVariantOrderSchema,
    kProgramSchema,
    kReflectionSchema,
    kUniformBlockSchema,
    kBlockMemberSchema,
    kResourceSchema,
    kVertexInputSchema,
    kStageVariableSchema,
    kBlobSchema,
    {},
    {},
    kPropertySchema,
}};

constexpr std::span<const FieldSpec> tableSchema(Chunk chunk) {
    return kTableSchemas[static_cast<size_t>(chunk)];
}

static_assert(std::size(kStringSchema) == kStringFieldCount);
static_assert(std::size(kToolSchema) == kToolFieldCount);
static_assert(std::size(kShaderSchema) == kShaderFieldCount);
static_assert(std::size(kPropertySchema) == kPropertyFieldCount);
static_assert(std::size(kShaderNameSchema) == kShaderNameFieldCount);
static_assert(std::size(kPassSchema) == kPassFieldCount);
static_assert(std::size(kTagSchema) == kTagFieldCount);
static_assert(std::size(kStringListSchema) == kStringListFieldCount);
static_assert(std::size(kKeywordSetSchema) == kSetFieldCount);
static_assert(std::size(kVariantProgramSchema) == kVariantProgramFieldCount);
static_assert(std::size(kVariantOrderSchema) == kOrderFieldCount);
static_assert(std::size(kProgramSchema) == kProgramFieldCount);
static_assert(std::size(kReflectionSchema) == kReflectionFieldCount);
static_assert(std::size(kUniformBlockSchema) == kBlockFieldCount);
static_assert(std::size(kBlockMemberSchema) == kMemberFieldCount);
static_assert(std::size(kResourceSchema) == kResourceFieldCount);
static_assert(std::size(kVertexInputSchema) == kVertexInputFieldCount);
static_assert(std::size(kStageVariableSchema) == kStageVarFieldCount);
static_assert(std::size(kBlobSchema) == kBlobFieldCount);

}  // namespace varc::pack
