// SPDX-License-Identifier: Apache-2.0
// varc built-in include: UnityCG.cginc. Declarations arrive with issue #4 (built-in include library);
// this file exists so shaders that include it resolve for variant listing.
#ifndef VARC_UNITYCG_INCLUDED
#define VARC_UNITYCG_INCLUDED
#endif
