// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityStandardCoreForward.cginc. The forward entry points of the Standard shader
// under the names its passes use (vertBase/fragBase, vertAdd/fragAdd). varc has no separate
// "simple" path (UNITY_STANDARD_SIMPLE is 0): both map to UnityStandardCore.cginc. Written for varc.
#ifndef UNITY_STANDARD_CORE_FORWARD_INCLUDED
#define UNITY_STANDARD_CORE_FORWARD_INCLUDED

#include "UnityStandardConfig.cginc"
#include "UnityStandardCore.cginc"

VertexOutputForwardBase vertBase(VertexInput v) { return vertForwardBase(v); }
VertexOutputForwardAdd vertAdd(VertexInput v) { return vertForwardAdd(v); }
half4 fragBase(VertexOutputForwardBase i) : SV_Target { return fragForwardBaseInternal(i); }
half4 fragAdd(VertexOutputForwardAdd i) : SV_Target { return fragForwardAddInternal(i); }

#endif // UNITY_STANDARD_CORE_FORWARD_INCLUDED
