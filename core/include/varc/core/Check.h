// SPDX-License-Identifier: Apache-2.0
// VARC_CHECK: aborts with file:line and a streamed message on programmer errors (error tier 3).
#pragma once

#include <sstream>

namespace varc::detail {

// Collects the streamed message and aborts in its destructor.
class CheckFailure {
public:
    CheckFailure(const char* file, int line, const char* condition);
    [[noreturn]] ~CheckFailure();
    template <typename T>
    CheckFailure& operator<<(const T& value) {
        mStream << value;
        return *this;
    }

private:
    std::ostringstream mStream;
};

}  // namespace varc::detail

// Stays enabled in release builds; use it for cheap invariants only.
#define VARC_CHECK(condition) \
    if (condition) {          \
    } else                    \
        ::varc::detail::CheckFailure(__FILE__, __LINE__, #condition)
