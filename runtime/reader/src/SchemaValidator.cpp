// SPDX-License-Identifier: Apache-2.0
// Checks every table field against its schema (PackTables.h), before any accessor runs.
#include <string>
#include <vector>

#include "PackImage.h"
#include "PackValidator.h"
#include "varc/pack/PackTables.h"

namespace varc::reader::detail {

namespace {

Error fieldError(pack::Chunk chunk, uint32_t record, size_t field, uint32_t value,
                 const char* problem) {
    return makeError(ErrorCode::InvalidInput,
                     std::string("corrupt pack: table ") + pack::chunkInfo(chunk).name +
                         " record " + std::to_string(record) + " field " + std::to_string(field) +
                         " = " + std::to_string(value) + ": " + problem);
}

// A schema field reduced to one comparison. Value and Count fields need none (a Count is
// checked with its First).
struct FieldCheck {
    enum class Kind : uint8_t { Below, NoneOrBelow, Range } kind;
    uint32_t field;
    uint32_t bound;  // values (or range ends) must be < bound (<= bound for Range)
};

std::vector<FieldCheck> checksFor(const PackImage& image, std::span<const pack::FieldSpec> schema) {
    std::vector<FieldCheck> checks;
    for (size_t f = 0; f < schema.size(); ++f) {
        const pack::FieldSpec& spec = schema[f];
        auto field = static_cast<uint32_t>(f);
        switch (spec.kind) {
            case pack::FieldKind::Value:
            case pack::FieldKind::Count:
                break;
            case pack::FieldKind::Bool:
                checks.push_back({FieldCheck::Kind::Below, field, 2});
                break;
            case pack::FieldKind::Below:
                checks.push_back({FieldCheck::Kind::Below, field, spec.limit});
                break;
            case pack::FieldKind::String:
                checks.push_back(
                    {FieldCheck::Kind::Below, field, image.count(pack::Chunk::Strings)});
                break;
            case pack::FieldKind::Index:
                checks.push_back({FieldCheck::Kind::Below, field, image.count(spec.target)});
                break;
            case pack::FieldKind::OptIndex:
                checks.push_back({FieldCheck::Kind::NoneOrBelow, field, image.count(spec.target)});
                break;
            case pack::FieldKind::First:
                checks.push_back({FieldCheck::Kind::Range, field, image.count(spec.target)});
                break;
        }
    }
    return checks;
}

bool passes(const FieldCheck& check, const TableView& table, uint32_t record) {
    uint32_t value = table.get(record, check.field);
    switch (check.kind) {
        case FieldCheck::Kind::Below:
            return value < check.bound;
        case FieldCheck::Kind::NoneOrBelow:
            return value == pack::kNone || value < check.bound;
        case FieldCheck::Kind::Range:
            return value <= check.bound &&
                   table.get(record, check.field + 1) <= check.bound - value;
    }
    return false;
}

Status validateTable(const PackImage& image, pack::Chunk chunk) {
    const TableView& table = image.table(chunk);
    std::vector<FieldCheck> checks = checksFor(image, pack::tableSchema(chunk));
    for (uint32_t record = 0; record < table.count; ++record) {
        for (const FieldCheck& check : checks) {
            if (!passes(check, table, record)) {
                const char* problem = check.kind == FieldCheck::Kind::Range ? "range out of bounds"
                                                                            : "value out of range";
                return fieldError(chunk, record, check.field, table.get(record, check.field),
                                  problem);
            }
        }
    }
    return Ok{};
}

}  // namespace

Status validateSchemas(const PackImage& image) {
    for (size_t i = 0; i < pack::kChunkCount; ++i) {
        auto chunk = static_cast<pack::Chunk>(i);
        if (!pack::chunkInfo(chunk).table) continue;
        if (Status status = validateTable(image, chunk); !status) return status;
    }
    return Ok{};
}

}  // namespace varc::reader::detail
