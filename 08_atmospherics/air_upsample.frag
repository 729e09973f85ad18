#version 330 core
// The air, computed at 1/k of the width and height, brought back to every pixel. Low-res pixel
// (x, y) is the eye ray of pixel (k x, k y), so those pixels get their own air exactly; the
// pixels between weigh their four low-res neighbours by distance (bilinear) and, with
// AIR_DEPTH_AWARE, by how close the neighbour's surface depth is to their own, so air does not
// leak across a silhouette: a pixel on the sphere takes the sphere's air, not that of the longer
// ray past its edge. Without it (the preview while input moves) it is plain bilinear.
uniform sampler2D uAir;    // low res: the slices' sum in rgb, the view depth its ray ends at in a
uniform sampler2D uDepth;  // full res (AIR_DEPTH_AWARE)
uniform int uFactor;       // k
uniform vec2 uNearFar;     // the camera's near and far planes
out vec4 outColor;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
#if AIR_DEPTH_AWARE
  float z = 2.0 * texelFetch(uDepth, p, 0).r - 1.0;
  float depth =
      2.0 * uNearFar.x * uNearFar.y / (uNearFar.y + uNearFar.x - z * (uNearFar.y - uNearFar.x));
#endif
  ivec2 base = p / uFactor;
  vec2 t = vec2(p - base * uFactor) / float(uFactor);
  ivec2 last = textureSize(uAir, 0) - 1;
  vec3 sum = vec3(0.0);
  float total = 0.0;
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i < 2; ++i) {
      vec4 air = texelFetch(uAir, min(base + ivec2(i, j), last), 0);
      // Bilinear 0 leaves a neighbour out: the exact pixels take theirs alone.
      float weight = (i == 0 ? 1.0 - t.x : t.x) * (j == 0 ? 1.0 - t.y : t.y);
#if AIR_DEPTH_AWARE
      // A relative depth difference of 1 % weighs a neighbour ten times less.
      weight /= 1e-3 + abs(air.a - depth) / depth;
#endif
      sum += weight * air.rgb;
      total += weight;
    }
  }
  outColor = vec4(sum / total, 0.0);
}
