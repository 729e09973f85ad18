// The eye passes of McCool's multi-digit comparison (seed 000, "GeForce/Quadro Precision
// Extension"), the register-combiner stages written out:
//   Tex0  the map's two 8-bit digits at (s/q, t/q) (GL_LUMINANCE8_ALPHA8 then, RG8 now)
//   Tex1  a 2D ramp, linear along both axes, at (s, 256 s): the fragment's two digits
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
uniform sampler2D uMap;   // Tex0: big digit in r, little digit in g
uniform sampler2D uRamp;  // Tex1
uniform vec3 uColor;
uniform int uPass;    // 1, 2 or 3
uniform int uOutput;  // 0 colour, 1 visibility, 2 which pass lit (1 grey, 2 green, 3 blue)
out vec4 outColor;

vec2 mapDigits() {
  vec4 v = texture(uMap, mapCoord());
  if (uMapIsDepth == 1) {
    float steps = depthToSteps(v.r, 65535.0, uReadbackNearest);
    return vec2(bigDigit(steps), littleDigit(steps));
  }
  return floor(v.rg * 255.0 + 0.5);
}

vec2 fragmentDigits() {
  float s = clamp(fragmentDepth(), 0.0, 1.0 - 0.5 / 65536.0);  // as rampDigits clamps
  return floor(texture(uRamp, vec2(s, 256.0 * s)).rg * 255.0 + 0.5);
}

void main() {
  if (uPass == 2 && !(behindLight() || bigDigitPassLights(mapDigits(), fragmentDigits()))) {
    discard;
  }
  if (uPass == 3 && (behindLight() || littleDigitPassAlpha(mapDigits(), fragmentDigits()) <= 0.0)) {
    discard;
  }
  if (uOutput == 1) {
    outColor = vec4(vec3(uPass == 1 ? 0.0 : 1.0), 1.0);
  } else if (uOutput == 2) {
    outColor = uPass == 1 ? vec4(0.15, 0.15, 0.15, 1.0)
                          : uPass == 2 ? vec4(0.0, 0.8, 0.0, 0.0) : vec4(0.0, 0.0, 0.8, 0.0);
  } else {
    outColor = vec4(shadeSurface(uColor, vWorld, normalize(vNormal), uPass == 1 ? 0.0 : 1.0), 1.0);
  }
}
