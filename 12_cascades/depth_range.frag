#version 330 core
// One step of reducing the depths the eye sees to their nearest and farthest (sample
// distribution shadow maps' first step): each texel written holds the least and the greatest
// of a 4x4 block of its source, the eye's window depth in the first step (FIRST_STEP; the sky,
// at 1, counts for none) or the last step's (least, greatest). An empty block: (1, 0).
uniform sampler2D uSource;
uniform vec2 uSourceSize;  // texels (whole numbers)
out vec4 outRange;
void main() {
  ivec2 base = ivec2(gl_FragCoord.xy) * 4;
  vec2 range = vec2(1.0, 0.0);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) {
      ivec2 at = base + ivec2(x, y);
      if (any(greaterThanEqual(at, ivec2(uSourceSize)))) continue;
#if FIRST_STEP
      float d = texelFetch(uSource, at, 0).r;
      if (d < 1.0) range = vec2(min(range.x, d), max(range.y, d));
#else
      vec2 r = texelFetch(uSource, at, 0).rg;
      range = vec2(min(range.x, r.x), max(range.y, r.y));
#endif
    }
  }
  outRange = vec4(range, 0.0, 1.0);
}
