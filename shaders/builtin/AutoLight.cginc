// SPDX-License-Identifier: Apache-2.0
// varc built-in include: AutoLight.cginc. Declarations arrive with issue #4 (built-in include library);
// this file exists so shaders that include it resolve for variant listing.
#ifndef VARC_AUTOLIGHT_INCLUDED
#define VARC_AUTOLIGHT_INCLUDED
#endif
