// SPDX-License-Identifier: Apache-2.0
// VARC_CHECK failure reporting and ErrorCode names.
#include "varc/core/Check.h"

#include <cstdio>
#include <cstdlib>

#include "varc/core/Result.h"

namespace varc::detail {

CheckFailure::CheckFailure(const char* file, int line, const char* condition) {
    mStream << file << ":" << line << ": internal error: check failed: " << condition << ": ";
}

CheckFailure::~CheckFailure() {
    std::fprintf(stderr, "%s\n", mStream.str().c_str());
    std::fflush(stderr);
    std::abort();
}

}  // namespace varc::detail

namespace varc {

const char* toString(ErrorCode code) {
    switch (code) {
        case ErrorCode::IoError: return "I/O error";
        case ErrorCode::InvalidInput: return "invalid input";
        case ErrorCode::Unsupported: return "unsupported";
        case ErrorCode::NotFound: return "not found";
        case ErrorCode::CompileFailed: return "compile failed";
        case ErrorCode::VulkanError: return "Vulkan error";
        case ErrorCode::Internal: return "internal error";
    }
    return "unknown error";
}

}  // namespace varc
