// Percentage-closer filtering (Reeves 1987; seed 000 "Hardware Shadow Map Filtering"): compare
// first, then average the results, never the depths. Every tap is one sampler2DShadow lookup.
// pcf_math.hpp mirrors the offsets below in C++ for the unit tests.
uniform sampler2DShadow uShadowMap;
uniform int uPcfMode;     // 0 none, 1 hw2x2, 2 grid, 3 dithered, 4 poisson
uniform float uRadius;    // kernel half-width in texels (001's "swidth" is uRadius / 2)
uniform int uGridSide;    // grid: N for N x N taps
uniform int uPoissonTaps; // poisson: how many of the 64 points
uniform int uEarlyOut;    // 1: stop after 4 probe taps that agree
uniform vec2 uTexel;      // 1 / map size

int gTaps = 0;         // taps this fragment took (counted, see scene.frag)
bool gStopped = false;  // the probes agreed and the rest were skipped

float tap(vec3 c, vec2 offsetTexels) {
  gTaps++;
  return texture(uShadowMap, vec3(c.xy + offsetTexels * uTexel, c.z));
}

// N x N taps at the midpoints of a box of half-width uRadius: the box filter's midpoint rule.
float gridOffset(int i, int n) { return (-1.0 + (2.0 * float(i) + 1.0) / float(n)) * uRadius; }

float pcfGrid(vec3 c) {
  int n = uGridSide, last = n - 1;
  float sum = 0.0;
  bool probed = uEarlyOut == 1 && n > 2;
  if (probed) {
    // The four corners first: if they agree, the neighbourhood is fully lit or fully shadowed
    // (unless something smaller than the kernel hides between them) and the rest is skipped.
    sum = tap(c, vec2(gridOffset(0, n), gridOffset(0, n))) +
          tap(c, vec2(gridOffset(last, n), gridOffset(0, n))) +
          tap(c, vec2(gridOffset(0, n), gridOffset(last, n))) +
          tap(c, vec2(gridOffset(last, n), gridOffset(last, n)));
    if (sum == 0.0 || sum == 4.0) {
      gStopped = true;
      return sum * 0.25;
    }
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      if (probed && (i == 0 || i == last) && (j == 0 || j == last)) continue;  // done above
      sum += tap(c, vec2(gridOffset(i, n), gridOffset(j, n)));
    }
  }
  return sum / float(n * n);
}

// Seed 001 "PCF with Dithering": 4 taps whose pattern depends on gl_FragCoord mod 2. The four
// patterns of a 2 x 2 pixel block together are the 4 x 4 grid of the same radius.
float pcfDithered(vec3 c) {
  float swidth = 0.5 * uRadius;
  vec2 offset = mod(floor(gl_FragCoord.xy), 2.0) * swidth;
  float sum = tap(c, vec2(-1.5 * swidth + offset.x, 1.5 * swidth - offset.y)) +
              tap(c, vec2(-1.5 * swidth + offset.x, -0.5 * swidth - offset.y)) +
              tap(c, vec2(0.5 * swidth + offset.x, 1.5 * swidth - offset.y)) +
              tap(c, vec2(0.5 * swidth + offset.x, -0.5 * swidth - offset.y));
  return sum * 0.25;
}

// Seed 003 slide 71: Poisson-disk samples. A progressive set (each prefix is spread out), the
// first four on the rim so they double as the early-out probes.
const vec2 kPoisson[64] = vec2[](
    vec2(0.6364, 0.6364), vec2(-0.6364, 0.6364), vec2(-0.6364, -0.6364), vec2(0.6364, -0.6364),
    vec2(-0.0213, 0.0144), vec2(0.9892, -0.0104), vec2(-0.9460, -0.0379), vec2(0.0371, -0.9720),
    vec2(0.0072, 0.9425), vec2(0.4781, 0.1453), vec2(-0.1561, -0.5123), vec2(-0.4557, 0.1950),
    vec2(0.0282, 0.4832), vec2(0.2798, -0.2901), vec2(-0.5320, -0.1895), vec2(0.2223, -0.6549),
    vec2(-0.9015, 0.3348), vec2(-0.3560, -0.9296), vec2(0.6528, -0.2006), vec2(-0.3868, 0.9175),
    vec2(0.8903, 0.3451), vec2(0.3506, 0.9340), vec2(-0.8607, -0.3669), vec2(0.3473, 0.4409),
    vec2(-0.2947, 0.5928), vec2(0.9379, -0.3368), vec2(0.3576, -0.9327), vec2(-0.2312, -0.1876),
    vec2(0.2048, 0.1853), vec2(-0.7193, 0.1017), vec2(-0.1647, 0.2537), vec2(-0.4166, -0.4569),
    vec2(0.7434, 0.1104), vec2(0.1696, 0.7117), vec2(0.0159, -0.2977), vec2(0.6284, 0.3764),
    vec2(-0.6299, 0.3801), vec2(-0.0287, -0.7276), vec2(0.4193, -0.5094), vec2(0.3624, -0.0640),
    vec2(-0.3406, -0.6830), vec2(-0.0786, 0.7117), vec2(0.3967, 0.6555), vec2(0.7440, -0.4383),
    vec2(-0.2929, 0.0279), vec2(-0.7658, -0.1645), vec2(-0.6443, -0.4155), vec2(-0.3949, 0.4047),
    vec2(0.5397, 0.8280), vec2(0.1522, -0.1113), vec2(0.4496, -0.7390), vec2(-0.8304, 0.5428),
    vec2(-0.5391, -0.8307), vec2(0.0667, -0.5224), vec2(0.4880, -0.3198), vec2(0.8279, 0.5451),
    vec2(-0.1904, 0.9690), vec2(-0.1662, -0.8729), vec2(0.8374, -0.1358), vec2(-0.5392, 0.0182),
    vec2(-0.9821, 0.1516), vec2(-0.4525, 0.7069), vec2(-0.2659, 0.7764), vec2(0.0470, 0.2986));

float pcfPoisson(vec3 c) {
  int n = uPoissonTaps;
  float sum = 0.0;
  int first = 0;
  if (uEarlyOut == 1 && n > 4) {
    for (int k = 0; k < 4; ++k) sum += tap(c, kPoisson[k] * uRadius);
    if (sum == 0.0 || sum == 4.0) {
      gStopped = true;
      return sum * 0.25;
    }
    first = 4;
  }
  for (int k = first; k < n; ++k) sum += tap(c, kPoisson[k] * uRadius);
  return sum / float(n);
}

// c: (s, t, r) after the divide by q.
float percentageCloser(vec3 c) {
  if (uPcfMode == 2) return pcfGrid(c);
  if (uPcfMode == 3) return pcfDithered(c);
  if (uPcfMode == 4) return pcfPoisson(c);
  return tap(c, vec2(0.0));  // none (nearest) or hw2x2 (the sampler is LINEAR: 4 texels, weighted)
}
