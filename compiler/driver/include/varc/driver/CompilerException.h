// SPDX-License-Identifier: Apache-2.0
// What varc reports when the compilers it runs in-process throw instead of reporting an error.
#pragma once

#include <exception>

#include "varc/core/Diagnostic.h"

namespace varc::driver {

// The error for an exception thrown while compiling one program (glslang and SPIRV-Tools throw
// std::bad_alloc, std::length_error, ... on input they cannot handle). It points at |origin|, the
// program block, so the build names the shader, pass, stage and keywords as for any other error
// and goes on with the other programs, instead of ending the process with "internal error".
Diagnostic diagnosticOfCompilerException(const std::exception_ptr& thrown,
                                         const SourceLocation& origin);

}  // namespace varc::driver
