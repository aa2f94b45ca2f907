// SPDX-License-Identifier: Apache-2.0
#include "varc/driver/CompilerException.h"

#include <new>
#include <string>

namespace varc::driver {

Diagnostic diagnosticOfCompilerException(const std::exception_ptr& thrown,
                                         const SourceLocation& origin) {
    std::string message;
    try {
        std::rethrow_exception(thrown);
    } catch (const std::bad_alloc&) {
        message = "out of memory while compiling this program";
    } catch (const std::exception& e) {
        message = std::string("the shader compiler failed on this program: ") + e.what() +
                  " (please report it with this shader)";
    } catch (...) {
        message =
            "the shader compiler failed on this program with an unknown exception "
            "(please report it with this shader)";
    }
    return {Severity::Error, origin, std::move(message), {}};
}

}  // namespace varc::driver
