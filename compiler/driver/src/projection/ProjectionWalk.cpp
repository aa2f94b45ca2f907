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
    if (mReachable && text.lines().size() < (size_t{1} << 26)) {  // (Ask keys: 27 bits)
        mTracker.emplace(text.braceMacros());
        mTextLines = &text.lines();
    }
    walk(text);
    settleAsks();
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
    const BlockTracker::Definitions definitions = [this](std::string_view name) -> const PpLine* {
        auto it = mTable.find(name);
        return it == mTable.end() ? nullptr : it->second;
    };
    const bool traced = mTracker && &lines == mTextLines;
    for (size_t i = 0; i < lines.size() && !mFailed;) {
        if (mBody >= 0 && i > mBodyUntil) mBody = -1;  // left the clean group
        while (!mDefineGroups.empty() && i > lines[mDefineGroups.back()].end)
            mDefineGroups.pop_back();
        const PpLine& line = lines[i];
        switch (line.kind) {
            case Kind::Text: {
                const int outer = mBody;
                const int body = traced ? mTracker->follow(line.code, definitions) : -1;
                if (mBody < 0) mBody = body;  // a run wholly inside one function body
                askAll(line.refs);
                mBody = outer;
                ++i;
                break;
            }
            case Kind::Other:
                askAll(line.refs);
                ++i;
                break;
            case Kind::Define:
            case Kind::Undef:
                // glslang compares a redefinition with the definition in force: a lookup, one
                // that always counts (it can fail the preprocessing).
                if (int k = mKeywords.keywordIndex(line.name); k >= 0) askAlways(k);
                if (traced && line.kind == Kind::Define && mDefineGroups.empty())
                    mLooseDefines.push_back(line.name);
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
                if (traced && mBody < 0 && line.clean) {
                    mBody = mTracker->functionBody();
                    mBodyUntil = line.end;
                }
                if (traced) {
                    mEntered.push_back({static_cast<uint32_t>(i), mBody, mDefineGroups.empty()});
                    if (line.definesOnly && mBody < 0)
                        mDefineGroups.push_back(static_cast<uint32_t>(i));
                }
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
    if (mAskedOutside.test(k)) return;
    const int group = mDefineGroups.empty() ? -1 : static_cast<int>(mDefineGroups.back());
    if (mBody < 0 && group < 0) {
        askAlways(keyword);
        return;
    }
    // One key per (keyword, body, group): 10 + 27 + 27 bits.
    static_assert(variants::VariantKey::kMaxKeywords <= 1024);
    const uint64_t place = (static_cast<uint64_t>(k) << 54) |
                           (static_cast<uint64_t>(mBody + 1) << 27) |
                           static_cast<uint64_t>(group + 1);
    if (mPlaceAsks.insert(place).second) mAsks.push_back({keyword, mBody, group});
}

void ProjectionWalk::askAlways(int keyword) {
    const size_t k = static_cast<size_t>(keyword);
    if (mAskedOutside.test(k)) return;
    mAskedOutside.set(k);
    mAsks.push_back({keyword, -1, -1});
}

void ProjectionWalk::askAll(const KeywordBits& keywords) {
    KeywordBits fresh = keywords & ~mAskedOutside;
    for (size_t k = 0; fresh.any() && k < fresh.size(); ++k) {
        if (!fresh.test(k)) continue;
        fresh.reset(k);
        ask(static_cast<int>(k));
    }
}

// Whether |ask| was made only in a body nothing reaches or a group defining only unused macros.
bool ProjectionWalk::leavable(const Ask& ask, const Liveness& liveness) {
    if (ask.body >= 0 && liveness.deadBodies[static_cast<size_t>(ask.body)]) return true;
    return ask.group >= 0 && !liveness.liveGroups[static_cast<size_t>(ask.group)];
}

void ProjectionWalk::settleAsks() {
    Liveness liveness;
    if (mTracker) {
        mTracker->finish();
        liveness = livenessOf({*mTracker, *mTextLines, mEntered, mLooseDefines}, mReachable->macros,
                              mReachable->entry);
    }
    for (const Ask& ask : mAsks) {
        const size_t k = static_cast<size_t>(ask.keyword);
        if ((liveness.decided && leavable(ask, liveness)) || mAsked.test(k)) continue;
        mAsked.set(k);
        mAnswers.emplace_back(ask.keyword, mKey.test(k));
    }
}

}  // namespace varc::driver::projection
