// SPDX-License-Identifier: Apache-2.0
// The up-front checks that make every later accessor of a PackImage safe without checks.
#pragma once

#include "varc/core/Result.h"

namespace varc::reader::detail {

class PackImage;

// Checks every field of every table record against its schema (PackTables.h): booleans,
// enum ranges, string ids, record indices and ranges into their target tables. InvalidInput
// names the table, record and field on failure.
Status validateSchemas(const PackImage& image);

// Checks what the schemas cannot express: strings inside StringBytes; shader-name index sorted
// and a permutation; per pass, a sorted unique keyword table, keys inside VariantKeys, strictly
// increasing and within the table, VariantOrder and the ordinals inverse permutations, programs
// in the slot of their stage; blobs inside BlobData with sane codecs and sizes.
Status validateReferences(const PackImage& image);

}  // namespace varc::reader::detail
