// SPDX-License-Identifier: Apache-2.0
// VariantRequests: resolves requests through PassView::lookup, reports misses once, logs usage.
#include "varc/reader/VariantRequests.h"

#include <cstdio>
#include <optional>
#include <utility>

#include "varc/core/AtomicFile.h"
#include "varc/pack/KeyEncoding.h"

namespace varc::reader {

namespace {

// "SPOT SHADOWS_DEPTH", or "no keywords" for the empty set.
std::string spaced(const std::vector<std::string>& names) {
    if (names.empty()) return "no keywords";
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : " ") + name;
    return text;
}

// |text| as a JSON string: quotes, backslashes and control characters escaped, other bytes
// (UTF-8) as they are.
void appendJsonString(std::string& out, std::string_view text) {
    out += '"';
    for (char c : text) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (static_cast<unsigned char>(c) < 0x20) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(c));
            out += escaped;
        } else {
            out += c;
        }
    }
    out += '"';
}

// Up to 3 variants of |pass| nearest |requested|, best first (variants::selectVariant's Strict
// ordering), as keyword lists. Reads every key of the pass: only for a miss's first report.
std::vector<std::string> nearestVariants(const PassView& pass,
                                         const variants::VariantKey& requested) {
    std::vector<variants::VariantKey> keys;
    keys.reserve(pass.variantCount());
    for (size_t e = 0; e < pass.variantCount(); ++e) keys.push_back(pass.variant(e).key());
    variants::Selection selection =
        variants::selectVariant(keys, requested, variants::SelectionPolicy::Strict);
    std::vector<std::string> nearest;
    for (size_t index : selection.nearest) {
        if (index < keys.size()) nearest.push_back(spaced(pass.keywordsOf(keys[index])));
    }
    return nearest;
}

}  // namespace

VariantRequests::VariantRequests(MissCallback onMiss) : mOnMiss(std::move(onMiss)) {}

Result<VariantView> VariantRequests::resolve(const PassView& pass,
                                             std::span<const std::string_view> keywords,
                                             variants::SelectionPolicy policy) {
    return resolve(pass, pass.keyOf(keywords), policy);
}

Result<VariantView> VariantRequests::resolve(const PassView& pass,
                                             const std::vector<std::string>& keywords,
                                             variants::SelectionPolicy policy) {
    return resolve(pass, pass.keyOf(keywords), policy);
}

Result<VariantView> VariantRequests::resolve(const PassView& pass, const variants::VariantKey& key,
                                             variants::SelectionPolicy policy) {
    // Masked first, so the recorded request is what selection saw (requested ∩ declared).
    variants::VariantKey requested = pack::maskKeyToTable(key, pass.keywordCount());
    return record(pass, requested, policy, pass.lookup(requested, policy));
}

Result<VariantView> VariantRequests::resolve(const PassView& pass,
                                             const variants::LightDescription& light,
                                             variants::SelectionPolicy policy,
                                             const variants::VariantKey& materialKey) {
    std::optional<variants::LightPassKind> kind =
        variants::lightPassKindFromLightMode(pass.lightMode());
    // Not a light pass: PassView's error, unrecorded (the request names no variant).
    if (!kind) return pass.lookup(light, policy, materialKey);
    variants::VariantKey key = pass.keyOf(variants::lightKeywords(light, *kind));
    return resolve(pass, key | materialKey, policy);
}

VariantMiss VariantRequests::describeMiss(const PassView& pass,
                                          const variants::VariantKey& requested,
                                          variants::SelectionPolicy policy,
                                          const Result<VariantView>& found) const {
    VariantMiss miss;
    miss.shader = std::string(pass.shaderName());
    miss.pass = pass.index();
    miss.lightMode = std::string(pass.lightMode());
    miss.requested = pass.keywordsOf(requested);
    miss.policy = policy;
    miss.report = "shader \"" + miss.shader + "\" pass " + std::to_string(miss.pass);
    if (!miss.lightMode.empty()) miss.report += " (" + miss.lightMode + ")";
    miss.report += ": no variant with " + spaced(miss.requested);
    const std::string policyName = variants::toString(policy);
    if (found) {
        miss.used = found->keywords();
        miss.report += "; using " + spaced(miss.used) + " (" + policyName + ")";
        return miss;
    }
    miss.report += " (" + policyName + ")";
    std::vector<std::string> nearest = nearestVariants(pass, requested);
    if (pass.variantCount() == 0) miss.report += "; the pass has no variants";
    for (size_t i = 0; i < nearest.size(); ++i)
        miss.report += (i == 0 ? "; nearest: " : " | ") + nearest[i];
    return miss;
}

Result<VariantView> VariantRequests::record(const PassView& pass,
                                            const variants::VariantKey& requested,
                                            variants::SelectionPolicy policy,
                                            Result<VariantView> found) {
    const bool missed = !found || !found->exact();
    RequestKey key{std::string(pass.shaderName()), pass.index(), pass.keywordsOf(requested)};
    std::optional<VariantMiss> firstReport;
    std::string report;
    {
        std::lock_guard lock(mMutex);
        auto [it, inserted] = mRequests.try_emplace(std::move(key));
        Entry& entry = it->second;
        if (inserted) entry.lightMode = std::string(pass.lightMode());
        if (missed) {
            if (!entry.missed) {
                entry.missed = true;
                entry.miss = describeMiss(pass, requested, policy, found);
                firstReport = entry.miss;
                firstReport->count = 1;
                if (!mOnMiss) mNewMisses.push_back(*firstReport);
            }
            ++entry.miss.count;
            if (!found) report = entry.miss.report;
        }
    }
    // Outside the lock: the callback may resolve again or take the lock through other methods.
    if (firstReport && mOnMiss) mOnMiss(*firstReport);
    if (!found) return makeError(ErrorCode::NotFound, report);
    return found;
}

std::vector<VariantMiss> VariantRequests::takeNewMisses() {
    std::lock_guard lock(mMutex);
    return std::exchange(mNewMisses, {});
}

std::vector<VariantMiss> VariantRequests::misses() const {
    std::lock_guard lock(mMutex);
    std::vector<VariantMiss> all;
    for (const auto& [key, entry] : mRequests) {
        if (entry.missed) all.push_back(entry.miss);
    }
    return all;
}

size_t VariantRequests::requestCount() const {
    std::lock_guard lock(mMutex);
    return mRequests.size();
}

std::string VariantRequests::usageLog() const {
    std::lock_guard lock(mMutex);
    std::string log = "{\"varc_usage_log\":1}\n";
    // The map's order is the log's: (shader, pass, keywords), each compared bytewise.
    for (const auto& [key, entry] : mRequests) {
        const auto& [shader, pass, keywords] = key;
        log += "{\"shader\":";
        appendJsonString(log, shader);
        log += ",\"pass\":" + std::to_string(pass) + ",\"lightmode\":";
        appendJsonString(log, entry.lightMode);
        log += ",\"keywords\":[";
        for (size_t i = 0; i < keywords.size(); ++i) {
            if (i) log += ',';
            appendJsonString(log, keywords[i]);
        }
        log += "]}\n";
    }
    return log;
}

Status VariantRequests::writeUsageLog(const std::string& path) const {
    return writeFileAtomically(path, usageLog());
}

}  // namespace varc::reader
