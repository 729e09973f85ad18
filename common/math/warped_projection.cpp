#include "math/warped_projection.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_access.hpp>

namespace shadows {

namespace {

HalfSpace normalized(glm::vec4 plane) {
  const float length = glm::length(glm::vec3(plane));
  if (length <= 0.0f) return {glm::vec3(0.0f), plane.w};
  return {glm::vec3(plane) / length, plane.w / length};
}

bool finite(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      if (!std::isfinite(m[c][r])) return false;
    }
  }
  return true;
}

Warp fallback(const glm::mat4& uniform, std::string why) {
  return {uniform, std::move(why)};
}

}  // namespace

std::vector<HalfSpace> frustumHalfSpaces(const glm::mat4& m) {
  const glm::vec4 x = glm::row(m, 0), y = glm::row(m, 1), z = glm::row(m, 2), w = glm::row(m, 3);
  return {normalized(w + x), normalized(w - x), normalized(w + y),
          normalized(w - y), normalized(w + z), normalized(w - z)};
}

std::vector<HalfSpace> boxHalfSpaces(const Bounds& b) {
  std::vector<HalfSpace> out;
  for (int axis = 0; axis < 3; ++axis) {
    glm::vec3 n(0.0f);
    n[axis] = 1.0f;
    out.push_back({n, -b.min[axis]});
    out.push_back({-n, b.max[axis]});
  }
  return out;
}

std::vector<glm::vec3> convexVertices(const std::vector<HalfSpace>& h) {
  std::vector<glm::vec3> out;
  const size_t n = h.size();
  for (size_t i = 0; i < n; ++i) {
    for (size_t j = i + 1; j < n; ++j) {
      for (size_t k = j + 1; k < n; ++k) {
        const glm::mat3 rows = glm::transpose(glm::mat3(h[i].n, h[j].n, h[k].n));
        if (std::abs(glm::determinant(rows)) < 1e-6f) continue;
        const glm::vec3 p = glm::inverse(rows) * glm::vec3(-h[i].d, -h[j].d, -h[k].d);
        const float scale = 1e-4f * std::max(1.0f, glm::length(p));
        if (std::all_of(h.begin(), h.end(),
                        [&](const HalfSpace& s) { return s.at(p) >= -scale; })) {
          out.push_back(p);
        }
      }
    }
  }
  return out;
}

Warp focusedProjection(const glm::mat4& uniform, const std::vector<glm::vec3>& body) {
  glm::vec2 lo(1.0f), hi(-1.0f);
  for (const glm::vec3& p : body) {
    const glm::vec4 c = uniform * glm::vec4(p, 1.0f);
    if (c.w <= 1e-6f) continue;
    const glm::vec2 ndc = glm::clamp(glm::vec2(c) / c.w, glm::vec2(-1.0f), glm::vec2(1.0f));
    lo = glm::min(lo, ndc);
    hi = glm::max(hi, ndc);
  }
  if (hi.x - lo.x < 1e-4f || hi.y - lo.y < 1e-4f) {
    return fallback(uniform, "nothing the eye sees lies in the light's frustum");
  }
  // x' = sx x + ox w: the body's light-space box becomes the whole map.
  glm::mat4 crop(1.0f);
  crop[0][0] = 2.0f / (hi.x - lo.x);
  crop[3][0] = -(hi.x + lo.x) / (hi.x - lo.x);
  crop[1][1] = 2.0f / (hi.y - lo.y);
  crop[3][1] = -(hi.y + lo.y) / (hi.y - lo.y);
  return {crop * uniform, ""};
}

Warp lispsmProjection(const LispsmInput& in, float* nUsed) {
  const auto ndc = [&](glm::vec3 p, bool& ok) {
    const glm::vec4 c = in.uniform * glm::vec4(p, 1.0f);
    ok = c.w > 1e-6f;
    return glm::vec3(c) / (ok ? c.w : 1.0f);
  };
  std::vector<glm::vec3> body;
  for (const glm::vec3& p : in.body) {
    bool ok = false;
    const glm::vec3 b = ndc(p, ok);
    if (ok) body.push_back(b);
  }
  if (body.size() < 4)
    return fallback(in.uniform, "nothing the eye sees lies in the light's frustum");
  bool ok = false;
  const glm::vec3 eye = ndc(in.eye, ok);
  if (!ok) return fallback(in.uniform, "the eye is behind the light: the warp would invert");
  // The view direction in the light's post-projective space (a line stays a line there).
  const float step = 1e-2f * std::max(glm::length(in.body.front() - in.eye), 1e-3f);
  const glm::vec3 ahead = ndc(in.eye + step * glm::normalize(in.forward), ok);
  if (!ok) return fallback(in.uniform, "the eye looks at the light's back: the warp would invert");
  const glm::vec3 v = glm::normalize(ahead - eye);
  const glm::vec3 l(0.0f, 0.0f, 1.0f);  // the light, directional in this space
  const glm::vec3 across = v - glm::dot(v, l) * l;
  const float sin_gamma = glm::length(across);
  if (!(sin_gamma > 0.02f)) {
    return fallback(in.uniform, "the eye looks along the light: no direction to warp");
  }
  const glm::vec3 f = across / sin_gamma, r = glm::normalize(glm::cross(f, l));
  float d_min = 1e30f, d_max = -1e30f;
  for (const glm::vec3& b : body) {
    d_min = std::min(d_min, glm::dot(f, b));
    d_max = std::max(d_max, glm::dot(f, b));
  }
  const float depth = d_max - d_min;
  if (!(depth > 1e-5f)) return fallback(in.uniform, "the body the eye sees has no depth");
  const float z_near = std::max(d_min - glm::dot(f, eye), 0.0f) + 1e-2f * depth;
  const float z_far = z_near + depth / sin_gamma;
  const float n_opt = (z_near + std::sqrt(z_near * z_far)) / sin_gamma;
  const float n = std::max(in.n_factor * n_opt, 1e-4f * depth);
  if (nUsed != nullptr) *nUsed = n;
  // The warp's centre: n before the body, across from the eye.
  const glm::vec3 c = eye + (d_min - n - glm::dot(f, eye)) * f;
  glm::mat4 view(1.0f);  // rows r, l, f about c
  for (int col = 0; col < 3; ++col) {
    view[col][0] = r[col], view[col][1] = l[col], view[col][2] = f[col];
  }
  view[3] = glm::vec4(-glm::dot(r, c), -glm::dot(l, c), -glm::dot(f, c), 1.0f);
  const float far = n + depth;
  glm::mat4 warp(0.0f);  // (x, y, a z + b, z)
  warp[0][0] = 1.0f;
  warp[1][1] = 1.0f;
  warp[2][2] = (far + n) / (far - n);
  warp[3][2] = -2.0f * far * n / (far - n);
  warp[2][3] = 1.0f;
  // The map: x across, y the warp's depth (near the eye gets more), depth along the light;
  // depth also covers the casters between the light's near plane and the body.
  glm::vec3 lo(1e30f), hi(-1e30f);
  const glm::mat4 wv = warp * view;
  for (const glm::vec3& b : body) {
    for (const glm::vec3& q : {b, glm::vec3(b.x, b.y, -1.0f)}) {
      const glm::vec4 h = wv * glm::vec4(q, 1.0f);
      const glm::vec3 m = glm::vec3(h.x, h.z, h.y) / h.w;
      lo = glm::min(lo, m);
      hi = glm::max(hi, m);
    }
  }
  const glm::vec3 size = hi - lo;
  if (!(size.x > 1e-6f && size.y > 1e-6f && size.z > 1e-6f)) {
    return fallback(in.uniform, "the warped body is flat");
  }
  glm::mat4 fit(0.0f);  // rows: x from X, y from Z, z from Y, w from W
  fit[0][0] = 2.0f / size.x;
  fit[3][0] = -(hi.x + lo.x) / size.x;
  fit[2][1] = 2.0f / size.y;
  fit[3][1] = -(hi.y + lo.y) / size.y;
  fit[1][2] = 2.0f / size.z;
  fit[3][2] = -(hi.z + lo.z) / size.z;
  fit[3][3] = 1.0f;
  const glm::mat4 m = fit * wv * in.uniform;
  if (!finite(m)) return fallback(in.uniform, "the warp is not finite");
  return {m, ""};
}

Warp planeOptimalProjection(const PlaneOptimalInput& in) {
  const glm::vec4 pi(in.plane.n, in.plane.d);
  const float pi_light = glm::dot(pi, in.light);
  const float light_scale =
      in.light.w == 0.0f ? 1.0f : std::max(1.0f, glm::length(glm::vec3(in.light)));
  if (std::abs(pi_light) < 1e-4f * light_scale) return {in.camera, "the light lies in the plane"};
  if (pi_light < 0.0f) return {in.camera, "the light is behind the plane"};
  const float pi_eye = in.plane.at(in.eye);
  if (std::abs(pi_eye) < 1e-3f) return {in.camera, "the eye lies in the plane"};
  if (pi_eye < 0.0f) return {in.camera, "the eye is behind the plane"};
  if (in.plane_in_view.size() < 3) return {in.camera, "the plane is not in view"};
  // P = C - (C L) pi^T / (pi^T L): P L = 0, and P = C where pi^T X = 0.
  glm::mat4 p = in.camera - glm::outerProduct(in.camera * in.light, pi) / pi_light;
  float w_min = 1e30f, w_max = 0.0f;
  for (const glm::vec3& q : in.depth_points) {
    const float w = glm::dot(glm::row(p, 3), glm::vec4(q, 1.0f));
    if (w <= 0.0f) continue;  // behind the light's centre of projection: region II
    w_min = std::min(w_min, w);
    w_max = std::max(w_max, w);
  }
  if (!(w_max > 0.0f) || w_min >= w_max) return {in.camera, "no caster lies before the plane"};
  w_min *= 0.98f, w_max *= 1.02f;
  // z/w = A + B / w: -1 at w_min, 1 at w_max, increasing along every ray from the light.
  const float b = -2.0f * w_min * w_max / (w_max - w_min);
  const float a = 1.0f - b / w_max;
  for (int col = 0; col < 4; ++col) p[col][2] = a * p[col][3] + (col == 3 ? b : 0.0f);
  if (!finite(p)) return {in.camera, "the projection is not finite"};
  return {p, ""};
}

bool inRegionOne(glm::vec3 p, glm::vec4 light, const HalfSpace& plane, const glm::mat4& camera,
                 const glm::mat4& planeModelInverse, glm::vec2 planeHalf) {
  // Along the light's ray through p, onward to the plane.
  const glm::vec3 dir = light.w == 0.0f ? -glm::vec3(light) : p - glm::vec3(light);
  const float denom = glm::dot(plane.n, dir);
  if (std::abs(denom) < 1e-8f) return false;
  const float s = -plane.at(p) / denom;
  if (s < -1e-4f) return false;  // the plane lies between the light and p
  const glm::vec3 q = p + s * dir;
  const glm::vec3 local = glm::vec3(planeModelInverse * glm::vec4(q, 1.0f));
  if (std::abs(local.x) > planeHalf.x || std::abs(local.z) > planeHalf.y) return false;
  const glm::vec4 c = camera * glm::vec4(q, 1.0f);
  return c.w > 0.0f && std::abs(c.x) <= c.w && std::abs(c.y) <= c.w;
}

}  // namespace shadows
