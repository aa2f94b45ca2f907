// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityCustomRenderTexture.cginc. The vertex programs and values of Custom Render
// Texture update and initialisation shaders: update zones drawn as quads generated from
// SV_VertexID, the texture's size, cube face or 3D slice, and the texture itself as
// _SelfTexture2D/Cube/3D. Written for varc from the documented behaviour (Unity manual, "Write a
// shader for a Custom Render Texture"); not derived from Unity.
#ifndef UNITY_CUSTOM_TEXTURE_INCLUDED
#define UNITY_CUSTOM_TEXTURE_INCLUDED

#include "UnityCG.cginc"
#include "UnityStandardConfig.cginc"

// Update zones drawn per batch; each zone is two triangles (six vertices).
#define kCustomTextureBatchSize 16

// The runtime's values. _CustomRenderTextureInfo: (width, height, depth, cube face or 3D slice
// index). CustomRenderTextureParameters: x = update-zone space (0 normalised, 1 pixels),
// y = the w texture coordinate of the 3D slice, z = 1 for a 3D texture.
// Per zone: centre (xyz), size and rotation in radians (xy, z), primitive ID.
float4 _CustomRenderTextureInfo;
float4 CustomRenderTextureParameters;
float4 CustomRenderTextureCenters[kCustomTextureBatchSize];
float4 CustomRenderTextureSizesAndRotations[kCustomTextureBatchSize];
float CustomRenderTexturePrimitiveIDs[kCustomTextureBatchSize];

#define _CustomRenderTextureWidth _CustomRenderTextureInfo.x
#define _CustomRenderTextureHeight _CustomRenderTextureInfo.y
#define _CustomRenderTextureDepth _CustomRenderTextureInfo.z
#define _CustomRenderTextureCubeFace _CustomRenderTextureInfo.w
#define _CustomRenderTexture3DSlice _CustomRenderTextureInfo.w
#define CustomRenderTextureUpdateSpace CustomRenderTextureParameters.x
#define CustomRenderTexture3DTexcoordW CustomRenderTextureParameters.y
#define CustomRenderTextureIs3D CustomRenderTextureParameters.z

// The texture being updated (its previous content with double buffering).
sampler2D _SelfTexture2D;
samplerCUBE _SelfTextureCube;
sampler3D _SelfTexture3D;

struct appdata_customrendertexture {
    uint vertexID : SV_VertexID;
};

struct v2f_customrendertexture {
    float4 vertex : SV_POSITION;
    float3 localTexcoord : TEXCOORD0;   // 0..1 across the update zone
    float3 globalTexcoord : TEXCOORD1;  // 0..1 across the texture
    uint primitiveID : TEXCOORD2;       // the zone's index in the update-zone list
    float3 direction : TEXCOORD3;       // cube maps: the texel's direction
};

struct appdata_init_customrendertexture {
    float4 vertex : POSITION;
    float2 texcoord : TEXCOORD0;
};

struct v2f_init_customrendertexture {
    float4 vertex : SV_POSITION;
    float3 texcoord : TEXCOORD0;
    float3 direction : TEXCOORD1;
};

// pos rotated by angle (radians, counter-clockwise).
float2 CustomRenderTextureRotate2D(float2 pos, float angle) {
    float s = sin(angle), c = cos(angle);
    return float2(pos.x * c - pos.y * s, pos.x * s + pos.y * c);
}

// Direction of the cube-map texel at globalTexcoord (0..1 on the face _CustomRenderTextureCubeFace:
// +x, -x, +y, -y, +z, -z), with v running down the face.
float3 CustomRenderTextureComputeCubeDirection(float2 globalTexcoord) {
    float2 xy = globalTexcoord * 2.0 - 1.0;
    float3 direction;
    int face = (int)_CustomRenderTextureCubeFace;
    if (face == 0) direction = float3(1.0, -xy.y, -xy.x);
    else if (face == 1) direction = float3(-1.0, -xy.y, xy.x);
    else if (face == 2) direction = float3(xy.x, 1.0, xy.y);
    else if (face == 3) direction = float3(xy.x, -1.0, -xy.y);
    else if (face == 4) direction = float3(xy.x, -xy.y, 1.0);
    else direction = float3(-xy.x, -xy.y, -1.0);
    return normalize(direction);
}

// One quad per update zone: vertex i is corner i % 6 of zone i / 6 (two triangles), placed at the
// zone's centre, size and rotation (in texels when CustomRenderTextureUpdateSpace is 1), and
// drawn over the texture with clip xy = 2 * uv - 1 (uv 0 = first row, SHADER_ABI.md §2).
v2f_customrendertexture CustomRenderTextureVertexShader(appdata_customrendertexture IN) {
    v2f_customrendertexture OUT;
    static const float2 corners[6] = {
        float2(0, 0), float2(1, 0), float2(1, 1), float2(0, 0), float2(1, 1), float2(0, 1)};
    uint zone = IN.vertexID / 6u;
    float2 corner = corners[IN.vertexID % 6u];
    float4 centre = CustomRenderTextureCenters[zone % kCustomTextureBatchSize];
    float4 sizeAndRotation = CustomRenderTextureSizesAndRotations[zone % kCustomTextureBatchSize];
    float2 texel = float2(_CustomRenderTextureWidth, _CustomRenderTextureHeight);
    float2 scale = CustomRenderTextureUpdateSpace > 0.0 ? 1.0 / texel : 1.0;
    float2 offset = CustomRenderTextureRotate2D((corner - 0.5) * sizeAndRotation.xy, sizeAndRotation.z);
    float2 uv = centre.xy * scale + offset * scale;
    OUT.vertex = float4(uv * 2.0 - 1.0, 0.0, 1.0);
    OUT.localTexcoord = float3(corner, CustomRenderTexture3DTexcoordW);
    OUT.globalTexcoord = float3(uv, CustomRenderTexture3DTexcoordW);
    OUT.primitiveID = (uint)CustomRenderTexturePrimitiveIDs[zone % kCustomTextureBatchSize];
    OUT.direction = CustomRenderTextureComputeCubeDirection(uv);
    return OUT;
}

// Initialisation: a full-texture quad; texcoord = (uv, the 3D slice's w).
v2f_init_customrendertexture InitCustomRenderTextureVertexShader(appdata_init_customrendertexture v) {
    v2f_init_customrendertexture o;
    o.vertex = UnityObjectToClipPos(v.vertex);
    o.texcoord = float3(v.texcoord.xy, CustomRenderTexture3DTexcoordW);
    o.direction = CustomRenderTextureComputeCubeDirection(v.texcoord.xy);
    return o;
}

#endif // UNITY_CUSTOM_TEXTURE_INCLUDED
