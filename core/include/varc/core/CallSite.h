// SPDX-License-Identifier: Apache-2.0
// The file and line of a call, captured at the call site, for messages that name where they
// came from.
#pragma once

namespace varc {

// What std::source_location gives, for the compilers varc builds with: clang 14 (the sanitizer
// and fuzzing builds) cannot use libstdc++ 12's std::source_location, while both compilers
// evaluate __builtin_FILE() and __builtin_LINE() in a default argument at the call site.
// Example: `Status check(int value, CallSite where = CallSite::current());` called on line 12 of
// a.cpp gets where.fileName() == ".../a.cpp" and where.line() == 12.
class CallSite {
public:
    static constexpr CallSite current(const char* file = __builtin_FILE(),
                                      unsigned line = __builtin_LINE()) {
        return CallSite(file, line);
    }
    constexpr const char* fileName() const { return mFile; }
    constexpr unsigned line() const { return mLine; }

private:
    constexpr CallSite(const char* file, unsigned line) : mFile(file), mLine(line) {}
    const char* mFile;
    unsigned mLine;
};

}  // namespace varc
