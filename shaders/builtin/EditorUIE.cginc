// SPDX-License-Identifier: Apache-2.0
// varc built-in: EditorUIE.cginc (Unity 2020.3 / 2021.3). UI Toolkit's editor shader: the editor
// renders its UI in gamma space whatever the project's colour space, so UnityUIE.cginc is
// included in gamma mode with 8-bit fragment types, and uie_editor_frag converts the standard
// fragment to linear when the editor's target is linear (_EditorColorSpace = 1). Written for varc
// from the documented behaviour.
#ifndef UNITY_EDITOR_UIE_INCLUDED
#define UNITY_EDITOR_UIE_INCLUDED

#define UIE_CUSTOM_SHADER 1
#define UIE_COLORSPACE_GAMMA 1
#define UIE_FRAG_T fixed4
#define UIE_FRAG_SCALAR_T fixed
#define UIE_NOINTERPOLATION nointerpolation

#include "UnityUIE.cginc"

fixed _EditorColorSpace;  // 1: the editor's render target is linear

fixed4 uie_editor_frag(v2f IN) {
    fixed4 color = uie_std_frag(IN);
    if (_EditorColorSpace > 0.5)
        color.rgb = uie_gamma_to_linear(color.rgb);
    return color;
}

#endif  // UNITY_EDITOR_UIE_INCLUDED
