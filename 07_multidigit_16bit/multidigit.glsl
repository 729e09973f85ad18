// The eye passes of McCool's multi-digit comparison (seed 000, "GeForce/Quadro Precision
// Extension"), the register-combiner stages written out, compiled once per pass (PASS 1-3):
//   Tex0  the map's two 8-bit digits at (s/q, t/q) (GL_LUMINANCE8_ALPHA8 then, RG8 now)
//   Tex1  pass 2: a 1D linear ramp at s ("2nd pass just requires a linear 1D texture");
//         pass 3: a 2D ramp, linear along both axes, at (s, 256 s): both digits
//   pass 1  everything dimmed
//   pass 2  lit where bigDigit(map) > bigDigit(fragment); writes stencil 1
//   pass 3  lit where the big digits leave it to the little ones: alpha = littleDigit(map) -
//           littleDigit(fragment) (0 if the fragment's big digit is larger), alpha test
//           GL_GREATER 0, stencil 1 rejected (pass 2 has lit the pixel already)
#include "lighting.glsl"
#include "depth_digits.glsl"
#include "readback_lookup.glsl"

in vec3 vWorld;
in vec3 vNormal;
uniform sampler2D uMap;       // Tex0: big digit in r, little digit in g
uniform Ramp uRampBig;        // Tex1 of pass 2 (ramp.glsl: 1D, or 256x1)
uniform sampler2D uRamp;      // Tex1 of pass 3
uniform vec3 uColor;
// Compiled per VIEW: the colour, the visibility, or which pass lit (1 grey, 2 green, 3 blue).
out vec4 outColor;

vec2 mapDigits() {
  vec4 v = mapTexel(uMap);
  if (uMapIsDepth == 1) {
    float steps = depthToSteps(v.r, 65535.0, uReadbackNearest);
    return vec2(bigDigit(steps), littleDigit(steps));
  }
  return floor(v.rg * 255.0 + 0.5);
}

// The fragment's light depth, stopping half a 16-bit step short of 1 as rampDigits does.
float rampS() {
  return clamp(fragmentDepth(), 0.0, 1.0 - 0.5 / 65536.0);
}

vec4 passColor(float shade, vec4 passesView) {
#if VIEW == VIEW_VISIBILITY
  return vec4(vec3(shade), 1.0);
#elif VIEW == VIEW_PASSES
  return passesView;
#else
  return vec4(shadeSurface(uColor, vWorld, normalize(vNormal), shade), 1.0);
#endif
}

void main() {
#if PASS == 1 && SHADOW_OFF
  outColor = passColor(1.0, vec4(0.15, 0.15, 0.15, 1.0));  // shadow.off: one pass, lit
#elif PASS == 1
  outColor = passColor(0.0, vec4(0.15, 0.15, 0.15, 1.0));
#elif PASS == 2
  float fragmentBig = floor(rampTexel(uRampBig, rampS()) * 255.0 + 0.5);
  if (!(behindLight() || bigDigitPassLights(mapDigits(), vec2(fragmentBig, 0.0)))) discard;
  outColor = passColor(1.0, vec4(0.0, 0.8, 0.0, 0.0));
#else
  float s = rampS();
  vec2 fragment = floor(texture(uRamp, vec2(s, 256.0 * s)).rg * 255.0 + 0.5);
  if (behindLight() || littleDigitPassAlpha(mapDigits(), fragment) <= 0.0) discard;
  outColor = passColor(1.0, vec4(0.0, 0.0, 0.8, 0.0));
#endif
}
