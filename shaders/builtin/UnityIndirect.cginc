// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityIndirect.cginc. Helpers of indirect draws (Graphics.RenderPrimitivesIndirect
// and RenderMeshIndirect, Unity 2021.3+): the draw's command id, its arguments read back from the
// arguments buffer, and vertex / instance ids relative to the draw's first vertex and instance.
// Written for varc from the documented behaviour.
#ifndef UNITY_INDIRECT_INCLUDED
#define UNITY_INDIRECT_INCLUDED

// The first command of the current multi-draw, set by the engine per draw call.
uint unity_BaseCommandID;
// Also a macro, so that a shader can test `#ifdef unity_BaseCommandID`.
#define unity_BaseCommandID unity_BaseCommandID

// The arguments of one command as Vulkan's VkDrawIndirectCommand and VkDrawIndexedIndirectCommand
// (and Direct3D's) lay them out: 4 and 5 consecutive uints.
struct IndirectDrawArgs {
    uint vertexCountPerInstance;
    uint instanceCount;
    uint startVertex;
    uint startInstance;
};
struct IndirectDrawIndexedArgs {
    uint indexCountPerInstance;
    uint instanceCount;
    uint startIndex;
    uint baseVertexIndex;
    uint startInstance;
};

// The command this draw executes: the multi-draw's base plus the draw index within it.
uint GetCommandID(uint svDrawID) {
    return unity_BaseCommandID + svDrawID;
}

void GetIndirectDrawArgs(out IndirectDrawArgs args, ByteAddressBuffer argsBuffer, uint commandId) {
    uint4 words = argsBuffer.Load4(commandId * 16);
    args.vertexCountPerInstance = words.x;
    args.instanceCount = words.y;
    args.startVertex = words.z;
    args.startInstance = words.w;
}
void GetIndirectDrawArgs(out IndirectDrawIndexedArgs args, ByteAddressBuffer argsBuffer, uint commandId) {
    uint offset = commandId * 20;
    uint4 words = argsBuffer.Load4(offset);
    args.indexCountPerInstance = words.x;
    args.instanceCount = words.y;
    args.startIndex = words.z;
    args.baseVertexIndex = words.w;
    args.startInstance = argsBuffer.Load(offset + 16);
}

uint GetIndirectVertexCount(IndirectDrawArgs args) {
    return args.vertexCountPerInstance;
}
uint GetIndirectVertexCount(IndirectDrawIndexedArgs args) {
    return args.indexCountPerInstance;
}
uint GetIndirectInstanceCount(IndirectDrawArgs args) {
    return args.instanceCount;
}
uint GetIndirectInstanceCount(IndirectDrawIndexedArgs args) {
    return args.instanceCount;
}

// Vertex ids: *_Base is the id counting from the buffer's start (the draw's first vertex, or the
// indexed draw's base vertex, included); the other is relative to the draw. Vulkan's and
// OpenGL's vertex index already includes the first vertex; other APIs' does not.
#if defined(SHADER_API_GLCORE) || defined(SHADER_API_VULKAN)
uint GetIndirectVertexID_Base(IndirectDrawArgs args, uint svVertexID) {
    return svVertexID;
}
uint GetIndirectVertexID(IndirectDrawArgs args, uint svVertexID) {
    return svVertexID - args.startVertex;
}
#else
uint GetIndirectVertexID_Base(IndirectDrawArgs args, uint svVertexID) {
    return svVertexID + args.startVertex;
}
uint GetIndirectVertexID(IndirectDrawArgs args, uint svVertexID) {
    return svVertexID;
}
#endif
uint GetIndirectVertexID_Base(IndirectDrawIndexedArgs args, uint svVertexID) {
    return svVertexID;
}
uint GetIndirectVertexID(IndirectDrawIndexedArgs args, uint svVertexID) {
    return svVertexID - args.baseVertexIndex;
}

// Instance ids, likewise: Vulkan's instance index includes the first instance, Direct3D's not.
#if defined(SHADER_API_VULKAN)
uint GetIndirectInstanceID_Base(IndirectDrawArgs args, uint svInstanceID) {
    return svInstanceID;
}
uint GetIndirectInstanceID_Base(IndirectDrawIndexedArgs args, uint svInstanceID) {
    return svInstanceID;
}
uint GetIndirectInstanceID(IndirectDrawArgs args, uint svInstanceID) {
    return svInstanceID - args.startInstance;
}
uint GetIndirectInstanceID(IndirectDrawIndexedArgs args, uint svInstanceID) {
    return svInstanceID - args.startInstance;
}
#else
uint GetIndirectInstanceID_Base(IndirectDrawArgs args, uint svInstanceID) {
    return svInstanceID + args.startInstance;
}
uint GetIndirectInstanceID_Base(IndirectDrawIndexedArgs args, uint svInstanceID) {
    return svInstanceID + args.startInstance;
}
uint GetIndirectInstanceID(IndirectDrawArgs args, uint svInstanceID) {
    return svInstanceID;
}
uint GetIndirectInstanceID(IndirectDrawIndexedArgs args, uint svInstanceID) {
    return svInstanceID;
}
#endif

// With UNITY_INDIRECT_DRAW_ARGS defined (IndirectDrawArgs or IndirectDrawIndexedArgs) before the
// include: the arguments are read once per invocation (InitIndirectDrawArgs) from
// unity_IndirectDrawArgs and the one-argument helpers use them.
#if defined(UNITY_INDIRECT_DRAW_ARGS)
ByteAddressBuffer unity_IndirectDrawArgs;
static UNITY_INDIRECT_DRAW_ARGS globalIndirectDrawArgs;

void InitIndirectDrawArgs(uint svDrawID) {
    GetIndirectDrawArgs(globalIndirectDrawArgs, unity_IndirectDrawArgs, GetCommandID(svDrawID));
}
uint GetIndirectVertexCount() {
    return GetIndirectVertexCount(globalIndirectDrawArgs);
}
uint GetIndirectInstanceCount() {
    return GetIndirectInstanceCount(globalIndirectDrawArgs);
}
uint GetIndirectVertexID_Base(uint svVertexID) {
    return GetIndirectVertexID_Base(globalIndirectDrawArgs, svVertexID);
}
uint GetIndirectVertexID(uint svVertexID) {
    return GetIndirectVertexID(globalIndirectDrawArgs, svVertexID);
}
uint GetIndirectInstanceID_Base(uint svInstanceID) {
    return GetIndirectInstanceID_Base(globalIndirectDrawArgs, svInstanceID);
}
uint GetIndirectInstanceID(uint svInstanceID) {
    return GetIndirectInstanceID(globalIndirectDrawArgs, svInstanceID);
}
#endif

#endif  // UNITY_INDIRECT_INCLUDED
