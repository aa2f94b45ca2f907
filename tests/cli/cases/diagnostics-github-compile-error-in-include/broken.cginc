// A helper with a type error on line 3.
float4 tint(float4 c) {
    return c * undefinedTint;
}
