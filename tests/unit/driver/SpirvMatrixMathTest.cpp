// SPDX-License-Identifier: Apache-2.0
// splitMatrixExtendedMath: HLSL's componentwise intrinsics on matrices become valid SPIR-V.
#include <gtest/gtest.h>

#include "varc/driver/GlslangFrontend.h"
#include "varc/driver/SpirvMatrixMath.h"
#include "varc/driver/SpirvOptimizer.h"
#include "varc/variants/PassKeywords.h"

namespace varc::driver {
namespace {

std::vector<uint32_t> compileFragment(const char* source) {
    CompileOutput compiled =
        compileProgram({source, "", shaderlab::ProgramLanguage::Cg, Stage::Fragment, "frag"});
    EXPECT_TRUE(compiled.ok) << compiled.log;
    return compiled.spirv;
}

TEST(SpirvMatrixMath, ComponentwiseIntrinsicsOnMatricesValidateAfterTheSplit) {
    std::vector<uint32_t> spirv = compileFragment(R"(
float3x3 _A, _B;
float _W;
float4 frag(float3 v : TEXCOORD0) : SV_Target {
    float3x3 m = lerp(_A, _B, _W) + lerp(_A, _B, _B) + saturate(_A) + pow(abs(_A), _B) +
                 smoothstep(_A, _B, 0.5) + max(_A, 1);
    return float4(mul(m, v), 1);
})");
    ASSERT_TRUE(validateSpirv(spirv).has_value());  // glslang's module, as it comes
    std::vector<uint32_t> split = splitMatrixExtendedMath(spirv);
    EXPECT_FALSE(validateSpirv(split).has_value()) << *validateSpirv(split);
    SpirvResult optimized = optimizeSpirv(split, OptimizationLevel::Performance);
    ASSERT_TRUE(optimized.ok) << optimized.message;
    EXPECT_FALSE(validateSpirv(optimized.spirv).has_value());
}

TEST(SpirvMatrixMath, ModulesWithoutMatrixMathAreReturnedWordForWord) {
    std::vector<uint32_t> spirv = compileFragment(R"(
float3x3 _A;
float4 frag(float3 v : TEXCOORD0) : SV_Target {
    return float4(lerp(v, mul(_A, v), 0.5), determinant(_A));
})");
    EXPECT_EQ(splitMatrixExtendedMath(spirv), spirv);
    std::vector<uint32_t> notSpirv = {1, 2, 3, 4, 5, 6};
    EXPECT_EQ(splitMatrixExtendedMath(notSpirv), notSpirv);
}

}  // namespace
}  // namespace varc::driver
