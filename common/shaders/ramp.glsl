// Tex1 of seed 000's readback lessons: a ramp of 256 texels read NEAREST, a 1D texture as the
// slides had it. OpenGL ES and WebGL have no 1D textures: there it is a 256x1 2D texture read
// along its one row, the same texels (Texture::table1D makes either).
#if HAS_TEXTURE_1D
#define Ramp sampler1D
float rampTexel(Ramp ramp, float s) {
  return texture(ramp, s).r;
}
#else
#define Ramp sampler2D
float rampTexel(Ramp ramp, float s) {
  return texture(ramp, vec2(s, 0.5)).r;
}
#endif
