// SPDX-License-Identifier: Apache-2.0
// Result<T>: a value or an Error, for failures from the environment (error tier 2).
#pragma once

#include <string>
#include <utility>
#include <variant>

#include "varc/core/Check.h"

namespace varc {

// A short taxonomy of environment failures, after shaderc_compilation_status.
enum class ErrorCode {
    IoError,         // a file could not be read, written or renamed
    InvalidInput,    // input is malformed (bad magic, truncated, checksum mismatch, ...)
    Unsupported,     // a valid input uses something this build cannot handle (version, ...)
    NotFound,        // a looked-up item (shader, pass, variant) does not exist
    CompileFailed,   // a shader failed to compile; details are diagnostics
    VulkanError,     // a Vulkan call returned an error
    Internal,        // a bug in varc
};

const char* toString(ErrorCode code);

struct Error {
    ErrorCode code = ErrorCode::Internal;
    std::string detail;
};

// std::expected stand-in (GCC 12 lacks it). Accessing the wrong alternative is a programmer
// error and aborts through VARC_CHECK.
template <typename T>
class [[nodiscard]] Result {
public:
    Result(T value) : mStorage(std::in_place_index<0>, std::move(value)) {}  // NOLINT: implicit
    Result(Error error) : mStorage(std::in_place_index<1>, std::move(error)) {}  // NOLINT

    bool ok() const { return mStorage.index() == 0; }
    explicit operator bool() const { return ok(); }

    T& value() & {
        VARC_CHECK(ok()) << "Result::value() on an error: " << error().detail;
        return std::get<0>(mStorage);
    }
    const T& value() const& {
        VARC_CHECK(ok()) << "Result::value() on an error: " << error().detail;
        return std::get<0>(mStorage);
    }
    T&& value() && {
        VARC_CHECK(ok()) << "Result::value() on an error: " << error().detail;
        return std::get<0>(std::move(mStorage));
    }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }

    const Error& error() const {
        VARC_CHECK(!ok()) << "Result::error() on a value";
        return std::get<1>(mStorage);
    }

private:
    std::variant<T, Error> mStorage;
};

// Result<void> equivalent.
struct Ok {};
using Status = Result<Ok>;

inline Error makeError(ErrorCode code, std::string detail) { return Error{code, std::move(detail)}; }

}  // namespace varc
