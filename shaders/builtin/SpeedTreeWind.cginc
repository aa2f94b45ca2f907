// SPDX-License-Identifier: Apache-2.0
// varc built-in: SpeedTreeWind.cginc. The wind model of SpeedTree vertices: a whole-tree sway
// (GlobalWind), branch oscillation (BranchWind and its styles), leaf ripple and tumble (LeafWind)
// and frond ripple (RippleFrond), driven by the _ST_Wind* uniforms the renderer sets per tree.
// Written for varc from the documented behaviour; not derived from Unity or SpeedTree.
//
// The model is deterministic (a function of position, per-vertex data, the uniforms and their
// times only) and every displacement is a product with a wind uniform: a tree whose _ST_Wind*
// uniforms are all zero does not move, and its normals do not change. Waves are
// TrigApproximate, a smooth periodic wave of period 1 (times are in cycles, not radians).
// Uniform layout (object space: the renderer rotates the wind into the tree's frame, hence the
// "rotated" wind vectors of the signatures):
//   _ST_WindVector            xyz wind direction scaled by its strength (0 = calm)
//   _ST_WindGlobal            x time, y sway distance at the reference height, z reference
//                             height, w height exponent (<= 0 is taken as 1)
//   _ST_WindBranch            x time, y distance a branch tip of weight 1 moves
//   _ST_WindBranchTwitch      x twitch share (0..1), y twitch frequency scale
//   _ST_WindBranchWhip        x extra amplitude of the tips (whip)
//   _ST_WindBranchAnchor      xyz direction palm fronds are pulled to, w its strength
//   _ST_WindBranchAdherences  x steady share of the global bend, y of the branch bend (0..1)
//   _ST_WindTurbulences       x branch turbulence (0..1: how much gusts weaken the motion)
//   _ST_WindLeaf{1,2}Ripple   x time, y ripple distance
//   _ST_WindLeaf{1,2}Tumble   x time, y flip angle, z twist angle (radians), w adherence angle
//   _ST_WindLeaf{1,2}Twitch   x twitch angle (radians), y sharpness (0..1), z time
//   _ST_WindFrondRipple       x time, y ripple distance, z ripples per unit of V
//   _ST_WindAnimation         x roll minimum scale, y roll speed, z roll ripple (per unit along
//                             the wind), w unused
#ifndef SPEEDTREE_WIND_INCLUDED
#define SPEEDTREE_WIND_INCLUDED

float4 _ST_WindVector;
float4 _ST_WindGlobal;
float4 _ST_WindBranch;
float4 _ST_WindBranchTwitch;
float4 _ST_WindBranchWhip;
float4 _ST_WindBranchAnchor;
float4 _ST_WindBranchAdherences;
float4 _ST_WindTurbulences;
float4 _ST_WindLeaf1Ripple;
float4 _ST_WindLeaf1Tumble;
float4 _ST_WindLeaf1Twitch;
float4 _ST_WindLeaf2Ripple;
float4 _ST_WindLeaf2Tumble;
float4 _ST_WindLeaf2Twitch;
float4 _ST_WindFrondRipple;
float4 _ST_WindAnimation;

#define wind_cross(a, b) cross((a), (b))

float3 mul_float3x3_float3(float3x3 mMatrix, float3 vVector) { return mul(mMatrix, vVector); }

float3x3 mul_float3x3_float3x3(float3x3 mMatrixA, float3x3 mMatrixB) {
    return mul(mMatrixA, mMatrixB);
}

// The same definitions as TerrainEngine.cginc's: whichever file comes first defines them.
#ifndef VARC_TRIANGLE_WAVE_DEFINED
#define VARC_TRIANGLE_WAVE_DEFINED
// 1 at integers, 0 at half integers, linear in between (period 1).
float4 TriangleWave(float4 vData) { return abs(frac(vData + 0.5) * 2.0 - 1.0); }
#endif

// The smoothstep polynomial 3x^2 - 2x^3 of x in [0, 1].
float4 CubicSmooth(float4 vData) { return vData * vData * (3.0 - 2.0 * vData); }

// A smooth wave in [-1, 1] of period 1, 1 at integers and -1 at half integers: a cheap
// stand-in for cos(2 pi x), 2 CubicSmooth(TriangleWave(x)) - 1.
float4 TrigApproximate(float4 vData) { return CubicSmooth(TriangleWave(vData)) * 2.0 - 1.0; }

// A direction packed into one float (each component in 16 steps): the components are the
// fractions of value / (16, 1, 1/16), mapped from [0, 1) to [-1, 1).
float3 UnpackNormalFromFloat(float fValue) {
    return frac(fValue / float3(16.0, 1.0, 0.0625)) * 2.0 - 1.0;
}

// The rotation by fAngle radians about the unit axis vAxis (right-handed, Rodrigues' formula):
// mul(RotationMatrix(a, t), v) turns v about a. A zero angle gives the identity for any axis.
float3x3 RotationMatrix(float3 vAxis, float fAngle) {
    float s = sin(fAngle), c = cos(fAngle), t = 1.0 - c;
    float3 a = vAxis;
    return float3x3(t * a.x * a.x + c, t * a.x * a.y - s * a.z, t * a.x * a.z + s * a.y,
                    t * a.x * a.y + s * a.z, t * a.y * a.y + c, t * a.y * a.z - s * a.x,
                    t * a.x * a.z - s * a.y, t * a.y * a.z + s * a.x, t * a.z * a.z + c);
}

// normalize(v), or 0 for a zero vector (a calm wind has no direction).
float3 VarcSpeedTreeSafeNormalize(float3 v) {
    float lengthSquared = dot(v, v);
    return lengthSquared > 1e-12 ? v * rsqrt(lengthSquared) : float3(0.0, 0.0, 0.0);
}

// A gust front rolling along the wind: fCurrent scaled between fMinScale and fMaxScale by a
// wave of phase fTime * fSpeed - fRipple * (distance of vPos along the wind).
float Roll(float fCurrent, float fMaxScale, float fMinScale, float fSpeed, float fRipple,
           float3 vPos, float fTime, float3 vRotatedWindVector) {
    float along = dot(vPos, VarcSpeedTreeSafeNormalize(vRotatedWindVector));
    float wave = 0.5 + 0.5 * TrigApproximate(float4(fTime * fSpeed - fRipple * along, 0, 0, 0)).x;
    return fCurrent * lerp(fMinScale, fMaxScale, wave);
}

// Sudden jerks: the product of two waves of incommensurate rates, raised to a power that grows
// with fSharpness (0..1: 1 to 16), in [0, fAmount].
float Twitch(float3 vPos, float fAmount, float fSharpness, float fTime) {
    float4 waves = TrigApproximate(float4(fTime + vPos.x + vPos.z, 0.87 * fTime + vPos.y, 0, 0));
    float combined = saturate(0.5 + 0.5 * waves.x * waves.y);
    return fAmount * pow(combined, 1.0 + 15.0 * saturate(fSharpness));
}

// The share of motion gusts leave: in [1 - fTurbulence, 1], from a slow wave of the global time
// and a faster one of the branch time.
float Turbulence(float fTime, float fOffset, float fGlobalTime, float fTurbulence) {
    float4 waves = TrigApproximate(float4(0.1 * fGlobalTime + fOffset, 1.13 * fTime + fOffset, 0, 0));
    return 1.0 - fTurbulence * (0.5 + 0.5 * waves.x * waves.y);
}

// A branch's oscillation. vOscillations receives the four waves (main, twitch, twitch partner,
// whip); the result is the main wave in [-1, 1], mixed towards the twitch product by fTwitch
// (bComplex), widened by the whip at the tips (bWhip: up to 1 + fWhip), and scaled by the rolling
// gusts of _ST_WindAnimation (bRoll).
float Oscillate(float3 vPos, float fTime, float fOffset, float fWeight, float fWhip, bool bWhip,
                bool bRoll, bool bComplex, float fTwitch, float fTwitchFreqScale,
                inout float4 vOscillations, float3 vRotatedWindVector) {
    float phase = fTime + fOffset;
    vOscillations = TrigApproximate(float4(phase, phase * fTwitchFreqScale,
                                           0.5 * phase * fTwitchFreqScale, phase + 1.0 - fWeight));
    float oscillation = vOscillations.x;
    if (bComplex) {
        oscillation = lerp(oscillation, vOscillations.y * vOscillations.z, saturate(fTwitch));
    }
    if (bWhip) oscillation *= 1.0 + fWhip * fWeight * (0.5 + 0.5 * vOscillations.w);
    if (bRoll) {
        oscillation = Roll(oscillation, 1.0, _ST_WindAnimation.x, _ST_WindAnimation.y,
                           _ST_WindAnimation.z, vPos, fTime, vRotatedWindVector);
    }
    return oscillation;
}

// A phase offset per tree, so that a forest does not sway in step.
float VarcSpeedTreeInstancePhase(float3 vInstancePos) {
    return dot(vInstancePos, float3(0.131, 0.071, 0.113));
}

// Branch sway back and forth along the wind: vPos + wind * fWeight * fDistance * oscillation
// (fWeight: 0 at the trunk, 1 at the tips).
float3 SimpleBranchWind(float3 vPos, float3 vInstancePos, float fWeight, float fOffset,
                        float fTime, float fDistance, float fTwitch, float fTwitchScale,
                        float fWhip, bool bWhip, bool bRoll, bool bComplex,
                        float3 vRotatedWindVector) {
    float4 oscillations;
    float oscillation = Oscillate(vPos, fTime, fOffset + VarcSpeedTreeInstancePhase(vInstancePos),
                                  fWeight, fWhip, bWhip, bRoll, bComplex, fTwitch, fTwitchScale,
                                  oscillations, vRotatedWindVector);
    return vPos + vRotatedWindVector * (fWeight * fDistance * oscillation);
}

// The directional styles' bend amount: a steady downwind share fAdherence plus the rest
// oscillating, weakened by gusts (bTurbulence).
float VarcSpeedTreeDirectionalBend(float3 vPos, float3 vInstancePos, float fWeight, float fOffset,
                                   float fTime, float fTurbulence, float fAdherence,
                                   float fTwitch, float fTwitchScale, float fWhip, bool bWhip,
                                   bool bRoll, bool bComplex, bool bTurbulence,
                                   float3 vRotatedWindVector) {
    float phase = fOffset + VarcSpeedTreeInstancePhase(vInstancePos);
    float4 oscillations;
    float oscillation = Oscillate(vPos, fTime, phase, fWeight, fWhip, bWhip, bRoll, bComplex,
                                  fTwitch, fTwitchScale, oscillations, vRotatedWindVector);
    if (bTurbulence) oscillation *= Turbulence(fTime, phase, _ST_WindGlobal.x, fTurbulence);
    float adherence = saturate(fAdherence);
    return adherence + (1.0 - adherence) * oscillation;
}

// Branches pushed downwind: vPos + wind * fWeight * fDistance * bend.
float3 DirectionalBranchWind(float3 vPos, float3 vInstancePos, float fWeight, float fOffset,
                             float fTime, float fDistance, float fTurbulence, float fAdherence,
                             float fTwitch, float fTwitchScale, float fWhip, bool bWhip,
                             bool bRoll, bool bComplex, bool bTurbulence,
                             float3 vRotatedWindVector) {
    float bend = VarcSpeedTreeDirectionalBend(vPos, vInstancePos, fWeight, fOffset, fTime,
                                              fTurbulence, fAdherence, fTwitch, fTwitchScale,
                                              fWhip, bWhip, bRoll, bComplex, bTurbulence,
                                              vRotatedWindVector);
    return vPos + vRotatedWindVector * (fWeight * fDistance * bend);
}

// Palm fronds: as DirectionalBranchWind, plus a steady pull towards vRotatedBranchAnchor that
// grows with the wind's strength.
float3 DirectionalBranchWindFrondStyle(float3 vPos, float3 vInstancePos, float fWeight,
                                       float fOffset, float fTime, float fDistance,
                                       float fTurbulence, float fAdherence, float fTwitch,
                                       float fTwitchScale, float fWhip, bool bWhip, bool bRoll,
                                       bool bComplex, bool bTurbulence, float3 vRotatedWindVector,
                                       float3 vRotatedBranchAnchor) {
    float bend = VarcSpeedTreeDirectionalBend(vPos, vInstancePos, fWeight, fOffset, fTime,
                                              fTurbulence, fAdherence, fTwitch, fTwitchScale,
                                              fWhip, bWhip, bRoll, bComplex, bTurbulence,
                                              vRotatedWindVector);
    float3 pull = vRotatedBranchAnchor * (length(vRotatedWindVector) * saturate(fAdherence));
    return vPos + (vRotatedWindVector * bend + pull) * (fWeight * fDistance);
}

// A branch vertex's wind: vWindData = (weight, phase offset, unused, unused) from the vertex;
// the palm style for palm trees, the simple style otherwise, with the _ST_WindBranch* uniforms.
float3 BranchWind(bool isPalmWind, float3 vPos, float3 vInstancePos, float4 vWindData,
                  float3 vRotatedWindVector, float3 vRotatedBranchAnchor) {
    if (isPalmWind) {
        return DirectionalBranchWindFrondStyle(
            vPos, vInstancePos, vWindData.x, vWindData.y, _ST_WindBranch.x, _ST_WindBranch.y,
            _ST_WindTurbulences.x, _ST_WindBranchAdherences.y, _ST_WindBranchTwitch.x,
            _ST_WindBranchTwitch.y, _ST_WindBranchWhip.x, true, false, true, true,
            vRotatedWindVector, vRotatedBranchAnchor);
    }
    return SimpleBranchWind(vPos, vInstancePos, vWindData.x, vWindData.y, _ST_WindBranch.x,
                            _ST_WindBranch.y, _ST_WindBranchTwitch.x, _ST_WindBranchTwitch.y,
                            _ST_WindBranchWhip.x, false, false, true, vRotatedWindVector);
}

// ---------------------------------------------------------------------------------------------
// Leaves and fronds.
// ---------------------------------------------------------------------------------------------
// A leaf moving along a direction: vPos + direction * fScale * fAmount * wave(fTime +
// fTrigOffset); the direction is the packed ripple direction (bDirectional) or vDirection (the
// leaf's normal, which is left as it is).
float3 LeafRipple(float3 vPos, inout float3 vDirection, float fScale, float fPackedRippleDir,
                  float fTime, float fAmount, bool bDirectional, float fTrigOffset) {
    float wave = TrigApproximate(float4(fTime + fTrigOffset, 0, 0, 0)).x;
    float3 direction = bDirectional ? UnpackNormalFromFloat(fPackedRippleDir) : vDirection;
    return vPos + direction * (fScale * fAmount * wave);
}

// A leaf card turning about its anchor: a flip about the axis across the wind and the growth
// direction, and a twist about the growth direction, with angles fFlip * wave and fTwist *
// wave (plus fAdherence: the steady turn into the wind, and vTwitch = (angle, sharpness, time)
// jerks with bTwitch), all times fScale and the wind's strength; rolling gusts vRoll = (max
// scale, min scale, speed, ripple) scale the angles with bRoll. The leaf's normal vDirection
// turns with it.
float3 LeafTumble(float3 vPos, inout float3 vDirection, float fScale, float3 vAnchor,
                  float3 vGrowthDir, float fTrigOffset, float fTime, float fFlip, float fTwist,
                  float fAdherence, float3 vTwitch, float4 vRoll, bool bTwitch, bool bRoll,
                  float3 vRotatedWindVector) {
    float strength = length(vRotatedWindVector) * fScale;
    float4 waves = TrigApproximate(float4(fTime + fTrigOffset, 0.75 * fTime + 1.3 * fTrigOffset, 0, 0));
    float flip = fFlip * waves.x + fAdherence;
    float twist = fTwist * waves.y;
    if (bTwitch) flip += Twitch(vAnchor, vTwitch.x, vTwitch.y, vTwitch.z + fTrigOffset);
    if (bRoll) {
        float roll = Roll(1.0, vRoll.x, vRoll.y, vRoll.z, vRoll.w, vAnchor, fTime, vRotatedWindVector);
        flip *= roll;
        twist *= roll;
    }
    float3 growth = VarcSpeedTreeSafeNormalize(vGrowthDir);
    float3 across = VarcSpeedTreeSafeNormalize(wind_cross(growth, vRotatedWindVector));
    float3x3 rotation = mul_float3x3_float3x3(RotationMatrix(growth, twist * strength),
                                              RotationMatrix(across, flip * strength));
    vDirection = mul_float3x3_float3(rotation, vDirection);
    return vAnchor + mul_float3x3_float3(rotation, vPos - vAnchor);
}

// A leaf vertex's wind with the uniforms of leaf group 1 or 2 (bLeaf2): a directional ripple
// along the packed ripple direction, and with the best quality (isBestWind) the tumble about
// vAnchor with the packed growth direction.
float3 LeafWind(bool isBestWind, bool bLeaf2, float3 vPos, inout float3 vDirection, float fScale,
                float3 vAnchor, float fPackedGrowthDir, float fPackedRippleDir,
                float fRippleTrigOffset, float3 vRotatedWindVector) {
    float4 ripple = bLeaf2 ? _ST_WindLeaf2Ripple : _ST_WindLeaf1Ripple;
    vPos = LeafRipple(vPos, vDirection, fScale, fPackedRippleDir, ripple.x, ripple.y, true,
                      fRippleTrigOffset);
    if (isBestWind) {
        float4 tumble = bLeaf2 ? _ST_WindLeaf2Tumble : _ST_WindLeaf1Tumble;
        float4 twitch = bLeaf2 ? _ST_WindLeaf2Twitch : _ST_WindLeaf1Twitch;
        vPos = LeafTumble(vPos, vDirection, fScale, vAnchor, UnpackNormalFromFloat(fPackedGrowthDir),
                          fRippleTrigOffset, tumble.x, tumble.y, tumble.z, tumble.w, twitch.xyz,
                          float4(1.0, 1.0, 0.0, 0.0), true, false, vRotatedWindVector);
    }
    return vPos;
}

// The frond ripple wave at V coordinate fV (_ST_WindFrondRipple: time, distance, ripples per
// unit of V): its value and its slope along V, both times fRippleScale * distance.
float2 VarcSpeedTreeFrondWave(float fV, float fRippleScale) {
    float phase = _ST_WindFrondRipple.x + fV * _ST_WindFrondRipple.z;
    float amplitude = fRippleScale * _ST_WindFrondRipple.y;
    float4 waves = TrigApproximate(float4(phase, phase + 0.25, 0, 0));
    return amplitude * float2(waves.x, -waves.y * _ST_WindFrondRipple.z);
}

// A one-sided frond rippling along its normal vDirection, more towards its edges (|fU - 0.5|
// from the midrib at U = 0.5); the normal tilts along the binormal by the wave's slope.
float3 RippleFrondOneSided(float3 vPos, inout float3 vDirection, float fU, float fV,
                           float fRippleScale, float3 vBinormal, float3 vTangent) {
    float2 wave = VarcSpeedTreeFrondWave(fV, fRippleScale) * (2.0 * abs(fU - 0.5));
    float3 moved = vPos + vDirection * wave.x;
    vDirection -= vBinormal * wave.y;
    return moved;
}

// A two-sided frond rippling along its packed ripple direction, more towards its tip
// (fLengthPercent: 0 at the base, 1 at the tip).
float3 RippleFrondTwoSided(float3 vPos, inout float3 vDirection, float fU, float fLengthPercent,
                           float fPackedRippleDir, float fRippleScale, float3 vBinormal,
                           float3 vTangent) {
    float2 wave = VarcSpeedTreeFrondWave(fU, fRippleScale) * fLengthPercent;
    float3 moved = vPos + UnpackNormalFromFloat(fPackedRippleDir) * wave.x;
    vDirection -= vTangent * wave.y;
    return moved;
}

// Fronds with a packed ripple direction (fPackedRippleDir > 0) are two-sided.
float3 RippleFrond(float3 vPos, inout float3 vDirection, float fU, float fV,
                   float fPackedRippleDir, float fRippleScale, float fLenghtPercent,
                   float3 vBinormal, float3 vTangent) {
    if (fPackedRippleDir > 0.0) {
        return RippleFrondTwoSided(vPos, vDirection, fU, fLenghtPercent, fPackedRippleDir,
                                   fRippleScale, vBinormal, vTangent);
    }
    return RippleFrondOneSided(vPos, vDirection, fU, fV, fRippleScale, vBinormal, vTangent);
}

// The whole tree bending downwind (Y up, the tree's base at the origin): the horizontal offset
// wind.xz * _ST_WindGlobal.y * (height / reference)^exponent * (adherence + (1 - adherence) *
// sway), sway in [0, 1]: never upwind, nothing below a zero height. With bPreserveShape the
// result is scaled back to the vertex's distance from the base (a bend, not a stretch: the crown
// above the trunk sinks as it leans).
float3 GlobalWind(float3 vPos, float3 vInstancePos, bool bPreserveShape,
                  float3 vRotatedWindVector, float time) {
    float exponent = _ST_WindGlobal.w > 0.0 ? _ST_WindGlobal.w : 1.0;
    float height = max(vPos.y, 0.0) / max(_ST_WindGlobal.z, 1e-4);
    float phase = time + VarcSpeedTreeInstancePhase(vInstancePos);
    float4 waves = TrigApproximate(float4(phase, 0.71 * phase, 0, 0));
    float sway = saturate(0.5 + 0.35 * waves.x + 0.15 * waves.y);
    float adherence = saturate(_ST_WindBranchAdherences.x);
    float amount = _ST_WindGlobal.y * pow(height, exponent) * (adherence + (1.0 - adherence) * sway);
    float3 moved = vPos + float3(vRotatedWindVector.x, 0.0, vRotatedWindVector.z) * amount;
    if (bPreserveShape) {
        float movedLength = length(moved);
        moved *= movedLength > 1e-6 ? length(vPos) / movedLength : 1.0;
    }
    return moved;
}

#endif // SPEEDTREE_WIND_INCLUDED
