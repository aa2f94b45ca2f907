// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityRayTracingMeshUtils.cginc (Unity 2019.4+). Mesh access for ray-tracing hit
// shaders: the triangle's vertex indices and any vertex attribute of the hit mesh, decoded from
// the mesh's raw index and vertex buffers with its vertex declaration (attribute stream, format,
// byte offset, dimension). Written for varc from the documented behaviour; the formats and
// attributes are numbered as UnityEngine.Rendering.VertexAttributeFormat / VertexAttribute.
//
// varc's runtime does not trace rays, so nothing binds these buffers yet; the functions read them
// like any storage buffer and compile in every stage. The 2019.4 per-mesh uniforms
// (unity_MeshIndexStart_RT ...) are declared for old shaders; the fetches use 2020.3's MeshInfo.
#ifndef UNITY_RAY_TRACING_MESH_UTILS_INCLUDED
#define UNITY_RAY_TRACING_MESH_UTILS_INCLUDED

#define kMaxVertexStreams 4
#define MAX_VERTEX_STREAM_COUNT kMaxVertexStreams
#define INVALID_VERTEX_ATTRIBUTE_OFFSET 0xFFFFFFFF

#define kVertexAttributePosition 0
#define kVertexAttributeNormal 1
#define kVertexAttributeTangent 2
#define kVertexAttributeColor 3
#define kVertexAttributeTexCoord0 4
#define kVertexAttributeTexCoord1 5
#define kVertexAttributeTexCoord2 6
#define kVertexAttributeTexCoord3 7
#define kVertexAttributeTexCoord4 8
#define kVertexAttributeTexCoord5 9
#define kVertexAttributeTexCoord6 10
#define kVertexAttributeTexCoord7 11
#define kVertexAttributeCount 12

#define kVertexFormatFloat 0
#define kVertexFormatFloat16 1
#define kVertexFormatUNorm8 2
#define kVertexFormatSNorm8 3
#define kVertexFormatUNorm16 4
#define kVertexFormatSNorm16 5
#define kVertexFormatUInt8 6
#define kVertexFormatSInt8 7
#define kVertexFormatUInt16 8
#define kVertexFormatSInt16 9
#define kVertexFormatUInt32 10
#define kVertexFormatSInt32 11

// One attribute of the vertex declaration; Dimension 0: the mesh lacks it.
struct VertexAttributeInfo {
    uint Stream;
    uint Format;
    uint ByteOffset;
    uint Dimension;
};

// The hit mesh's geometry: bytes per vertex of each stream, the base vertex added to indices,
// the first vertex, the index size in bytes (2 or 4) and the first index.
struct MeshInfo {
    uint vertexSize[kMaxVertexStreams];
    uint baseVertex;
    uint vertexStart;
    uint indexSize;
    uint indexStart;
};

StructuredBuffer<MeshInfo> unity_MeshInfo_RT;
StructuredBuffer<VertexAttributeInfo> unity_MeshVertexDeclaration_RT;
ByteAddressBuffer unity_MeshIndexBuffer_RT;
ByteAddressBuffer unity_MeshVertexBuffers_RT[kMaxVertexStreams];
// glslang's HLSL front end declares arrays of buffers but cannot call a method on an element, so
// the fetches read each stream from its own buffer; a runtime binds stream n to both names.
ByteAddressBuffer varc_MeshVertexBuffer0_RT;
ByteAddressBuffer varc_MeshVertexBuffer1_RT;
ByteAddressBuffer varc_MeshVertexBuffer2_RT;
ByteAddressBuffer varc_MeshVertexBuffer3_RT;
// 2019.4's single-stream layout.
ByteAddressBuffer unity_MeshVertexBuffer_RT;
uint unity_MeshIndexStart_RT;
uint unity_MeshIndexSize_RT;
uint unity_MeshStartVertex_RT;
uint unity_MeshVertexSize_RT;
uint unity_MeshBaseVertex_RT;

// Components an attribute of each dimension (0..4) provides, and the value of each attribute a
// mesh lacks (or of the components it lacks): w = 1 for positions and tangents, white colour.
// (The initialisers are macros so that scripts/builtin-api.py reads these lines as variables.)
#define VARC_RT_CHANNEL_MASKS \
    {float4(0, 0, 0, 0), float4(1, 0, 0, 0), float4(1, 1, 0, 0), float4(1, 1, 1, 0), float4(1, 1, 1, 1)}
#define VARC_RT_DEFAULT_ATTRIBUTES                                                              \
    {float4(0, 0, 0, 1), float4(0, 0, 1, 0), float4(1, 0, 0, 1), float4(1, 1, 1, 1), float4(0, 0, 0, 0), \
     float4(0, 0, 0, 0), float4(0, 0, 0, 0), float4(0, 0, 0, 0), float4(0, 0, 0, 0), float4(0, 0, 0, 0), \
     float4(0, 0, 0, 0), float4(0, 0, 0, 0)}
static float4 unity_VertexChannelMask_RT[5] = VARC_RT_CHANNEL_MASKS;
static float4 unity_DefaultVertexAttributes[kVertexAttributeCount] = VARC_RT_DEFAULT_ATTRIBUTES;

// A signed normalised 16-bit value (the low 16 bits of data) in [-1, 1].
float DecodeSNorm16(uint data) {
    int value = ((int)(data << 16)) >> 16;
    return max((float)value / 32767.0, -1.0);
}

// The three vertex indices of triangle primitiveIndex, base vertex added.
uint3 UnityRayTracingFetchTriangleIndices(uint primitiveIndex) {
    MeshInfo mesh = unity_MeshInfo_RT[0];
    uint first = mesh.indexStart + 3 * primitiveIndex;
    uint3 indices;
    if (mesh.indexSize == 2) {
        uint address = first * 2, aligned = address & ~3u;
        uint2 words = unity_MeshIndexBuffer_RT.Load2(aligned);
        // Three 16-bit indices start at a 4-byte boundary or 2 bytes past one.
        indices = address == aligned ? uint3(words.x & 0xFFFF, words.x >> 16, words.y & 0xFFFF)
                                     : uint3(words.x >> 16, words.y & 0xFFFF, words.y >> 16);
    } else {
        indices = unity_MeshIndexBuffer_RT.Load3(first * 4);
    }
    return indices + mesh.baseVertex;
}

bool UnityRayTracingHasVertexAttribute(uint attributeType) {
    return unity_MeshVertexDeclaration_RT[attributeType].Dimension != 0;
}

#include "VarcRayTracingFetch.cginc"

#endif  // UNITY_RAY_TRACING_MESH_UTILS_INCLUDED
