// SPDX-License-Identifier: Apache-2.0
// Decodes a Reflections record and the tables it points into back to ProgramReflection.
#pragma once

#include <cstdint>

#include "varc/pack/ProgramReflection.h"

namespace varc::reader::detail {

class PackImage;

// |record| < the Reflections count of the validated |image|.
pack::ProgramReflection decodeReflection(const PackImage& image, uint32_t record);

}  // namespace varc::reader::detail
