// b includes a back
float b;
#include "a.hlsl"
