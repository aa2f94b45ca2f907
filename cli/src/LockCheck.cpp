// SPDX-License-Identifier: Apache-2.0
// Compares current variant counts with a lock file: the CI gate behind `varc check`.
#include "varc/cli/LockCheck.h"
#include "varc/cli/VariantReport.h"

#include <algorithm>
#include <map>
#include <sstream>

namespace varc::cli {

namespace {

std::string describeSet(const LockedSet& set) {
    std::string text = set.directive + ":";
    for (const std::string& keyword : set.keywords) text += " " + keyword;
    return text;
}

std::string signedDelta(uint64_t from, uint64_t to) {
    std::ostringstream out;
    if (to >= from) {
        out << "+" << (to - from);
    } else {
        out << "-" << (from - to);
    }
    return out.str();
}

// Whether growing from |locked| to |now| variants is within |policy| (equality always is).
bool allowed(uint64_t locked, uint64_t now, const CheckPolicy& policy) {
    if (policy.budget) return now <= *policy.budget;
    if (policy.maxGrowth) {
        if (now <= locked) return true;
        double limit = policy.maxGrowth->percent
                           ? static_cast<double>(locked) * policy.maxGrowth->amount / 100.0
                           : policy.maxGrowth->amount;
        return static_cast<double>(now - locked) <= limit;
    }
    return now == locked;
}

// Notes naming the pragma lines whose sets differ between |locked| and |current|.
std::vector<DiagnosticNote> setChanges(const LockedPass& locked,
                                       const frontend::LoadedPass& current) {
    std::vector<DiagnosticNote> notes;
    LockedPass now = makeLockedPass(current);
    for (size_t i = 0; i < now.sets.size(); ++i) {
        if (std::find(locked.sets.begin(), locked.sets.end(), now.sets[i]) == locked.sets.end()) {
            notes.push_back({current.keywords.sets[i].location,
                             "keyword set added: " + describeSet(now.sets[i])});
        }
    }
    for (const LockedSet& set : locked.sets) {
        if (std::find(now.sets.begin(), now.sets.end(), set) == now.sets.end()) {
            notes.push_back({current.pass->location,
                             "keyword set removed (was in the lock): " + describeSet(set)});
        }
    }
    if (now.skipped != locked.skipped) {
        notes.push_back({current.pass->location, "skip_variants changed"});
    }
    return notes;
}

class ShaderComparison {
public:
    ShaderComparison(const CheckPolicy& policy, DiagnosticSink& sink)
        : mPolicy(policy), mSink(sink) {}

    bool passed() const { return mPassed; }

    void compare(const LockedShader* locked, const frontend::LoadedShader& shader) {
        uint64_t before = locked ? locked->variants : 0;
        uint64_t now = shader.variantCount();
        bool ok = allowed(before, now, mPolicy);
        std::string budget =
            mPolicy.budget ? " (budget " + std::to_string(*mPolicy.budget) + ")" : "";
        if (!locked) {
            report(ok && isLenient(), shader.ast.location,
                   "shader \"" + shader.ast.name + "\" is not in the lock file (" +
                       std::to_string(now) + " variants" + budget + ")",
                   {});
            return;
        }
        // With an allowance the shader total decides; strict mode judges each pass below.
        if (isLenient() && (!ok || before != now)) {
            report(ok, shader.ast.location,
                   "shader \"" + shader.ast.name + "\": " + std::to_string(now) +
                       " variants, lock has " + std::to_string(before) + " (" +
                       signedDelta(before, now) + ")" + budget,
                   {});
        }
        comparePasses(*locked, shader);
    }

    void reportRemoved(const LockedShader& locked) {
        report(isLenient(), {},
               "shader \"" + locked.name + "\" (" + locked.file +
                   ") is in the lock file but was not found",
               {});
    }

private:
    void comparePasses(const LockedShader& locked, const frontend::LoadedShader& shader) {
        for (const frontend::LoadedPass& pass : shader.passes) {
            auto it = std::find_if(locked.passes.begin(), locked.passes.end(),
                                   [&](const LockedPass& p) { return p.index == pass.index; });
            uint64_t now = pass.variantCount();
            std::string what = frontend::describePass(shader.ast, *pass.pass, pass.index);
            if (it == locked.passes.end()) {
                report(isLenient(), pass.pass->location,
                       what + " is not in the lock file (" + std::to_string(now) + " variants)",
                       {});
            } else if (it->variants != now) {
                report(isLenient(), pass.pass->location,
                       what + ": " + std::to_string(now) + " variants, lock has " +
                           std::to_string(it->variants) + " (" + signedDelta(it->variants, now) +
                           ")",
                       changesOf(*it, pass));
            }
        }
        for (const LockedPass& lockedPass : locked.passes) {
            bool present = std::any_of(shader.passes.begin(), shader.passes.end(),
                                       [&](const auto& p) { return p.index == lockedPass.index; });
            if (!present) {
                report(isLenient(), shader.ast.location,
                       "pass " + std::to_string(lockedPass.index) + " of shader \"" +
                           shader.ast.name + "\" is in the lock file (" +
                           std::to_string(lockedPass.variants) + " variants) but no longer exists",
                       {});
            }
        }
    }

    // The set changes, then (with a project) the stage at which the counts part.
    static std::vector<DiagnosticNote> changesOf(const LockedPass& locked,
                                                 const frontend::LoadedPass& pass) {
        std::vector<DiagnosticNote> notes = setChanges(locked, pass);
        if (locked.stages && pass.plan) {
            const LockedStages& was = *locked.stages;
            frontend::VariantStageCounts now = pass.plan->counts;
            notes.push_back({pass.pass->location,
                             "lock: " + stagesText({was.declared, was.materials, was.settings,
                                                    was.rules}) +
                                 "; now: " + stagesText(now)});
        }
        return notes;
    }

    // Pass-level differences only fail the strict (no allowance) gate; with an allowance the
    // shader totals decide.
    bool isLenient() const { return mPolicy.budget || mPolicy.maxGrowth; }

    void report(bool ok, SourceLocation location, std::string message,
                std::vector<DiagnosticNote> notes) {
        if (!ok) mPassed = false;
        mSink.report({ok ? Severity::Warning : Severity::Error, location, std::move(message),
                      std::move(notes)});
    }

    const CheckPolicy& mPolicy;
    DiagnosticSink& mSink;
    bool mPassed = true;
};

}  // namespace

bool checkAgainstLock(const LockFile& lock, const std::vector<frontend::LoadedShader>& shaders,
                      const CheckPolicy& policy, DiagnosticSink& sink) {
    std::map<std::string, const LockedShader*> byName;
    for (const LockedShader& locked : lock.shaders) byName[locked.name] = &locked;
    ShaderComparison comparison(policy, sink);
    for (const frontend::LoadedShader& shader : shaders) {
        auto it = byName.find(shader.ast.name);
        comparison.compare(it == byName.end() ? nullptr : it->second, shader);
        if (it != byName.end()) byName.erase(it);
    }
    for (const auto& [name, locked] : byName) comparison.reportRemoved(*locked);
    return comparison.passed();
}

}  // namespace varc::cli
