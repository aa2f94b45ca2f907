#define TINT float4(1, 0, 0, 1)
