#ifndef HELPERS_INCLUDED
#define HELPERS_INCLUDED
#include "No Such File.cginc"
#endif
