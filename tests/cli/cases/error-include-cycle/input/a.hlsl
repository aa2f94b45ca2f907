// a includes b
#include "b.hlsl"
