// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityColorGamut.cginc. Colour-space and HDR-display encodings: sRGB and gamma 2.2
// transfer functions, SMPTE ST 2084 (PQ), the Rec. 709 / Rec. 2020 / Display P3 primaries
// conversions and a simple paper-white HDR output encoding. Written for varc from the published
// standards (IEC 61966-2-1, SMPTE ST 2084, ITU-R BT.2087, SMPTE EG 432-1); not derived from Unity.
#ifndef UNITY_COLOR_GAMUT_INCLUDED
#define UNITY_COLOR_GAMUT_INCLUDED

// Values of UnityEngine.ColorGamut, the gamut/encoding of the display being rendered to.
#define kColorGamutSRGB         0
#define kColorGamutRec709       1
#define kColorGamutRec2020      2
#define kColorGamutDisplayP3    3
#define kColorGamutHDR10        4
#define kColorGamutDolbyHDR     5
#define kColorGamutP3D65G22     6

// Luminance (cd/m^2) of Rec. 709 / sRGB reference white.
#define kReferenceLuminanceWhiteForRec709 80

// Linear RGB primaries conversions (D65 white), applied as mul(M, rgb). Rec. 709 and sRGB share
// primaries; the Rec. 2020 pair is that of ITU-R BT.2087, the P3 pair follows from the
// primaries' chromaticities of SMPTE EG 432-1.
static const float3x3 Rec709ToRec2020 = {
    0.627403896, 0.329283039, 0.043313065,
    0.069097289, 0.919540395, 0.011362316,
    0.016391439, 0.088013308, 0.895595253};
static const float3x3 Rec2020ToRec709 = {
    1.660491002, -0.587641139, -0.072849863,
    -0.124550475, 1.132899897, -0.008349422,
    -0.018150763, -0.100578898, 1.118729661};
static const float3x3 Rec709ToP3D65Mat = {
    0.822461969, 0.177538031, 0.000000000,
    0.033194199, 0.966805801, 0.000000000,
    0.017082631, 0.072397440, 0.910519929};
static const float3x3 P3D65MatToRec709 = {
    1.224940176, -0.224940176, 0.000000000,
    -0.042056955, 1.042056955, 0.000000000,
    -0.019637555, -0.078636046, 1.098273601};

// sRGB transfer function (IEC 61966-2-1), per channel, for values in [0, 1].
float3 SRGBToLinear(float3 color) {
    float3 low = color / 12.92;
    float3 high = pow((color + 0.055) / 1.055, 2.4);
    return float3(color.r <= 0.04045 ? low.r : high.r, color.g <= 0.04045 ? low.g : high.g,
                  color.b <= 0.04045 ? low.b : high.b);
}
float3 LinearToSRGB(float3 color) {
    float3 low = color * 12.92;
    float3 high = 1.055 * pow(max(color, 0.0), 1.0 / 2.4) - 0.055;
    return float3(color.r <= 0.0031308 ? low.r : high.r, color.g <= 0.0031308 ? low.g : high.g,
                  color.b <= 0.0031308 ? low.b : high.b);
}

// Pure power-law gamma 2.2.
float3 Gamma22ToLinear(float3 color) { return pow(max(color, 0.0), 2.2); }
float3 LinearToGamma22(float3 color) { return pow(max(color, 0.0), 1.0 / 2.2); }

// SMPTE ST 2084 (PQ). Linear values are normalised so that 1 = 10000 cd/m^2.
#define PQ_M1 (2610.0 / 16384.0)
#define PQ_M2 (2523.0 / 4096.0 * 128.0)
#define PQ_C1 (3424.0 / 4096.0)
#define PQ_C2 (2413.0 / 4096.0 * 32.0)
#define PQ_C3 (2392.0 / 4096.0 * 32.0)

float3 LinearToST2084(float3 color) {
    float3 y = pow(saturate(color), PQ_M1);
    return pow((PQ_C1 + PQ_C2 * y) / (1.0 + PQ_C3 * y), PQ_M2);
}
float3 ST2084ToLinear(float3 color) {
    float3 e = pow(saturate(color), 1.0 / PQ_M2);
    return pow(max(e - PQ_C1, 0.0) / (PQ_C2 - PQ_C3 * e), 1.0 / PQ_M1);
}

// Encodes a scene-referred linear Rec. 709 colour for a display of gamut |colorGamut|: the scene
// value 1 is shown at nitsForPaperWhite cd/m^2 and clipped at maxDisplayNits.
//   sRGB, Rec709:  the colour is returned as is (an sRGB render target encodes it), or encoded
//                  with LinearToSRGB when forceGammaToLinear asks for the encoding in the shader.
//   Rec2020, HDR10, DolbyHDR: converted to Rec. 2020 primaries, scaled to cd/m^2, clipped, and
//                  PQ-encoded (LinearToST2084 of nits / 10000).
//   DisplayP3:     converted to P3 primaries, scaled to paper white / maxDisplayNits, sRGB curve.
//   P3D65G22:      converted to P3 primaries, scaled the same way, gamma 2.2.
float3 SimpleHDRDisplayToneMapAndOETF(float3 scene, int colorGamut, bool forceGammaToLinear,
                                      float nitsForPaperWhite, float maxDisplayNits) {
    if (colorGamut == kColorGamutRec2020 || colorGamut == kColorGamutHDR10 ||
        colorGamut == kColorGamutDolbyHDR) {
        float3 nits = min(mul(Rec709ToRec2020, scene) * nitsForPaperWhite, maxDisplayNits);
        return LinearToST2084(max(nits, 0.0) / 10000.0);
    }
    if (colorGamut == kColorGamutDisplayP3 || colorGamut == kColorGamutP3D65G22) {
        float3 p3 = saturate(mul(Rec709ToP3D65Mat, scene) * (nitsForPaperWhite / maxDisplayNits));
        return colorGamut == kColorGamutP3D65G22 ? LinearToGamma22(p3) : LinearToSRGB(p3);
    }
    return forceGammaToLinear ? LinearToSRGB(saturate(scene)) : scene;
}

// The inverse of SimpleHDRDisplayToneMapAndOETF where it does not clip.
float3 InverseSimpleHDRDisplayToneMapAndOETF(float3 result, int colorGamut, bool forceGammaToLinear,
                                             float nitsForPaperWhite, float maxDisplayNits) {
    if (colorGamut == kColorGamutRec2020 || colorGamut == kColorGamutHDR10 ||
        colorGamut == kColorGamutDolbyHDR) {
        float3 nits = ST2084ToLinear(result) * 10000.0;
        return mul(Rec2020ToRec709, nits / nitsForPaperWhite);
    }
    if (colorGamut == kColorGamutDisplayP3 || colorGamut == kColorGamutP3D65G22) {
        float3 p3 = colorGamut == kColorGamutP3D65G22 ? Gamma22ToLinear(result) : SRGBToLinear(result);
        return mul(P3D65MatToRec709, p3 * (maxDisplayNits / nitsForPaperWhite));
    }
    return forceGammaToLinear ? SRGBToLinear(result) : result;
}

#endif // UNITY_COLOR_GAMUT_INCLUDED
