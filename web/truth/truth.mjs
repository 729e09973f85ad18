// The ray-traced truth for a browser (and node): the job the native runner writes
// (common/truth_job.*) traced with three-mesh-bvh instead of Embree. The rays are the native
// tracer's (common/truth/truth.cpp, air_truth.cpp, sample_hash.hpp): the same origins and offsets,
// the same area-light samples, the same air integration, in the same float32 arithmetic
// (Math.fround where C++ rounds to float). Intersections are three-mesh-bvh's; the metrics
// stay in C++ (error_metrics.cpp), fed with what traceTruth() returns.
import { BufferAttribute, BufferGeometry, DoubleSide, Ray, Vector3 } from 'three';
import { MeshBVH, SAH } from 'three-mesh-bvh';

const f = Math.fround;
const JOB_MAGIC = 0x4a544853; // "SHTJ"
const TRACE_MAGIC = 0x52544853; // "SHTR"
const VERSION = 1;
const NOT_COUNTED = -1;
const PI = f(Math.PI);
const ONE_SHORT = f(1 - f(1e-4)); // a finite light's rays stop this short of it

// ---- the job's bytes (common/truth/truth_job.cpp, web/truth/README.md) ----

// A job from its bytes: an ArrayBuffer, or a typed array viewing one (a wasm heap slice).
export function parseJob(bytes) {
  const u8 = bytes instanceof ArrayBuffer ? new Uint8Array(bytes) : new Uint8Array(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  // Typed arrays over the job need 4-byte alignment: copy when the view does not have it.
  const buf = u8.byteOffset % 4 === 0 ? u8 : u8.slice();
  const dv = new DataView(buf.buffer, buf.byteOffset, buf.byteLength);
  let at = 0;
  const u32 = () => { const v = dv.getUint32(at, true); at += 4; return v; };
  const i32 = () => { const v = dv.getInt32(at, true); at += 4; return v; };
  const f32 = () => { const v = dv.getFloat32(at, true); at += 4; return v; };
  const u64hex = () => { const lo = u32(); const hi = u32(); return hi.toString(16).padStart(8, '0') + lo.toString(16).padStart(8, '0'); };
  const vec = (n) => { const v = []; for (let k = 0; k < n; k++) v.push(f32()); return v; };
  const array = (Type, n) => {
    if (at + n * Type.BYTES_PER_ELEMENT > buf.byteLength) throw new Error('truth job ends early');
    const a = new Type(buf.buffer, buf.byteOffset + at, n);
    at += n * Type.BYTES_PER_ELEMENT;
    return a;
  };
  if (buf.byteLength < 16 || u32() !== JOB_MAGIC) throw new Error('not a truth job');
  const version = u32();
  if (version !== VERSION) throw new Error(`truth job version ${version}, expected ${VERSION}`);
  const job = { id: u64hex(), sceneId: u64hex() };
  job.width = i32();
  job.height = i32();
  const vertices = u32();
  const triangles = u32();
  job.sceneRadius = f32();
  job.rayOffset = f32();
  job.light = { position: vec(3), direction: vec(3), directional: u32() !== 0, radius: f32(), samples: i32() };
  const hasAir = u32() !== 0;
  const air = {
    eye: vec(3), inverseViewProjection: vec(16), density: f32(), lightPosition: vec(3),
    lightViewProjection: vec(16), samples: i32(), directional: u32() !== 0, lightDirection: vec(3),
  };
  const spotWidth = i32();
  const spotHeight = i32();
  const n = job.width * job.height;
  job.positions = array(Float32Array, 3 * vertices);
  job.triangles = array(Uint32Array, 3 * triangles);
  job.surfacePosition = array(Float32Array, 4 * n);
  job.surfaceNormal = array(Float32Array, 4 * n);
  const spotRgba = array(Uint8Array, 4 * spotWidth * spotHeight);
  if (at !== buf.byteLength) throw new Error('truth job has extra bytes');
  air.spot = spotWidth > 0 ? { width: spotWidth, height: spotHeight, rgba: spotRgba } : null;
  job.air = hasAir ? air : null;
  return job;
}

// The trace's bytes, which the native runner reads back (--truth-from, or in memory).
export function serializeTrace(job, trace) {
  const n = job.width * job.height;
  const out = new ArrayBuffer(40 + 4 * n * (trace.air ? 2 : 1));
  const dv = new DataView(out);
  dv.setUint32(0, TRACE_MAGIC, true);
  dv.setUint32(4, VERSION, true);
  dv.setUint32(8, parseInt(job.id.slice(8), 16), true);
  dv.setUint32(12, parseInt(job.id.slice(0, 8), 16), true);
  dv.setInt32(16, job.width, true);
  dv.setInt32(20, job.height, true);
  dv.setUint32(24, trace.air ? 1 : 0, true);
  dv.setUint32(28, 0, true);
  dv.setFloat64(32, trace.air ? trace.air.noise : 0, true);
  new Float32Array(out, 40, n).set(trace.visibility);
  if (trace.air) new Float32Array(out, 40 + 4 * n, n).set(trace.air.light);
  return new Uint8Array(out);
}

// ---- the scene: three-mesh-bvh over the job's triangles ----

let cached = null; // { sceneId, bvh }: a page keeps its BVH while the scene stays

export function sceneOf(job) {
  if (cached && cached.sceneId === job.sceneId) return cached;
  let bvh = null;
  if (job.triangles.length > 0) {
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new BufferAttribute(new Float32Array(job.positions), 3));
    geometry.setIndex(new BufferAttribute(new Uint32Array(job.triangles), 1));
    bvh = new MeshBVH(geometry, { strategy: SAH, targetLeafSize: 4 });
  }
  const ray = new Ray();
  // True when nothing blocks o + t dir for 0 <= t <= tfar (Embree's rtcOccluded1 with
  // tnear 0; both faces of every triangle block, as in Embree).
  const unoccluded = (o, dir, tfar) => {
    if (!bvh) return true;
    ray.origin.set(o[0], o[1], o[2]);
    ray.direction.set(dir[0], dir[1], dir[2]);
    return bvh.raycastFirst(ray, DoubleSide, 0, tfar) === null;
  };
  cached = { sceneId: job.sceneId, bvh, unoccluded };
  return cached;
}

// ---- float32 vector arithmetic as glm does it ----

const add = (a, b) => [f(a[0] + b[0]), f(a[1] + b[1]), f(a[2] + b[2])];
const sub = (a, b) => [f(a[0] - b[0]), f(a[1] - b[1]), f(a[2] - b[2])];
const scale = (a, s) => [f(a[0] * s), f(a[1] * s), f(a[2] * s)];
const divide = (a, s) => [f(a[0] / s), f(a[1] / s), f(a[2] / s)];
const dot = (a, b) => f(f(f(a[0] * b[0]) + f(a[1] * b[1])) + f(a[2] * b[2]));
const length = (a) => f(Math.sqrt(dot(a, a)));
const normalize = (a) => scale(a, f(1 / f(Math.sqrt(dot(a, a)))));
const finite3 = (a) => Number.isFinite(a[0]) && Number.isFinite(a[1]) && Number.isFinite(a[2]);
// glm's mat4 * vec4 (column-major): (m0 x + m1 y) + (m2 z + m3 w), per row.
function mulMat4(m, v) {
  const out = [0, 0, 0, 0];
  for (let r = 0; r < 4; r++) {
    const a = f(f(m[r] * v[0]) + f(m[4 + r] * v[1]));
    const b = f(f(m[8 + r] * v[2]) + f(m[12 + r] * v[3]));
    out[r] = f(a + b);
  }
  return out;
}

// sample_hash.hpp: lowbias32, and [0, 1) from its top 24 bits.
export function hash32(x) {
  x >>>= 0;
  x ^= x >>> 16;
  x = Math.imul(x, 0x7feb352d) >>> 0;
  x ^= x >>> 15;
  x = Math.imul(x, 0x846ca68b) >>> 0;
  x ^= x >>> 16;
  return x >>> 0;
}
const unitFloat = (h) => (h >>> 8) * 2 ** -24;
const pixelSeed = (i, salt) => hash32((Math.imul(i, 0x9e3779b9) + salt) >>> 0);

// truth.cpp's Shirley-Chiu concentric map and Duff et al.'s tangent frame.
function concentricDisk(u, v) {
  const a = f(f(2 * u) - 1);
  const b = f(f(2 * v) - 1);
  if (a === 0 && b === 0) return [0, 0];
  let r, phi;
  if (Math.abs(a) > Math.abs(b)) {
    r = a;
    phi = f(f(PI / 4) * f(b / a));
  } else {
    r = b;
    phi = f(f(PI / 2) - f(f(PI / 4) * f(a / b)));
  }
  return [f(r * f(Math.cos(phi))), f(r * f(Math.sin(phi)))];
}
function tangentFrame(n) {
  const sign = n[2] < 0 || Object.is(n[2], -0) ? -1 : 1;
  const a = f(-1 / f(sign + n[2]));
  const c = f(f(n[0] * n[1]) * a);
  const t = [f(1 + f(f(sign * f(n[0] * n[0])) * a)), f(sign * c), f(-sign * n[0])];
  const b = [c, f(sign + f(f(n[1] * n[1]) * a)), -n[1]];
  return [t, b];
}

// truth.hpp's kGrazingNdotL, as a float32 (ndotl is compared in float32 arithmetic there).
const GRAZING_NDOTL = Math.fround(0.001);

// truth_job.cpp's countedPixel: the point, unit normal and N.L, or null when not counted.
function countedPixel(job, i) {
  const P = job.surfacePosition, N = job.surfaceNormal, light = job.light;
  if (!(P[4 * i + 3] >= 0)) return null;
  const p = [P[4 * i], P[4 * i + 1], P[4 * i + 2]];
  let n = [N[4 * i], N[4 * i + 1], N[4 * i + 2]];
  if (!finite3(p) || !finite3(n)) return null;
  const len = length(n);
  if (!(len > 0)) return null;
  n = divide(n, len);
  let l = light.directional ? light.direction.map((x) => -x) : sub(light.position, p);
  const ll = length(l);
  if (!(ll > 0) || !Number.isFinite(ll)) return null;
  l = divide(l, ll);
  const ndotl = dot(n, l);
  return ndotl >= GRAZING_NDOTL ? { p, n } : null;
}

// Truth::visibility: the fraction of the light each counted pixel's surface sees, for rows
// [y0, y1) into `out`, which holds those rows only (pixel i at i - y0 * width).
function visibility(job, unoccluded, out, y0, y1) {
  const light = job.light;
  const w = job.width, h = job.height;
  let axis = [0, 0, 0];
  if (length(light.direction) > 0) axis = normalize(light.direction);
  const axisZero = axis[0] === 0 && axis[1] === 0 && axis[2] === 0;
  if (light.directional && axisZero) throw new Error('directional light needs a direction');
  const area = light.radius > 0;
  const k = Math.max(1, Math.round(Math.sqrt(Math.max(light.samples, 1))));
  const count = f(k * k);
  const [axisT, axisB] = axisZero ? [[0, 0, 0], [0, 0, 0]] : tangentFrame(axis);
  const minusAxis = axis.map((x) => -x);
  const offset = job.rayOffset;
  const seesPoint = (o, target) => {
    const d = sub(target, o);
    const dist = length(d);
    if (!(dist > 0)) return true;
    return unoccluded(o, divide(d, dist), f(dist * ONE_SHORT));
  };
  const base = y0 * w;
  for (let i = y0 * w; i < y1 * w; i++) {
    const c = countedPixel(job, i);
    if (!c) continue;
    const o = add(c.p, scale(c.n, offset));
    if (!area) {
      if (light.directional) out[i - base] = unoccluded(o, minusAxis, Infinity) ? 1 : 0;
      else out[i - base] = seesPoint(o, light.position) ? 1 : 0;
      continue;
    }
    let centre = light.position, t = axisT, b = axisB;
    if (light.directional) {
      const dist = Math.max(dot(sub(light.position, o), minusAxis), offset);
      centre = sub(o, scale(axis, dist));
    } else if (axisZero) {
      const toP = sub(o, light.position);
      const len = length(toP);
      if (!(len > 0)) { out[i - base] = 1; continue; }
      [t, b] = tangentFrame(divide(toP, len));
    }
    const seed = pixelSeed(i, 0x7f4a7c15);
    let seen = 0;
    for (let sy = 0; sy < k; sy++) {
      for (let sx = 0; sx < k; sx++) {
        const s = sy * k + sx;
        const u = f(f(sx + unitFloat(hash32((seed + 2 * s) >>> 0))) / k);
        const v = f(f(sy + unitFloat(hash32((seed + 2 * s + 1) >>> 0))) / k);
        const d = concentricDisk(u, v).map((x) => f(x * light.radius));
        const target = add(add(centre, scale(t, d[0])), scale(b, d[1]));
        const lit = light.directional ? unoccluded(o, normalize(sub(target, o)), Infinity)
                                      : seesPoint(o, target);
        if (lit) seen++;
      }
    }
    out[i - base] = f(seen / count);
  }
}

// spotlight.cpp's SpotTexture::value: nearest texel, luminance.
function spotValue(spot, s, t) {
  if (!(s >= 0 && s <= 1 && t >= 0 && t <= 1) || spot.width === 0) return 0;
  const x = Math.min(Math.trunc(f(s * spot.width)), spot.width - 1);
  const y = Math.min(Math.trunc(f(t * spot.height)), spot.height - 1);
  const px = 4 * (y * spot.width + x), c = spot.rgba;
  const lum = f(f(f(f(0.2126) * c[px]) + f(f(0.7152) * c[px + 1])) + f(f(0.0722) * c[px + 2]));
  return f(lum / 255);
}

// air_truth.cpp's clipToFrustum: [t0, t1] of o + t d inside the light's frustum, or null.
function clipToFrustum(lvp, o, d, tmax) {
  const c0 = mulMat4(lvp, [o[0], o[1], o[2], 1]);
  const c1 = mulMat4(lvp, [d[0], d[1], d[2], 0]);
  const planes = [
    [f(c0[3] + c0[0]), f(c1[3] + c1[0])], [f(c0[3] - c0[0]), f(c1[3] - c1[0])],
    [f(c0[3] + c0[1]), f(c1[3] + c1[1])], [f(c0[3] - c0[1]), f(c1[3] - c1[1])],
    [f(c0[3] + c0[2]), f(c1[3] + c1[2])], [f(c0[3] - c0[2]), f(c1[3] - c1[2])],
    [c0[3], c1[3]],
  ];
  let t0 = 0, t1 = tmax;
  for (const [a, b] of planes) {
    if (b > 0) t0 = Math.max(t0, f(-a / b));
    else if (b < 0) t1 = Math.min(t1, f(-a / b));
    else if (a < 0) return null;
  }
  return t1 > t0 ? [t0, t1] : null;
}

// Truth::airLight: single scattering along each pixel's eye ray, two interleaved halves, for
// rows [y0, y1) into `light`, which holds those rows only; returns the sum of the halves' differences over lit pixels, and
// their count (the noise is their ratio over the whole picture).
function airLight(job, unoccluded, light, y0, y1) {
  const air = job.air, w = job.width, h = job.height;
  const P = job.surfacePosition, N = job.surfaceNormal;
  const n = Math.max(2, Math.trunc(air.samples / 2) * 2);
  const base = y0 * w;
  const halfDifference = new Float32Array(light.length).fill(-1);
  const minusDirection = air.lightDirection.map((x) => -x);
  for (let y = y0; y < y1; y++) {
    for (let x = 0; x < w; x++) {
      const i = y * w + x;
      const ndc = [f(f(f(f(x + 0.5) / w) * 2) - 1), f(f(f(f(y + 0.5) / h) * 2) - 1)];
      const farClip = mulMat4(air.inverseViewProjection, [ndc[0], ndc[1], 1, 1]);
      const farPoint = divide(farClip, farClip[3]);
      const d = normalize(sub(farPoint, air.eye));
      const hit = N[4 * i] !== 0 || N[4 * i + 1] !== 0 || N[4 * i + 2] !== 0 || N[4 * i + 3] !== 0;
      const end = hit ? [P[4 * i], P[4 * i + 1], P[4 * i + 2]] : farPoint;
      const tmax = length(sub(end, air.eye));
      const span = clipToFrustum(air.lightViewProjection, air.eye, d, tmax);
      if (!span) continue;
      const [t0, t1] = span;
      const seed = pixelSeed(i, 0x1234567);
      const half = [0, 0];
      for (let k = 0; k < n; k++) {
        const u = f(f(k + unitFloat(hash32((seed + k) >>> 0))) / n);
        const p = add(air.eye, scale(d, f(t0 + f(u * f(t1 - t0)))));
        const c = mulMat4(air.lightViewProjection, [p[0], p[1], p[2], 1]);
        const s = f(f(f(c[0] / c[3]) * 0.5) + 0.5), t = f(f(f(c[1] / c[3]) * 0.5) + 0.5);
        const spot = air.spot ? spotValue(air.spot, s, t) : 1;
        if (spot <= 0) continue;
        if (air.directional) {
          if (!unoccluded(p, minusDirection, Infinity)) continue;
        } else {
          const toLight = sub(air.lightPosition, p);
          const dist = length(toLight);
          if (dist > 0 && !unoccluded(p, divide(toLight, dist), f(dist * ONE_SHORT))) continue;
        }
        half[k % 2] += spot;
      }
      const scaleFactor = (air.density * f(t1 - t0) * 2) / n;
      light[i - base] = f(0.5 * scaleFactor * (half[0] + half[1]));
      halfDifference[i - base] = f(0.5 * scaleFactor * Math.abs(half[0] - half[1]));
    }
  }
  let sum = 0, lit = 0;
  for (const v of halfDifference) {
    if (v < 0) continue;
    sum += v;
    lit++;
  }
  return { sum, lit };
}

// Rows [y0, y1) of a job's truth (a page's workers trace a job in bands of rows):
// { visibility, light (with air), airSum, airLit } for those rows only, in the native
// tracer's layout (rows bottom-up, kNotCounted = -1).
export function traceRows(job, y0, y1) {
  const { unoccluded } = sceneOf(job);
  const pixels = (y1 - y0) * job.width;
  const band = { visibility: new Float32Array(pixels).fill(NOT_COUNTED), light: null, airSum: 0, airLit: 0 };
  visibility(job, unoccluded, band.visibility, y0, y1);
  if (job.air) {
    band.light = new Float32Array(pixels);
    const { sum, lit } = airLight(job, unoccluded, band.light, y0, y1);
    Object.assign(band, { airSum: sum, airLit: lit });
  }
  return band;
}

// A job's truth from its bands (each { y0, y1, visibility, light, airSum, airLit }, covering
// every row once): { visibility, air: { light, noise } | null }, as traceTruth returns it.
export function joinRows(job, bands) {
  const w = job.width, h = job.height;
  const vis = new Float32Array(w * h), light = job.air ? new Float32Array(w * h) : null;
  let sum = 0, lit = 0;
  for (const band of [...bands].sort((a, b) => a.y0 - b.y0)) {
    vis.set(band.visibility, band.y0 * w);
    if (light) light.set(band.light, band.y0 * w);
    sum += band.airSum;
    lit += band.airLit;
  }
  return { visibility: vis, air: light ? { light, noise: lit > 0 ? sum / lit : 0 } : null };
}

// The truth for a job (parsed, or its bytes): { visibility, air: { light, noise } | null },
// in the native tracer's layout (rows bottom-up, kNotCounted = -1).
export function traceTruth(jobOrBytes) {
  const job = jobOrBytes.surfacePosition ? jobOrBytes : parseJob(jobOrBytes);
  return joinRows(job, [{ y0: 0, y1: job.height, ...traceRows(job, 0, job.height) }]);
}

// A trace's bytes back (the native runner's --truth-result, or serializeTrace's).
export function parseTrace(bytes) {
  const u8 = bytes instanceof ArrayBuffer ? new Uint8Array(bytes) : new Uint8Array(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const buf = u8.slice(); // aligned copy
  const dv = new DataView(buf.buffer);
  if (buf.byteLength < 40 || dv.getUint32(0, true) !== TRACE_MAGIC) throw new Error('not a truth trace');
  if (dv.getUint32(4, true) !== VERSION) throw new Error('truth trace version mismatch');
  const id = dv.getUint32(12, true).toString(16).padStart(8, '0') + dv.getUint32(8, true).toString(16).padStart(8, '0');
  const width = dv.getInt32(16, true), height = dv.getInt32(20, true), n = width * height;
  const hasAir = dv.getUint32(24, true) !== 0;
  if (buf.byteLength !== 40 + 4 * n * (hasAir ? 2 : 1)) throw new Error('truth trace has the wrong size');
  return {
    jobId: id, width, height,
    visibility: new Float32Array(buf.buffer, 40, n),
    air: hasAir ? { light: new Float32Array(buf.buffer, 40 + 4 * n, n), noise: dv.getFloat64(32, true) } : null,
  };
}
