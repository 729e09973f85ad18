#version 330 core
// Pass 2: compare the fragment's light depth B = r/q with the map's A at (s/q, t/q).
// sampler2DShadow does the compare in hardware: 1 where B <= A (lit), 0 where B > A.
#include "lighting.glsl"
#include "border.glsl"

in vec3 vWorld;
in vec3 vNormal;
in vec4 vShadowCoord;
uniform sampler2DShadow uShadowMap;  // compare mode on
uniform sampler2D uShadowDepth;      // the same texture, read raw for the debug views
uniform vec3 uColor;
// Compiled per view (VIEW, from main.cpp) and SHADOW_OFF, so the shaded frame runs only the
// shading: VIEW_PROJECTED_DEPTH shows A, VIEW_LIGHT_DISTANCE B, VIEW_COMPARE both.
uniform float uLightNear;
uniform float uLightFar;
uniform int uLightPerspective;
out vec4 outColor;

float shadowTerm() {
  vec4 c = vShadowCoord;
  if (c.w <= 0.0) return 1.0;  // behind a spot light: outside its frustum, the map says nothing
  // Beyond the far plane: clamp B to 1 so every depth format behaves alike (16/24-bit clamp).
  c.z = min(c.z, c.w);
  if (outsideTexture(c.xy / c.w, vec2(textureSize(uShadowMap, 0)))) return 1.0;  // the border
  return textureProj(uShadowMap, c);
}

// Window depth to 0..1 distance between near and far, so a perspective map is not all white.
float toDistance(float depth) {
  if (uLightPerspective == 0) return depth;
  float z = 2.0 * depth - 1.0;
  float linear = 2.0 * uLightNear * uLightFar / (uLightFar + uLightNear - z * (uLightFar - uLightNear));
  return (linear - uLightNear) / (uLightFar - uLightNear);
}

void main() {
  vec3 n = normalize(vNormal);
#if SHADOW_OFF
  float shade = 1.0;  // shadow.off: the baseline, no lookup at all
#else
  float shade = shadowTerm();
#endif
#if VIEW == VIEW_SHADED || VIEW == VIEW_LIGHT_VIEW
  outColor = vec4(shadeSurface(uColor, vWorld, n, shade), 1.0);
#elif VIEW == VIEW_VISIBILITY
  outColor = vec4(vec3(shade), 1.0);
#else
  vec3 c = vShadowCoord.xyz / max(vShadowCoord.w, 1e-6);
  bool inside = vShadowCoord.w > 0.0 && all(greaterThanEqual(c.xy, vec2(0.0))) &&
                all(lessThanEqual(c.xy, vec2(1.0)));
  float a = toDistance(texture(uShadowDepth, c.xy).r);
  float b = toDistance(clamp(c.z, 0.0, 1.0));
  if (!inside) {
    outColor = vec4(vec3(0.25), 1.0);
  } else {
#if VIEW == VIEW_PROJECTED_DEPTH
    outColor = vec4(vec3(a), 1.0);
#elif VIEW == VIEW_LIGHT_DISTANCE
    outColor = vec4(vec3(b), 1.0);
#else
    // Kilgard's comparison: green where A and B agree (lit), the plain surface where B > A.
    float lit = shade;
    vec3 plain = shadeSurface(uColor, vWorld, n, 0.0);
    outColor = vec4(mix(plain, vec3(0.1, 0.9, 0.2) * (0.3 + 0.7 * max(dot(n, directionToLight(vWorld)), 0.0)), lit), 1.0);
#endif
  }
#endif
}
