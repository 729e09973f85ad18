// Ray-traced ground truth with Embree 3 (the error metrics are in error_metrics.cpp).
#include "truth/truth.hpp"

#include "truth/sample_hash.hpp"
#include "truth/truth_job.hpp"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

namespace shadows {

namespace {

constexpr float kPi = 3.14159265358979323846f;

// Embree reports errors through a callback that may run on its own build threads; collect
// the first message here and throw from our own code, never across Embree's frames.
struct ErrorSink {
  std::mutex mutex;
  std::string message;
};

const char* errorName(RTCError code) {
  switch (code) {
    case RTC_ERROR_NONE:
      return "none";
    case RTC_ERROR_UNKNOWN:
      return "unknown error";
    case RTC_ERROR_INVALID_ARGUMENT:
      return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION:
      return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY:
      return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU:
      return "unsupported CPU";
    case RTC_ERROR_CANCELLED:
      return "cancelled";
  }
  return "unrecognised error";
}

void onEmbreeError(void* user, RTCError code, const char* str) {
  auto* sink = static_cast<ErrorSink*>(user);
  std::lock_guard<std::mutex> lock(sink->mutex);
  if (sink->message.empty()) {
    sink->message = std::string(errorName(code)) + (str ? std::string(": ") + str : "");
  }
}

// Shirley-Chiu concentric map: keeps the square's strata compact and equal-area on the disk.
glm::vec2 concentricDisk(float u, float v) {
  const float a = 2.0f * u - 1.0f;
  const float b = 2.0f * v - 1.0f;
  if (a == 0.0f && b == 0.0f) return glm::vec2(0.0f);
  float r, phi;
  if (std::abs(a) > std::abs(b)) {
    r = a;
    phi = (kPi / 4.0f) * (b / a);
  } else {
    r = b;
    phi = (kPi / 2.0f) - (kPi / 4.0f) * (a / b);
  }
  return glm::vec2(r * std::cos(phi), r * std::sin(phi));
}

// Orthonormal tangents of a unit normal (Duff et al. 2017, branchless and stable).
void tangentFrame(const glm::vec3& n, glm::vec3& t, glm::vec3& b) {
  const float sign = std::copysign(1.0f, n.z);
  const float a = -1.0f / (sign + n.z);
  const float c = n.x * n.y * a;
  t = glm::vec3(1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x);
  b = glm::vec3(c, sign + n.y * n.y * a, -n.y);
}

bool finite3(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

void checkSurface(const SurfaceBuffer& s) {
  if (s.width < 0 || s.height < 0) throw std::invalid_argument("SurfaceBuffer: negative size");
  const std::size_t n = static_cast<std::size_t>(s.width) * static_cast<std::size_t>(s.height);
  if (s.position.size() != n || s.normal.size() != n) {
    throw std::invalid_argument("SurfaceBuffer: position/normal size != width*height");
  }
}

}  // namespace

struct Truth::Impl {
  ErrorSink errors;
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;  // null when the mesh is empty: everything is lit

  ~Impl() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }

  void check(const char* what) {
    RTCError code = rtcGetDeviceError(device);
    std::string message;
    {
      std::lock_guard<std::mutex> lock(errors.mutex);
      message = errors.message;
    }
    if (code == RTC_ERROR_NONE && message.empty()) return;
    if (message.empty()) message = errorName(code);
    throw std::runtime_error(std::string("Embree error while ") + what + ": " + message);
  }
};

Truth::Truth(const std::vector<glm::vec3>& positions, const std::vector<glm::uvec3>& triangles,
             float sceneRadius)
    : impl_(std::make_unique<Impl>()) {
  if (!std::isfinite(sceneRadius)) throw std::invalid_argument("Truth: sceneRadius not finite");
  ray_offset_ = rayOffsetFor(sceneRadius);

  if (positions.size() > std::numeric_limits<std::uint32_t>::max()) {
    throw std::invalid_argument("Truth: too many vertices for 32-bit indices");
  }
  for (const glm::uvec3& t : triangles) {
    if (t.x >= positions.size() || t.y >= positions.size() || t.z >= positions.size()) {
      throw std::invalid_argument("Truth: triangle index out of range");
    }
  }

  impl_->device = rtcNewDevice(nullptr);
  if (!impl_->device) {
    throw std::runtime_error(std::string("Embree error while creating the device: ") +
                             errorName(rtcGetDeviceError(nullptr)));
  }
  rtcSetDeviceErrorFunction(impl_->device, onEmbreeError, &impl_->errors);

  if (triangles.empty()) return;

  impl_->scene = rtcNewScene(impl_->device);
  impl_->check("creating the scene");
  // Robust: no rays slipping through shared edges, which would show up as false lit pixels.
  rtcSetSceneFlags(impl_->scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(impl_->scene, RTC_BUILD_QUALITY_HIGH);

  RTCGeometry geom = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
  impl_->check("creating the triangle geometry");
  rtcSetGeometryBuildQuality(geom, RTC_BUILD_QUALITY_HIGH);
  // New (Embree-owned) buffers: Embree pads them for its SIMD loads, which a shared
  // std::vector<glm::vec3> would not be.
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
      geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), positions.size()));
  auto* idx = static_cast<std::uint32_t*>(
      rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                              3 * sizeof(std::uint32_t), triangles.size()));
  if (!v || !idx) {
    rtcReleaseGeometry(geom);
    impl_->check("allocating geometry buffers");
    throw std::runtime_error("Embree error while allocating geometry buffers");
  }
  for (std::size_t i = 0; i < positions.size(); ++i) {
    v[3 * i + 0] = positions[i].x;
    v[3 * i + 1] = positions[i].y;
    v[3 * i + 2] = positions[i].z;
  }
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    idx[3 * i + 0] = triangles[i].x;
    idx[3 * i + 1] = triangles[i].y;
    idx[3 * i + 2] = triangles[i].z;
  }
  rtcCommitGeometry(geom);
  rtcAttachGeometry(impl_->scene, geom);
  rtcReleaseGeometry(geom);  // the scene holds its own reference
  impl_->check("committing the geometry");
  rtcCommitScene(impl_->scene);
  impl_->check("building the scene");
}

Truth::~Truth() = default;

std::vector<float> Truth::visibility(const SurfaceBuffer& surface, const TruthLight& light,
                                     TraceControl* control) const {
  checkSurface(surface);
  glm::vec3 axis(0.0f);  // unit light axis; zero for a point light without a direction
  if (glm::length(light.direction) > 0.0f) axis = glm::normalize(light.direction);
  if (light.directional && axis == glm::vec3(0.0f)) {
    throw std::invalid_argument("Truth::visibility: directional light needs a direction");
  }
  if (!(light.radius >= 0.0f) || !std::isfinite(light.radius) || !finite3(light.position)) {
    throw std::invalid_argument("Truth::visibility: invalid light position or radius");
  }

  const bool area = light.radius > 0.0f;
  const int k = TruthLight::sampleSide(light.samples);
  const float kf = static_cast<float>(k);
  const float count = kf * kf;
  glm::vec3 axisT(0.0f), axisB(0.0f);
  if (axis != glm::vec3(0.0f)) tangentFrame(axis, axisT, axisB);

  const int w = surface.width;
  const int h = surface.height;
  std::vector<float> out(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), kNotCounted);
  const float offset = ray_offset_;
  const float inf = std::numeric_limits<float>::infinity();

  auto unoccluded = [this](const glm::vec3& o, const glm::vec3& dir, float tfar) {
    return this->unoccluded(o, dir, tfar);
  };
  // Toward a finite point: stop just short of it so the emitter itself never occludes.
  auto seesPoint = [&](const glm::vec3& o, const glm::vec3& target) {
    const glm::vec3 d = target - o;
    const float dist = glm::length(d);
    if (!(dist > 0.0f)) return true;
    return unoccluded(o, d / dist, dist * (1.0f - 1e-4f));
  };

  auto pixel = [&](std::size_t i) -> float {
    glm::vec3 p, n;
    float ndotl;
    if (!countedPixel(surface, i, light, p, n, ndotl)) return kNotCounted;
    // N.L > 0 here, so n already faces the light; lifting along it clears the surface.
    const glm::vec3 o = p + n * offset;

    if (!area) {
      if (light.directional) return unoccluded(o, -axis, inf) ? 1.0f : 0.0f;
      return seesPoint(o, light.position) ? 1.0f : 0.0f;
    }

    // Area light: a disk of `radius` facing `axis`. A point light without a direction turns
    // its disk toward the receiver (a spherical light seen from p).
    glm::vec3 centre = light.position;
    glm::vec3 t = axisT, b = axisB;
    if (light.directional) {
      // Directional: a cone of directions around -axis whose tangent is radius / D, D being
      // p's distance to the light plane through `position` (the near plane of the light's
      // orthographic frustum). Equivalently, a disk in that plane centred on p's own axis
      // line, with rays continued to infinity: every pixel sees the light straight along
      // -axis (still directional) and radius -> 0 tends to the hard directional shadow.
      // The cone is set at the receiver, so an occluder edge a gap g above it casts a
      // penumbra of half-width g * radius / D (not g * radius / D_occluder, as a disk light
      // in that plane would); lesson 05 matches its kernel to that. Points at or behind the
      // plane get a tiny D (wide cone).
      const float dist = std::max(glm::dot(light.position - o, -axis), offset);
      centre = o - axis * dist;
    } else if (axis == glm::vec3(0.0f)) {
      const glm::vec3 toP = o - light.position;
      const float len = glm::length(toP);
      if (!(len > 0.0f)) return 1.0f;
      tangentFrame(toP / len, t, b);
    }
    const std::uint32_t seed = hash32(static_cast<std::uint32_t>(i) * 0x9E3779B9u + 0x7F4A7C15u);
    int seen = 0;
    for (int sy = 0; sy < k; ++sy) {
      for (int sx = 0; sx < k; ++sx) {
        const std::uint32_t s = static_cast<std::uint32_t>(sy * k + sx);
        const float u = (static_cast<float>(sx) + unitFloat(hash32(seed + 2u * s))) / kf;
        const float v = (static_cast<float>(sy) + unitFloat(hash32(seed + 2u * s + 1u))) / kf;
        const glm::vec2 d = concentricDisk(u, v) * light.radius;
        const glm::vec3 target = centre + t * d.x + b * d.y;
        bool lit;
        if (light.directional) {
          lit = unoccluded(o, glm::normalize(target - o), inf);
        } else {
          lit = seesPoint(o, target);
        }
        seen += lit ? 1 : 0;
      }
    }
    return static_cast<float>(seen) / count;
  };

  // Rows interleaved across threads (cheap load balance); each output element is written by
  // exactly one thread and depends only on its pixel, so the result is thread-count invariant.
  const int threads =
      std::max(1, std::min(static_cast<int>(std::thread::hardware_concurrency()), h));
  auto work = [&](int first) {
    for (int y = first; y < h; y += threads) {
      if (control != nullptr && control->cancel.load()) return;
      for (int x = 0; x < w; ++x) {
        const std::size_t i =
            static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x);
        out[i] = pixel(i);
      }
      if (control != nullptr) ++control->rows_done;
    }
  };
  if (threads == 1) {
    work(0);
  } else {
    std::vector<std::thread> pool;
    pool.reserve(static_cast<std::size_t>(threads - 1));
    for (int t = 1; t < threads; ++t) pool.emplace_back(work, t);
    work(0);
    for (std::thread& th : pool) th.join();
  }
  impl_->check("tracing visibility rays");
  return out;
}

bool Truth::unoccluded(const glm::vec3& o, const glm::vec3& dir, float tfar) const {
  const RTCScene scene = impl_->scene;
  if (!scene) return true;
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  RTCRay ray;
  ray.org_x = o.x;
  ray.org_y = o.y;
  ray.org_z = o.z;
  ray.tnear = 0.0f;
  ray.dir_x = dir.x;
  ray.dir_y = dir.y;
  ray.dir_z = dir.z;
  ray.time = 0.0f;
  ray.tfar = tfar;
  ray.mask = 0xFFFFFFFFu;
  ray.id = 0;
  ray.flags = 0;
  rtcOccluded1(scene, &ctx, &ray);
  return ray.tfar >= 0.0f;  // Embree sets tfar to -inf on a hit
}

namespace {

// The native tracer of a job: one Embree scene of its triangles.
class EmbreeTracer final : public TruthTracer {
 public:
  explicit EmbreeTracer(const TruthJob& job)
      : scene_id_(job.sceneId()), truth_(job.positions, job.triangles, job.scene_radius) {}

  TruthTrace trace(const TruthJob& job) const override {
    if (job.sceneId() != scene_id_) {
      throw std::invalid_argument("EmbreeTracer: the job is for another scene");
    }
    TruthTrace out;
    out.width = job.surface.width;
    out.height = job.surface.height;
    out.visibility = truth_.visibility(job.surface, job.light);
    if (job.air) {
      AirMedium medium = job.air->medium;
      medium.spot = job.air->spot ? &*job.air->spot : nullptr;
      out.air =
          truth_.airLight(job.surface, job.air->eye, job.air->inverse_view_projection, medium);
    }
    return out;
  }
  std::uint64_t sceneId() const override { return scene_id_; }

 private:
  std::uint64_t scene_id_;
  Truth truth_;
};

}  // namespace

std::shared_ptr<const TruthTracer> makeTruthTracer(const TruthJob& job) {
  return std::make_shared<EmbreeTracer>(job);
}

bool truthTracerAvailable() {
  return true;
}

}  // namespace shadows
