// SPDX-License-Identifier: Apache-2.0
// varc built-in, part of UnityRayTracingMeshUtils.cginc: vertex attribute fetches, decoding each
// VertexAttributeFormat from the raw vertex buffers. Written for varc.
#include "UnityRayTracingMeshUtils.cginc"
#ifndef VARC_RAY_TRACING_FETCH_INCLUDED
#define VARC_RAY_TRACING_FETCH_INCLUDED

// The 32-bit word at a 4-byte aligned address of vertex stream |streamIndex|.
uint VarcRT_LoadWord(uint streamIndex, uint address) {
    if (streamIndex == 1)
        return varc_MeshVertexBuffer1_RT.Load(address);
    if (streamIndex == 2)
        return varc_MeshVertexBuffer2_RT.Load(address);
    if (streamIndex == 3)
        return varc_MeshVertexBuffer3_RT.Load(address);
    return varc_MeshVertexBuffer0_RT.Load(address);
}

// Component |c| (of |bytes| bytes) of the attribute at |address|, as an unsigned integer.
uint VarcRT_LoadBits(uint streamIndex, uint address, uint c, uint bytes) {
    uint at = address + c * bytes, word = VarcRT_LoadWord(streamIndex, at & ~3u);
    uint shift = (at & 3u) * 8u;
    return bytes == 4 ? word : (word >> shift) & (bytes == 2 ? 0xFFFFu : 0xFFu);
}

// One component decoded by format.
float VarcRT_Decode(uint bits, uint format) {
    switch (format) {
    case kVertexFormatFloat: return asfloat(bits);
    case kVertexFormatFloat16: return f16tof32(bits);
    case kVertexFormatUNorm8: return bits / 255.0;
    case kVertexFormatSNorm8: return max((float)(((int)(bits << 24)) >> 24) / 127.0, -1.0);
    case kVertexFormatUNorm16: return bits / 65535.0;
    case kVertexFormatSNorm16: return DecodeSNorm16(bits);
    case kVertexFormatUInt8:
    case kVertexFormatUInt16:
    case kVertexFormatUInt32: return (float)bits;
    case kVertexFormatSInt8: return (float)(((int)(bits << 24)) >> 24);
    case kVertexFormatSInt16: return (float)(((int)(bits << 16)) >> 16);
    default: return (float)(int)bits;
    }
}

// Attribute attributeType of vertex vertexIndex: the mesh's components, the default value
// (unity_DefaultVertexAttributes) for the components or the attribute it lacks.
float4 UnityRayTracingFetchVertexAttribute4(uint vertexIndex, uint attributeType) {
    VertexAttributeInfo info = unity_MeshVertexDeclaration_RT[attributeType];
    float4 fallback = unity_DefaultVertexAttributes[attributeType];
    if (info.Dimension == 0)
        return fallback;
    MeshInfo mesh = unity_MeshInfo_RT[0];
    uint bytes = info.Format == kVertexFormatFloat || info.Format >= kVertexFormatUInt32 ? 4
        : (info.Format == kVertexFormatUNorm8 || info.Format == kVertexFormatSNorm8
           || info.Format == kVertexFormatUInt8 || info.Format == kVertexFormatSInt8 ? 1 : 2);
    uint address = vertexIndex * mesh.vertexSize[info.Stream] + info.ByteOffset;
    float4 value = fallback;
    for (uint c = 0; c < min(info.Dimension, 4u); ++c)
        value[c] = VarcRT_Decode(VarcRT_LoadBits(info.Stream, address, c, bytes), info.Format);
    float4 mask = unity_VertexChannelMask_RT[min(info.Dimension, 4u)];
    return value * mask + fallback * (1 - mask);
}
float3 UnityRayTracingFetchVertexAttribute3(uint vertexIndex, uint attributeType) {
    return UnityRayTracingFetchVertexAttribute4(vertexIndex, attributeType).xyz;
}
float2 UnityRayTracingFetchVertexAttribute2(uint vertexIndex, uint attributeType) {
    return UnityRayTracingFetchVertexAttribute4(vertexIndex, attributeType).xy;
}

#endif  // VARC_RAY_TRACING_FETCH_INCLUDED
