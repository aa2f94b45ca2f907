// SPDX-License-Identifier: Apache-2.0
// The vocabulary of table schemas: what each u32 field of a table record may hold.
#pragma once

#include <cstdint>

#include "varc/pack/PackFormat.h"

namespace varc::pack {

// What a u32 field may hold. The reader checks every field of every record against its kind
// once, at open, so accessors afterwards index without checks.
enum class FieldKind : uint8_t {
    Value,     // any value
    Bool,      // 0 or 1
    Below,     // < FieldSpec::limit (enums, masks)
    String,    // index into Strings
    Index,     // index into the target table
    OptIndex,  // index into the target table, or kNone
    First,     // first record of a range in the target table; the next field is its Count
    Count,     // length of the range started by the previous field
};

struct FieldSpec {
    FieldKind kind = FieldKind::Value;
    Chunk target = Chunk::Strings;  // for Index, OptIndex, First
    uint32_t limit = 0;             // for Below
};

constexpr FieldSpec valueField() { return {FieldKind::Value, Chunk::Strings, 0}; }
constexpr FieldSpec boolField() { return {FieldKind::Bool, Chunk::Strings, 0}; }
constexpr FieldSpec belowField(uint32_t limit) { return {FieldKind::Below, Chunk::Strings, limit}; }
constexpr FieldSpec stringField() { return {FieldKind::String, Chunk::Strings, 0}; }
constexpr FieldSpec indexField(Chunk target) { return {FieldKind::Index, target, 0}; }
constexpr FieldSpec optIndexField(Chunk target) { return {FieldKind::OptIndex, target, 0}; }
constexpr FieldSpec firstField(Chunk target) { return {FieldKind::First, target, 0}; }
constexpr FieldSpec countField() { return {FieldKind::Count, Chunk::Strings, 0}; }

}  // namespace varc::pack
