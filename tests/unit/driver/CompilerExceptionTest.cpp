// SPDX-License-Identifier: Apache-2.0
#include <gtest/gtest.h>

#include <new>
#include <stdexcept>

#include "varc/driver/CompilerException.h"

namespace varc::driver {
namespace {

SourceLocation programBlock() { return {3, 12, 1}; }

template <typename Thrown>
Diagnostic diagnose(Thrown thrown) {
    try {
        throw thrown;
    } catch (...) {
        return diagnosticOfCompilerException(std::current_exception(), programBlock());
    }
}

TEST(CompilerException, OutOfMemoryIsAnErrorAtTheProgramBlock) {
    Diagnostic diagnostic = diagnose(std::bad_alloc());
    EXPECT_EQ(diagnostic.severity, Severity::Error);
    EXPECT_EQ(diagnostic.location, programBlock());
    EXPECT_EQ(diagnostic.message, "out of memory while compiling this program");
}

TEST(CompilerException, AStandardExceptionKeepsItsText) {
    Diagnostic diagnostic = diagnose(std::length_error("vector::_M_realloc_insert"));
    EXPECT_EQ(diagnostic.severity, Severity::Error);
    EXPECT_NE(diagnostic.message.find("vector::_M_realloc_insert"), std::string::npos);
    EXPECT_NE(diagnostic.message.find("please report it"), std::string::npos);
}

TEST(CompilerException, AnythingElseThrownIsStillAnError) {
    Diagnostic diagnostic = diagnose(42);
    EXPECT_EQ(diagnostic.severity, Severity::Error);
    EXPECT_NE(diagnostic.message.find("unknown exception"), std::string::npos);
}

}  // namespace
}  // namespace varc::driver
