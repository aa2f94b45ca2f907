// SPDX-License-Identifier: Apache-2.0
// Resolves an engine's variant requests, reports each miss once and keeps a usage log.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <span>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "varc/core/Result.h"
#include "varc/reader/PassView.h"
#include "varc/reader/VariantView.h"
#include "varc/variants/LightKeywords.h"
#include "varc/variants/VariantKey.h"
#include "varc/variants/VariantSelector.h"

namespace varc::reader {

// A request the pack holds no exact variant for (docs/KEYWORDS.md §8, "Misses at run time").
struct VariantMiss {
    std::string shader;
    uint32_t pass = 0;                   // PassView::index()
    std::string lightMode;               // "" when the pass has none
    std::vector<std::string> requested;  // sorted; only keywords the pass declares
    std::vector<std::string> used;       // the variant drawn instead; empty under Strict/Exact
    variants::SelectionPolicy policy = variants::SelectionPolicy::Closest;
    uint64_t count = 0;  // how many requests missed this way so far
    // One line for a log, e.g. `shader "Custom/X" pass 1 (ForwardAdd): no variant with SPOT
    // SHADOWS_DEPTH; using SPOT (closest)`; under Strict/Exact it names up to 3 nearest variants.
    std::string report;
};

// Held by an engine beside its Packs: every variant request goes through resolve(), which
// records it. Thread-safe: any number of threads may call any method at once (one mutex; the
// pack lookups themselves run outside it). Unlike an exact PassView::lookup, resolve allocates
// (the request's keyword names), so engines call it when a draw's material or light changes,
// not per frame. The views it returns are valid while their Pack lives.
class VariantRequests {
public:
    using MissCallback = std::function<void(const VariantMiss&)>;

    // |onMiss| (optional) is called once per new miss (shader, pass, requested keywords), on the
    // thread whose request missed first and outside the lock; without it, new misses queue for
    // takeNewMisses(). Later misses of the same request only raise its count.
    explicit VariantRequests(MissCallback onMiss = {});

    // The variant |pass| uses for |keywords| (names the pass does not declare are ignored, as in
    // PassView::keyOf) under |policy|, recording the request. Closest (Unity's default) and First
    // always give a variant when the pass has any; Strict (Unity's strictShaderVariantMatching)
    // and Exact make a miss a NotFound error, e.g. `shader "Custom/X" pass 1 (ForwardAdd): no
    // variant with SPOT SHADOWS_DEPTH (strict); nearest: SPOT | POINT | SPOT_COOKIE`.
    Result<VariantView> resolve(const PassView& pass, std::span<const std::string_view> keywords,
                                variants::SelectionPolicy policy);
    Result<VariantView> resolve(const PassView& pass, const std::vector<std::string>& keywords,
                                variants::SelectionPolicy policy);
    Result<VariantView> resolve(const PassView& pass, const variants::VariantKey& key,
                                variants::SelectionPolicy policy);
    // The light's keywords added to |materialKey|, as PassView::lookup(light, ...) does.
    Result<VariantView> resolve(const PassView& pass, const variants::LightDescription& light,
                                variants::SelectionPolicy policy,
                                const variants::VariantKey& materialKey = {});

    // The misses first seen since the last call (only when constructed without a callback), in
    // the order they happened.
    std::vector<VariantMiss> takeNewMisses();
    // Every distinct miss so far with its count, sorted by (shader, pass, requested).
    std::vector<VariantMiss> misses() const;
    size_t requestCount() const;  // distinct requests recorded, hits and misses

    // The usage log (docs/USAGE_LOG.md): `{"varc_usage_log":1}`, then one JSON object per
    // distinct request sorted by (shader, pass, keywords), one per line. Deterministic: the same
    // requests in any order and from any threads give the same bytes.
    std::string usageLog() const;
    // Writes usageLog() to |path| atomically (writeFileAtomically: a device such as /dev/null
    // stays a device). Errors name the path and the reason.
    Status writeUsageLog(const std::string& path) const;

private:
    using RequestKey = std::tuple<std::string, uint32_t, std::vector<std::string>>;
    struct Entry {
        std::string lightMode;
        bool missed = false;
        VariantMiss miss;  // when |missed|
    };

    // Records a request of |pass| for |requested| that |found| answered.
    Result<VariantView> record(const PassView& pass, const variants::VariantKey& requested,
                               variants::SelectionPolicy policy, Result<VariantView> found);
    VariantMiss describeMiss(const PassView& pass, const variants::VariantKey& requested,
                             variants::SelectionPolicy policy,
                             const Result<VariantView>& found) const;

    MissCallback mOnMiss;
    mutable std::mutex mMutex;
    std::map<RequestKey, Entry> mRequests;  // guarded by mMutex
    std::vector<VariantMiss> mNewMisses;    // guarded by mMutex; only without mOnMiss
};

}  // namespace varc::reader
