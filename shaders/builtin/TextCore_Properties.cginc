// SPDX-License-Identifier: Apache-2.0
// varc built-in: TextCore_Properties.cginc. Unity 2021.3's name of the TextCore SDF material
// properties; the declarations live in TextCoreProperties.cginc (2022.3's name), so including
// both declares each property once. Written for varc.
#ifndef VARC_TEXTCORE__PROPERTIES_INCLUDED
#define VARC_TEXTCORE__PROPERTIES_INCLUDED

#include "TextCoreProperties.cginc"

#endif // VARC_TEXTCORE__PROPERTIES_INCLUDED
