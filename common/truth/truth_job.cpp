// A truth job and its trace as bytes, and what counts as a pixel to trace. No Embree here:
// a browser's build links this file too.
#include "truth/truth_job.hpp"

#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "core/fnv.hpp"

namespace shadows {

namespace {

bool finite3(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Unit vector toward the light used for N.L; false when undefined.
bool lightVector(const TruthLight& light, const glm::vec3& p, glm::vec3& l) {
  if (light.directional) {
    l = -light.direction;
  } else {
    l = light.position - p;
  }
  const float len = glm::length(l);
  if (!(len > 0.0f) || !std::isfinite(len)) return false;
  l /= len;
  return true;
}

// "SHTJ" and "SHTR" read as little-endian words.
constexpr std::uint32_t kJobMagic = 0x4A544853u;
constexpr std::uint32_t kTraceMagic = 0x52544853u;
constexpr std::uint32_t kVersion = 1;

// Little-endian 4-byte words (every target the collection builds for is little-endian).
class Writer {
 public:
  void u32(std::uint32_t v) { raw(&v, 4); }
  void i32(std::int32_t v) { raw(&v, 4); }
  void f32(float v) { raw(&v, 4); }
  void f64(double v) { raw(&v, 8); }
  void vec3(const glm::vec3& v) { raw(&v, 12); }
  void mat4(const glm::mat4& m) { raw(&m, 64); }  // column-major, as glm and WebGL keep it
  void u64(std::uint64_t v) { raw(&v, 8); }
  void raw(const void* data, std::size_t size) {
    const std::size_t at = bytes.size();
    bytes.resize(at + size);
    if (size > 0) std::memcpy(bytes.data() + at, data, size);
  }
  std::vector<std::uint8_t> bytes;
};

class Reader {
 public:
  Reader(const std::vector<std::uint8_t>& bytes, const char* what) : bytes_(bytes), what_(what) {}
  void raw(void* out, std::size_t size) {
    if (size > bytes_.size() - at_) {
      throw std::invalid_argument(std::string(what_) + " ends early (" +
                                  std::to_string(bytes_.size()) + " bytes)");
    }
    if (size == 0) return;  // an empty vector's data() may be null: no memcpy from or to it
    std::memcpy(out, bytes_.data() + at_, size);
    at_ += size;
  }
  template <class T>
  T get() {
    T v;
    raw(&v, sizeof v);
    return v;
  }
  // n elements of T; n checked against what is left before anything is allocated.
  template <class T>
  std::vector<T> array(std::size_t n) {
    if (n > (bytes_.size() - at_) / sizeof(T)) {
      throw std::invalid_argument(std::string(what_) + " ends early (" +
                                  std::to_string(bytes_.size()) + " bytes)");
    }
    std::vector<T> out(n);
    raw(out.data(), n * sizeof(T));
    return out;
  }
  void end() const {
    if (at_ != bytes_.size()) throw std::invalid_argument(std::string(what_) + " has extra bytes");
  }

 private:
  const std::vector<std::uint8_t>& bytes_;
  const char* what_;
  std::size_t at_ = 0;
};

void checkHeader(Reader& r, std::uint32_t magic, const char* what) {
  if (r.get<std::uint32_t>() != magic) throw std::invalid_argument(std::string("not a ") + what);
  if (const auto v = r.get<std::uint32_t>(); v != kVersion) {
    throw std::invalid_argument(std::string(what) + " version " + std::to_string(v) +
                                ", expected " + std::to_string(kVersion));
  }
}

std::size_t pixelCount(int width, int height, const char* what) {
  if (width < 0 || height < 0 || width > 16384 || height > 16384) {
    throw std::invalid_argument(std::string(what) + ": bad size");
  }
  return static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
}

// The job's bytes after its 16-byte header (magic, version, id): what id() hashes.
std::vector<std::uint8_t> jobBody(const TruthJob& job) {
  Writer w;
  const SurfaceBuffer& s = job.surface;
  const std::size_t n = static_cast<std::size_t>(s.width) * static_cast<std::size_t>(s.height);
  if (s.position.size() != n || s.normal.size() != n) {
    throw std::invalid_argument("truth job: surface buffer does not match its size");
  }
  w.u64(job.sceneId());
  w.i32(s.width);
  w.i32(s.height);
  w.u32(static_cast<std::uint32_t>(job.positions.size()));
  w.u32(static_cast<std::uint32_t>(job.triangles.size()));
  w.f32(job.scene_radius);
  w.f32(job.rayOffset());
  w.vec3(job.light.position);
  w.vec3(job.light.direction);
  w.u32(job.light.directional ? 1 : 0);
  w.f32(job.light.radius);
  w.i32(job.light.samples);
  w.u32(job.air ? 1 : 0);
  const TruthJob::Air air = job.air.value_or(TruthJob::Air{});
  w.vec3(air.eye);
  w.mat4(air.inverse_view_projection);
  w.f32(air.medium.density);
  w.vec3(air.medium.light_position);
  w.mat4(air.medium.light_view_projection);
  w.i32(air.medium.samples);
  w.u32(air.medium.directional ? 1 : 0);
  w.vec3(air.medium.light_direction);
  const Image spot = air.spot ? air.spot->image() : Image{};
  w.i32(spot.width);
  w.i32(spot.height);
  w.raw(job.positions.data(), job.positions.size() * sizeof(glm::vec3));
  w.raw(job.triangles.data(), job.triangles.size() * sizeof(glm::uvec3));
  w.raw(s.position.data(), n * sizeof(glm::vec4));
  w.raw(s.normal.data(), n * sizeof(glm::vec4));
  w.raw(spot.rgba.data(), spot.rgba.size());
  return std::move(w.bytes);
}

}  // namespace

bool countedPixel(const SurfaceBuffer& s, std::size_t i, const TruthLight& light, glm::vec3& p,
                  glm::vec3& n, float& ndotl) {
  const glm::vec4 pw = s.position[i];
  if (!(pw.w >= 0.0f)) return false;  // also rejects NaN
  p = glm::vec3(pw);
  n = glm::vec3(s.normal[i]);
  if (!finite3(p) || !finite3(n)) return false;
  const float len = glm::length(n);
  if (!(len > 0.0f)) return false;
  n /= len;
  glm::vec3 l;
  if (!lightVector(light, p, l)) return false;
  ndotl = glm::dot(n, l);
  return ndotl >= kGrazingNdotL;
}

std::uint64_t TruthJob::sceneId() const {
  Fnv f;
  f.add(positions.data(), positions.size() * sizeof(glm::vec3));
  f.add(triangles.data(), triangles.size() * sizeof(glm::uvec3));
  f.add(&scene_radius, sizeof scene_radius);
  return f.h;
}

std::uint64_t TruthJob::id() const {
  const std::vector<std::uint8_t> body = jobBody(*this);
  Fnv f;
  f.add(body.data(), body.size());
  return f.h;
}

std::vector<std::uint8_t> serializeTruthJob(const TruthJob& job) {
  std::vector<std::uint8_t> body = jobBody(job);
  Fnv f;
  f.add(body.data(), body.size());
  Writer w;
  w.u32(kJobMagic);
  w.u32(kVersion);
  w.u64(f.h);
  w.raw(body.data(), body.size());
  return std::move(w.bytes);
}

TruthJob parseTruthJob(const std::vector<std::uint8_t>& bytes) {
  const char* what = "truth job";
  Reader r(bytes, what);
  checkHeader(r, kJobMagic, what);
  const auto id = r.get<std::uint64_t>();
  TruthJob job;
  const auto scene_id = r.get<std::uint64_t>();
  SurfaceBuffer& s = job.surface;
  s.width = r.get<std::int32_t>();
  s.height = r.get<std::int32_t>();
  const std::size_t n = pixelCount(s.width, s.height, what);
  const auto vertices = r.get<std::uint32_t>();
  const auto triangles = r.get<std::uint32_t>();
  job.scene_radius = r.get<float>();
  r.get<float>();  // the ray offset, derived from the radius
  job.light.position = r.get<glm::vec3>();
  job.light.direction = r.get<glm::vec3>();
  job.light.directional = r.get<std::uint32_t>() != 0;
  job.light.radius = r.get<float>();
  job.light.samples = r.get<std::int32_t>();
  const bool has_air = r.get<std::uint32_t>() != 0;
  TruthJob::Air air;
  air.eye = r.get<glm::vec3>();
  air.inverse_view_projection = r.get<glm::mat4>();
  air.medium.density = r.get<float>();
  air.medium.light_position = r.get<glm::vec3>();
  air.medium.light_view_projection = r.get<glm::mat4>();
  air.medium.samples = r.get<std::int32_t>();
  air.medium.directional = r.get<std::uint32_t>() != 0;
  air.medium.light_direction = r.get<glm::vec3>();
  Image spot;
  spot.width = r.get<std::int32_t>();
  spot.height = r.get<std::int32_t>();
  const std::size_t texels = pixelCount(spot.width, spot.height, "truth job's spot");
  job.positions = r.array<glm::vec3>(vertices);
  job.triangles = r.array<glm::uvec3>(triangles);
  s.position = r.array<glm::vec4>(n);
  s.normal = r.array<glm::vec4>(n);
  spot.rgba = r.array<std::uint8_t>(texels * 4);
  r.end();
  if (texels > 0) air.spot = SpotTexture::fromImage(std::move(spot));
  if (has_air) job.air = std::move(air);
  for (const glm::uvec3& t : job.triangles) {
    if (t.x >= vertices || t.y >= vertices || t.z >= vertices) {
      throw std::invalid_argument("truth job: triangle index out of range");
    }
  }
  if (job.sceneId() != scene_id || job.id() != id) {
    throw std::invalid_argument("truth job: its id does not match its contents");
  }
  return job;
}

std::vector<std::uint8_t> serializeTruthTrace(const TruthTrace& trace) {
  const std::size_t n = pixelCount(trace.width, trace.height, "truth trace");
  if (trace.visibility.size() != n || (trace.air && trace.air->light.size() != n)) {
    throw std::invalid_argument("truth trace: buffers do not match its size");
  }
  Writer w;
  w.u32(kTraceMagic);
  w.u32(kVersion);
  w.u64(trace.job_id);
  w.i32(trace.width);
  w.i32(trace.height);
  w.u32(trace.air ? 1 : 0);
  w.u32(0);  // keeps the double 8-byte aligned
  w.f64(trace.air ? trace.air->noise : 0.0);
  w.raw(trace.visibility.data(), n * sizeof(float));
  if (trace.air) w.raw(trace.air->light.data(), n * sizeof(float));
  return std::move(w.bytes);
}

namespace {

// A trace's fixed part, before its pixels: magic, version, job id, size, air flag, padding, noise.
constexpr std::size_t kTraceHeaderBytes = 40;

struct TraceHeader {
  std::uint64_t job_id = 0;
  int width = 0, height = 0;
  bool air = false;
  double noise = 0.0;
  std::size_t pixels = 0;
  // The whole trace's bytes as the header describes it.
  std::size_t bytes() const { return kTraceHeaderBytes + pixels * sizeof(float) * (air ? 2 : 1); }
};

TraceHeader readTraceHeader(Reader& r) {
  const char* what = "truth trace";
  checkHeader(r, kTraceMagic, what);
  TraceHeader h;
  h.job_id = r.get<std::uint64_t>();
  h.width = r.get<std::int32_t>();
  h.height = r.get<std::int32_t>();
  h.pixels = pixelCount(h.width, h.height, what);
  h.air = r.get<std::uint32_t>() != 0;
  r.get<std::uint32_t>();
  h.noise = r.get<double>();
  if (!std::isfinite(h.noise) || h.noise < 0.0) {
    throw std::invalid_argument("truth trace: its air noise " + std::to_string(h.noise) +
                                " is not a finite number >= 0");
  }
  return h;
}

// A tracer's answer is a fraction of the light (or kNotCounted) a pixel, and air light >= 0:
// anything else is a damaged or forged file, never a figure to report.
void checkTraceValues(const TruthTrace& t) {
  const auto where = [&t](std::size_t i) {
    return "pixel (" + std::to_string(i % static_cast<std::size_t>(std::max(t.width, 1))) + ", " +
           std::to_string(i / static_cast<std::size_t>(std::max(t.width, 1))) + ")";
  };
  const auto shown = [](float v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", static_cast<double>(v));
    return std::string(text);
  };
  for (std::size_t i = 0; i < t.visibility.size(); ++i) {
    const float v = t.visibility[i];
    if (!(v == kNotCounted || (v >= 0.0f && v <= 1.0f))) {  // NaN fails both
      throw std::invalid_argument("truth trace: visibility " + shown(v) + " at " + where(i) +
                                  " is not in [0, 1] (nor -1, not counted)");
    }
  }
  if (!t.air) return;
  for (std::size_t i = 0; i < t.air->light.size(); ++i) {
    const float v = t.air->light[i];
    if (!(std::isfinite(v) && v >= 0.0f)) {
      throw std::invalid_argument("truth trace: air light " + shown(v) + " at " + where(i) +
                                  " is not a finite number >= 0");
    }
  }
}

}  // namespace

TruthTrace parseTruthTrace(const std::vector<std::uint8_t>& bytes) {
  Reader r(bytes, "truth trace");
  const TraceHeader h = readTraceHeader(r);
  TruthTrace t;
  t.job_id = h.job_id;
  t.width = h.width;
  t.height = h.height;
  t.visibility = r.array<float>(h.pixels);
  if (h.air) t.air = Truth::AirResult{r.array<float>(h.pixels), h.noise};
  r.end();
  checkTraceValues(t);
  return t;
}

TruthTrace readTruthTrace(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw std::invalid_argument("cannot read '" + path + "' (not a regular file)");
  }
  try {
    // The header first, then the file's size against the size it declares: a large file that
    // is no trace (or not this one) is refused before its bytes are read.
    std::ifstream in(path, std::ios::binary);
    std::vector<std::uint8_t> bytes(kTraceHeaderBytes);
    in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    bytes.resize(static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));
    if (!in && !in.eof()) throw std::invalid_argument("cannot be read");
    Reader header(bytes, "truth trace");
    const TraceHeader h = readTraceHeader(header);
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) throw std::invalid_argument("cannot be read (" + ec.message() + ")");
    if (size != h.bytes()) {
      throw std::invalid_argument("truth trace of " + std::to_string(h.width) + "x" +
                                  std::to_string(h.height) + " is " + std::to_string(h.bytes()) +
                                  " bytes, the file " + std::to_string(size));
    }
    bytes.resize(h.bytes());
    in.read(reinterpret_cast<char*>(bytes.data() + kTraceHeaderBytes),
            static_cast<std::streamsize>(h.bytes() - kTraceHeaderBytes));
    if (static_cast<std::size_t>(in.gcount()) != h.bytes() - kTraceHeaderBytes) {
      throw std::invalid_argument("cannot be read to its end");
    }
    return parseTruthTrace(bytes);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("'" + path + "': " + e.what());
  }
}

bool keepTruthTrace(const std::string& path, const TruthTrace& trace) {
  std::error_code ec;
  std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
  const std::string part = path + "." + std::to_string(getpid()) + ".part";
  const std::vector<std::uint8_t> bytes = serializeTruthTrace(trace);
  std::ofstream out(part, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()),
            static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (out && !ec) std::filesystem::rename(part, path, ec);
  const bool kept = out && !ec;
  if (!kept) std::filesystem::remove(part, ec);
  return kept;
}

}  // namespace shadows
