// The receiver's half of the biases of lesson 04 (lesson 05 includes it too). The window-space
// offsets (glPolygonOffset, back faces, the clip-space translate) live in pass 1 instead.
uniform mat4 uShadowMatrix;  // B * P_light * V_light: world to (s, t, r, q)
uniform mat4 uLightView;     // V_light, for the point's distance along the light's axis
uniform vec2 uTexelWorld;    // world size of one map texel at light distance d: x * d + y
uniform vec3 uLightAxis;     // unit, the light's view axis pointing away from it (light-space z)

// The geometric normal of the triangle, facing the eye: the same normal the truth uses.
vec3 geometricNormal(vec3 p) { return normalize(cross(dFdx(p), dFdy(p))); }

// Normal offset (beyond the seeds): look the map up from a point lifted off the surface along
// its normal. A texel of world size h spans depths h/2 * tan(theta) either side of its centre
// (theta between N and L); a point lifted by delta lies delta / cos(theta) in front of the
// surface along the light ray, so delta >= h/2 * sin(theta) clears the texel. `texels` scales h.
vec3 normalOffsetPoint(vec3 p, vec3 n, vec3 toLight, float texels) {
  float d = max(-(uLightView * vec4(p, 1.0)).z, 0.0);
  float h = uTexelWorld.x * d + uTexelWorld.y;
  float cos_theta = clamp(dot(n, toLight), -1.0, 1.0);
  float sin_theta = sqrt(1.0 - cos_theta * cos_theta);
  return p + n * (texels * h * sin_theta);
}

// Seed 002: how much window depth a step of `distance` world units along the light's z axis
// is at p (d u3 / d X3 times the distance): a constant in light space, not in the depth buffer.
float lightSpaceDepthStep(vec3 p, float distance) {
  vec4 a = uShadowMatrix * vec4(p, 1.0);
  vec4 b = uShadowMatrix * vec4(p + uLightAxis * distance, 1.0);
  return b.z / b.w - a.z / a.w;
}

// The stored depth at uv, 1 ("nothing in front") outside the map (border.glsl).
float storedDepth(sampler2D depthMap, vec2 uv) {
  return outsideTexture(uv, vec2(textureSize(depthMap, 0))) ? 1.0 : texture(depthMap, uv).r;
}

// Seed 002 (Ogre): the stored depth A plus a bias from the map itself: the depth gradient over
// the neighbouring texels (clamped, since across a silhouette it jumps to another surface)
// times `scale`. Returns A + that; scene.frag adds the constant, expressed in light space
// (lightSpaceDepthStep), where bias.units is not 0.
float gradientBiasedDepth(sampler2D depthMap, vec2 uv, vec3 p, float scale, float clampDistance) {
  vec2 texel = 1.0 / vec2(textureSize(depthMap, 0));
  float centre = storedDepth(depthMap, uv);
  vec4 depths = vec4(storedDepth(depthMap, uv - vec2(texel.x, 0.0)),
                     storedDepth(depthMap, uv + vec2(texel.x, 0.0)),
                     storedDepth(depthMap, uv - vec2(0.0, texel.y)),
                     storedDepth(depthMap, uv + vec2(0.0, texel.y)));
  vec2 differences = abs(depths.yw - depths.xz);
  float gradient = min(lightSpaceDepthStep(p, clampDistance), max(differences.x, differences.y));
  return centre + gradient * scale;
}
