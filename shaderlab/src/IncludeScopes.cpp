// SPDX-License-Identifier: Apache-2.0
// Tracks which *INCLUDE blocks are in scope for which passes while a shader is parsed.
#include "IncludeScopes.h"

#include <algorithm>

#include "varc/core/Check.h"

namespace varc::shaderlab {

void IncludeScopes::enter() { mOpen.push_back(mNextId++); }

void IncludeScopes::leave() {
    VARC_CHECK(!mOpen.empty()) << "IncludeScopes::leave without enter";
    mOpen.pop_back();
}

void IncludeScopes::addInclude(ProgramBlock block) {
    VARC_CHECK(!mOpen.empty()) << "include block outside any scope";
    mIncludes.emplace_back(mOpen.back(), std::move(block));
}

void IncludeScopes::addPass(size_t subShader, size_t pass) {
    mPasses.push_back(PassScopes{subShader, pass, mOpen});
}

void IncludeScopes::assignTo(ShaderFile& shader) const {
    for (const PassScopes& entry : mPasses) {
        VARC_CHECK(entry.subShader < shader.subShaders.size()) << "stale subshader index";
        std::vector<Pass>& passes = shader.subShaders[entry.subShader].passes;
        VARC_CHECK(entry.pass < passes.size()) << "stale pass index";
        std::vector<ProgramBlock>& blocks = passes[entry.pass].includeBlocks;
        blocks.clear();
        for (const auto& [scope, block] : mIncludes) {
            if (std::find(entry.scopes.begin(), entry.scopes.end(), scope) != entry.scopes.end()) {
                blocks.push_back(block);
            }
        }
    }
}

}  // namespace varc::shaderlab
