// SPDX-License-Identifier: Apache-2.0
// Walks a text's directives for one variant, recording the keywords looked up.
#include "ProjectionWalk.h"

namespace varc::driver::projection {

namespace {

// What a keyword macro expands to (varc defines each keyword as 1).
const PpLine& keywordDefinition() {
    static const PpLine kOne = [] {
        PpLine line;
        line.kind = PpLine::Kind::Define;
        line.tokens = {"1"};
        return line;
    }();
    return kOne;
}

// Names glslang may predefine itself (GL_ extensions, __VERSION__, VULKAN): their values are
// not modelled, so a text testing one is left to glslang.
bool mayBeGlslangBuiltin(std::string_view name) {
    return name.starts_with("GL_") || name.starts_with("__") || name == "VULKAN";
}

}  // namespace

bool ProjectionWalk::run(const ConditionalText& base, const ConditionalText& text,
                         const KeywordBits& formable) {
    if (!base.usable() || !text.usable()) return false;
    askAll(formable);
    walk(base);
    walk(text);
    return !mFailed;
}

const PpLine* ProjectionWalk::macro(std::string_view name) {
    if (auto it = mTable.find(name); it != mTable.end()) return it->second;
    if (int k = mKeywords.keywordIndex(name); k >= 0) {
        ask(k);
        return mKey.test(static_cast<size_t>(k)) ? &keywordDefinition() : nullptr;
    }
    if (mayBeGlslangBuiltin(name)) mFailed = true;
    return nullptr;
}

void ProjectionWalk::walk(const ConditionalText& text) {
    using Kind = PpLine::Kind;
    const std::vector<PpLine>& lines = text.lines();
    for (size_t i = 0; i < lines.size() && !mFailed;) {
        const PpLine& line = lines[i];
        switch (line.kind) {
            case Kind::Text:
            case Kind::Other:
                askAll(line.refs);
                ++i;
                break;
            case Kind::Define:
            case Kind::Undef:
                // glslang compares a redefinition with the definition in force: a lookup.
                if (int k = mKeywords.keywordIndex(line.name); k >= 0) ask(k);
                mTable[line.name] = line.kind == Kind::Define ? &line : nullptr;
                ++i;
                break;
            case Kind::Elif:
            case Kind::Else:
                i = line.end;  // the branch before was taken: skip to the #endif
                break;
            case Kind::If:
            case Kind::Ifdef:
            case Kind::Ifndef:
                i = enterGroup(lines, i);
                break;
            default:  // #endif, #pragma (glslang does not expand it)
                ++i;
        }
    }
}

size_t ProjectionWalk::enterGroup(const std::vector<PpLine>& lines, size_t i) {
    using Kind = PpLine::Kind;
    while (!mFailed) {
        const PpLine& branch = lines[i];
        bool taken = false;
        switch (branch.kind) {
            case Kind::If:
            case Kind::Elif: {
                std::optional<long long> value = evaluateCondition(branch.tokens, *this);
                if (!value) mFailed = true;
                taken = value && *value != 0;
                break;
            }
            case Kind::Ifdef:
                taken = macro(branch.name) != nullptr;
                break;
            case Kind::Ifndef:
                taken = macro(branch.name) == nullptr;
                break;
            case Kind::Else:
                taken = true;
                break;
            default:  // #endif: no branch taken
                return i + 1;
        }
        if (taken) return i + 1;
        i = branch.next;
    }
    return lines.size();
}

void ProjectionWalk::ask(int keyword) {
    const size_t k = static_cast<size_t>(keyword);
    if (mAsked.test(k)) return;
    mAsked.set(k);
    mAnswers.emplace_back(keyword, mKey.test(k));
}

void ProjectionWalk::askAll(const KeywordBits& keywords) {
    KeywordBits fresh = keywords & ~mAsked;
    for (size_t k = 0; fresh.any() && k < fresh.size(); ++k) {
        if (!fresh.test(k)) continue;
        fresh.reset(k);
        ask(static_cast<int>(k));
    }
}

}  // namespace varc::driver::projection
