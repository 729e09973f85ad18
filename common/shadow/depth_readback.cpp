#include "shadow/depth_readback.hpp"

#include "core/json.hpp"

#include <imgui.h>

#include <bit>
#include <cstring>

#include "shadow/depth_digits.hpp"

namespace shadows {

void DepthReadback::declare(Params& p, bool linearChoice) {
  const Params::SharedScope shared(p);
  const int digits = digits_;
  light_.declareSize(p);
  light_.declareFit(p);
  light_.trackCasterDistances();  // the report's and panel's step at the casters
  // 000: "frustum confined to objects of interest" is where few bits are enough.
  p.setDefaultFloat(p.at("shadow.fit"), 1.0);
  if (linearChoice) {
    encoding_ =
        p.addChoice("map.encoding", {"projective", "linear"}, "projective",
                    "projective: window depth read back; linear: Heidrich's eye-planar Z in colour",
                    kDirtyShadowMap | kDirtyResources);
  }
  path_param_ =
      p.addChoice("map.path", {"read_pixels", "copy_texture", "render_to_texture"}, "read_pixels",
                  "how the depth reaches a texture: glReadPixels + glTexSubImage2D, "
                  "glCopyTexSubImage2D, or none (the light pass's own texture)",
                  kDirtyShadowMap | kDirtyResources);
  depth_bits_param_ =
      p.addChoice("map.depth_bits", {"24", "16"}, "24",
                  "the light pass's depth buffer (000: copies are fastest when it matches the "
                  "texture's precision)",
                  kDirtyShadowMap | kDirtyResources);
  bias_mode_ =
      p.addChoice("bias.mode", {"polygon_offset", "texgen"}, "polygon_offset",
                  "polygon_offset: while the map is built (000); texgen: subtracted from the "
                  "fragment's r before the divide (000: does not work)",
                  kDirtyShadowMap);
  bias_factor_ = p.addFloat("bias.factor", 2.0f, 0.0f, 20.0f,
                            "glPolygonOffset factor (slope scale)", kDirtyShadowMap);
  const std::string step = digits == 1 ? "1/255" : "1/65535";
  Param& steps =
      p.addFloat("bias.steps", 3.0f, 0.0f, digits == 1 ? 64.0f : 4096.0f,
                 "constant bias in map steps (" + step + " of the depth range)", kDirtyShadowMap);
  steps.logarithmic = digits == 2;
  bias_steps_ = steps;
  inset_param_ = p.addBool("inset", true, "show the map in a corner");
}

namespace {
// Whether glReadPixels rounds a depth to the nearest step or down (the GL allows both): clear
// a 1x1 depth buffer to 100.7 steps and read it back. Where depth cannot be read back (OpenGL
// ES) the conversion pass quantizes instead, and does what Mesa's glReadPixels does, on which
// the goldens were made: bytes down, shorts to the nearest step.
bool driverReadbackRoundsToNearest(int digits, [[maybe_unused]] int depthBits) {
#if SHADOWS_GLES
  return digits == 2;
#else
  const Texture depth = Texture::depth(1, 1, depthBits);
  Framebuffer target;
  target.attachDepth(depth);
  const double top = digits == 1 ? 255.0 : 65535.0;
  glClearDepth(100.7 / top);
  glClear(GL_DEPTH_BUFFER_BIT);
  glClearDepth(1.0);
  std::uint16_t value[2] = {0, 0};
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, digits == 1 ? GL_UNSIGNED_BYTE : GL_UNSIGNED_SHORT,
               value);
  const int steps = digits == 1 ? reinterpret_cast<std::uint8_t*>(value)[0] : value[0];
  return steps == 101;
#endif
}

// A 1x1 depth texture's value without reading depth back (OpenGL ES): a pass writes its float's
// bits into a colour target (common/shaders/depth_bits.frag), and those are read.
[[maybe_unused]] float depthThroughColour(const Texture& depth, const Program& bits) {
  const Texture color = Texture::color(1, 1, GL_RGBA8);
  Framebuffer target;
  target.attachColor(color);
  glViewport(0, 0, 1, 1);
  PassState convert;
  convert.depth_test = false;
  convert.apply();
  depth.bind(0);
  bits.set("uDepth", 0);
  GLuint vao = 0;
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  bits.use();
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDeleteVertexArrays(1, &vao);
  PassState{}.apply();
  std::uint8_t bytes[4] = {0, 0, 0, 0};
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, bytes);
  const std::uint32_t word =
      bytes[0] | bytes[1] << 8 | bytes[2] << 16 | static_cast<std::uint32_t>(bytes[3]) << 24;
  float value = 0.0f;  // std::bit_cast, which emscripten 3.1's libc++ lacks
  std::memcpy(&value, &word, sizeof value);
  return value;
}
// The size of one glPolygonOffset `unit` in window depth for a depth buffer of these bits:
// "the smallest value guaranteed to produce a resolvable offset", whose size the GL leaves
// to the driver (llvmpipe's is 2^-23 for 24 bits, twice 1 / (2^24 - 1)). Measured: a
// triangle at depth 0.5, offset by 1000 units, into a 1x1 depth buffer, read back (on OpenGL
// ES through colour, depthThroughColour).
float driverOffsetUnit(int depthBits, const Program& flat, [[maybe_unused]] const Program& bits) {
  const Texture depth = Texture::depth(1, 1, depthBits);
  Framebuffer target;
  target.attachDepth(depth);
  glViewport(0, 0, 1, 1);
  glClearDepthf(1.0f);
  glClear(GL_DEPTH_BUFFER_BIT);
  PassState offset;
  offset.depth_func = GL_ALWAYS;
  offset.polygon_offset = true;
  offset.offset_units = 1000.0f;
  offset.apply();
  GLuint vao = 0;
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  flat.use();
  glDrawArrays(GL_TRIANGLES, 0, 3);  // fullscreen.vert: z = 0, window depth 0.5
  glDeleteVertexArrays(1, &vao);
  PassState{}.apply();
#if SHADOWS_GLES
  const float value = depthThroughColour(depth, bits);
#else
  float value = 0.5f;
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &value);
#endif
  return std::max((value - 0.5f) / 1000.0f, 1e-12f);
}

}  // namespace

void DepthReadback::init() {
  const auto dir = commonShaderDir();
  light_program_ = Program(dir / "readback_light.vert", dir / "readback_light.frag");
  probe_program_ = Program(dir / "fullscreen.vert", dir / "depth_only.frag");
  if (!caps().depth_readback) {
    bits_program_ = Program(dir / "fullscreen.vert", dir / "depth_bits.frag");
    digits_program_ = Program(dir / "fullscreen.vert", dir / "depth_to_digits.frag");
    GLuint vao = 0;
    glGenVertexArrays(1, &vao);
    empty_vao_ = GlName<deleteVertexArray>(vao);
  }
  if (digits_ == 1) {
    // 256 texels, texel i holding i (the last one step short: see rampSteps).
    std::vector<std::uint8_t> ramp(256);
    for (int i = 0; i < 256; ++i) ramp[static_cast<size_t>(i)] = static_cast<std::uint8_t>(i);
    ramp[255] = 254;
    ramp_ = Texture::table1D(256, GL_R8, GL_RED, ramp.data());
  } else {
    // 256 x 256, linear along both axes: column = big digit (r), row = little digit (g).
    std::vector<std::uint8_t> ramp(256 * 256 * 2);
    for (int row = 0; row < 256; ++row) {
      for (int column = 0; column < 256; ++column) {
        const size_t at = 2 * static_cast<size_t>(row * 256 + column);
        ramp[at] = static_cast<std::uint8_t>(column);
        ramp[at + 1] = static_cast<std::uint8_t>(row);
      }
    }
    ramp[ramp.size() - 1] = 254;  // texel (255, 255): see rampDigits
    // Pass 2 needs only the big digit: "a linear 1D texture" (texel i holding i, all 256).
    std::vector<std::uint8_t> big(256);
    for (int i = 0; i < 256; ++i) big[static_cast<size_t>(i)] = static_cast<std::uint8_t>(i);
    ramp_big_ = Texture::table1D(256, GL_R8, GL_RED, big.data());
    ramp_ = Texture::color(256, 256, GL_RG8);
    ramp_.upload(GL_RG, GL_UNSIGNED_BYTE, ramp.data());
    ramp_.setFilter(GL_NEAREST);
    ramp_.setWrap(GL_CLAMP_TO_EDGE, GL_REPEAT);  // t = 256 s wraps once per big digit
  }
}

bool DepthReadback::prepare(Frame& f) {
  const glm::ivec2 size = light_.mapSize();
  linear_ = encoding_.valid() && encoding_.name() == "linear";
  path_ = path_param_.name();
  inset_ = inset_param_();
  depth_bits_ = depth_bits_param_.name() == "16" ? 16 : 24;
  const std::string key =
      path_ + (linear_ ? "/linear/" : "/projective/") + std::to_string(depth_bits_);
  bool recreated = false;
  if (f.params.consume(kDirtyResources) || size != size_ || key != storage_key_) {
    storage_key_ = key;
    recreate(size);
    recreated = true;
  }
  return light_.update(f, size, recreated);
}

void DepthReadback::recreate(glm::ivec2 size) {
  size_ = size;
  nearest_ = driverReadbackRoundsToNearest(digits_, depth_bits_);
  offset_unit_ = driverOffsetUnit(depth_bits_, probe_program_, bits_program_);
  const glm::vec4 nothing_in_front(1.0f);  // outside the map: the cleared value, lit
  light_depth_ = Texture::depth(size.x, size.y, depth_bits_);
  light_target_ = std::make_unique<Framebuffer>();
  if (linear_) {
    light_color_ = Texture::color(size.x, size.y, GL_R8);
    light_color_.setFilter(GL_NEAREST);
    light_color_.setWrap(GL_CLAMP_TO_BORDER, GL_CLAMP_TO_BORDER);
    light_color_.setBorder(nothing_in_front);
    light_color_.setSwizzle(GL_RED, GL_RED, GL_RED, GL_ONE);  // grey in the inset
    light_target_->attachColor(light_color_);
  } else {
    light_color_ = Texture();
  }
  light_target_->attachDepth(light_depth_);
  light_target_->check();
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
                                        GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE,
                                        &allocated_depth_bits_);
  // No depth read back or copied on OpenGL ES: a pass writes the map's digits into a colour
  // target, and that is read back or copied instead (common/shaders/depth_to_digits.frag).
  digits_color_ = Texture();
  digits_target_.reset();
  if (throughColour() && path_ != "render_to_texture") {
    digits_color_ = Texture::color(size.x, size.y, GL_RGBA8);
    digits_color_.setFilter(GL_NEAREST);
    digits_target_ = std::make_unique<Framebuffer>();
    digits_target_->attachColor(digits_color_);
    digits_target_->check();
  }

  digits_texture_ = Texture();
  copied_ = Texture();
  bytes_.clear();
  shorts_.clear();
  if (path_ == "read_pixels") {
    digits_texture_ = Texture::color(size.x, size.y, digits_ == 1 ? GL_R8 : GL_RG8);
    digits_texture_.setFilter(GL_NEAREST);
    digits_texture_.setWrap(GL_CLAMP_TO_BORDER, GL_CLAMP_TO_BORDER);
    digits_texture_.setBorder(nothing_in_front);
    if (digits_ == 1) {
      digits_texture_.setSwizzle(GL_RED, GL_RED, GL_RED, GL_ONE);
    } else if (throughColour()) {
      // The conversion pass wrote the big digit in r already.
    } else if constexpr (std::endian::native == std::endian::little) {
      // A 16-bit value's low byte comes first in memory: swap so r is the big digit.
      digits_texture_.setSwizzle(GL_GREEN, GL_RED, GL_ZERO, GL_ONE);
    }
  } else if (path_ == "copy_texture") {
    if (throughColour()) {
      copied_ = Texture::color(size.x, size.y, digits_ == 1 ? GL_R8 : GL_RG8);  // the digits
      if (digits_ == 1) copied_.setSwizzle(GL_RED, GL_RED, GL_RED, GL_ONE);
    } else if (linear_) {
      copied_ = Texture::color(size.x, size.y, GL_R8);
      copied_.setSwizzle(GL_RED, GL_RED, GL_RED, GL_ONE);
    } else {
      copied_ = Texture::depth(size.x, size.y, depth_bits_);
    }
    copied_.setFilter(GL_NEAREST);
    copied_.setWrap(GL_CLAMP_TO_BORDER, GL_CLAMP_TO_BORDER);
    copied_.setBorder(nothing_in_front);
  }
}

void DepthReadback::render(Frame& f) {
  const bool offset = bias_mode_.name() == "polygon_offset";
  const float factor = bias_factor_(), steps = bias_steps_();
  {
    auto timing = f.measure.pass("shadow");
    f.measure.count("shadow_map_renders");
    light_target_->bind();
    glViewport(0, 0, size_.x, size_.y);
    PassState state;
    // 000: "perform bias during depth map construct ... so bias will be in depth buffer
    // space". `steps` map steps in glPolygonOffset units, as this driver sizes a unit.
    state.polygon_offset = offset && !linear_;
    state.offset_factor = factor;
    state.offset_units = steps / (digits_ == 1 ? 255.0f : 65535.0f) / offset_unit_;
    state.apply();
    glClearColor(1.0f, 1.0f, 1.0f, 1.0f);  // linear: "nothing in front" is the top step
    glClear(GL_DEPTH_BUFFER_BIT | (linear_ ? GL_COLOR_BUFFER_BIT : 0u));
    const glm::mat4 light_view_projection = light_.viewProjection();
    light_program_.set("uLightViewProjection", light_view_projection);
    light_program_.set("uLinear", linear_ ? 1 : 0);
    light_program_.set("uLinearPlane", linearPlane());
    light_program_.set("uRamp", 1);
    // Linear depth lives in colour, where glPolygonOffset does not reach: the light pass adds
    // the same slope-scaled offset to what it writes.
    light_program_.set("uOffsetFactor", offset ? factor : 0.0f);
    light_program_.set("uOffsetSteps", offset ? steps : 0.0f);
    ramp_.bind(1);
    f.drawObjects(light_program_, Objects::Casters, &light_view_projection);
    PassState{}.apply();
  }
  transfer(f);
}

void DepthReadback::transfer(Frame& f) {
  if (path_ == "render_to_texture") return;  // the eye pass reads the light pass's texture
  auto timing = f.measure.pass("readback");
  const int w = size_.x, h = size_.y;
  const auto texels = static_cast<size_t>(w) * static_cast<size_t>(h);
  if (throughColour()) writeDigits();  // OpenGL ES: the depth's digits into colour first
  (throughColour() ? *digits_target_ : *light_target_).bind();
  if (path_ == "copy_texture") {
    // Within the GPU: depth buffer to depth texture (or colour to colour: linear, and the
    // digits on OpenGL ES).
    glBindTexture(GL_TEXTURE_2D, copied_.id());
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, w, h);
    f.measure.count("copied_texels", static_cast<long long>(texels));
    return;
  }
  // Through the CPU, as un-extended OpenGL had to: read back, then load into the texture.
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  if (!caps().depth_readback) {
    // OpenGL ES reads colour as RGBA only: four bytes a texel, the digits in r and g.
    std::vector<std::uint8_t> rgba(texels * 4);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    bytes_.resize(texels * static_cast<size_t>(digits_));
    for (size_t i = 0; i < texels; ++i) {
      for (size_t d = 0; d < static_cast<size_t>(digits_); ++d) {
        bytes_[i * static_cast<size_t>(digits_) + d] = rgba[i * 4 + d];
      }
    }
    digits_texture_.upload(digits_ == 1 ? GL_RED : GL_RG, GL_UNSIGNED_BYTE, bytes_.data());
    if (digits_ == 2) bytes_.clear();  // lastBytes(): one digit only
    f.measure.count("readback_bytes", static_cast<long long>(rgba.size()));
    return;
  }
  if (digits_ == 2) {
    shorts_.resize(texels);
    glReadPixels(0, 0, w, h, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, shorts_.data());
    digits_texture_.upload(GL_RG, GL_UNSIGNED_BYTE, shorts_.data());
  } else {
    bytes_.resize(texels);
    if (linear_) glReadBuffer(GL_COLOR_ATTACHMENT0);
    glReadPixels(0, 0, w, h, linear_ ? GL_RED : GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE,
                 bytes_.data());
    digits_texture_.upload(GL_RED, GL_UNSIGNED_BYTE, bytes_.data());
  }
  f.measure.count("readback_bytes", static_cast<long long>(texels) * digits_);
}

glm::vec4 DepthReadback::linearPlane() const {
  // S = (eye-planar distance from the light - near) / (far - near), as one plane equation
  // (000, "Improving Depth Map Precision"): distance = -(V_light * p).z.
  const glm::mat4& v = light_.view();
  const LightFrustum& fr = light_.frustum();
  const float range = std::max(fr.far - fr.near, 1e-6f);
  const glm::vec4 row_z(v[0][2], v[1][2], v[2][2], v[3][2]);
  return (-row_z - glm::vec4(0.0f, 0.0f, 0.0f, fr.near)) / range;
}

float DepthReadback::texgenBias(const Frame& f) const {
  if (bias_mode_.name() != "texgen") return 0.0f;
  const float step = bias_steps_() / (digits_ == 1 ? 255.0f : 65535.0f);
  if (linear_ || light_.frustum().directional) return step;  // q = 1: a plain constant
  // 000's mistake: r - b before the divide by q is b / q after it. Tuned to `steps` at the
  // light's target, it is more in front of it and less behind, and has no slope term.
  return step * std::max(glm::distance(f.light.position, f.light.target), 1e-3f);
}

void DepthReadback::writeDigits() const {
  digits_target_->bind();
  glViewport(0, 0, size_.x, size_.y);
  PassState convert;
  convert.depth_test = false;
  convert.depth_write = false;
  convert.apply();
  light_depth_.bind(0);
  digits_program_.set("uDepth", 0);
  digits_program_.set("uDigits", digits_);
  digits_program_.set("uReadbackNearest", nearest_ ? 1 : 0);
  digits_program_.use();
  glBindVertexArray(empty_vao_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  countDrawCall();
  PassState{}.apply();
}

const Texture& DepthReadback::lookupTexture() const {
  if (path_ == "read_pixels") return digits_texture_;
  if (path_ == "copy_texture") return copied_;
  return linear_ ? light_color_ : light_depth_;
}

void DepthReadback::bindForLookup(const Frame& f, const Program& program) const {
  lookupTexture().bind(0);
  ramp_.bind(1);
  program.set("uMap", 0);
  program.set("uRamp", 1);
  if (digits_ == 2) {
    ramp_big_.bind(2);
    program.set("uRampBig", 2);
  }
  // Depth textures hold depth, not steps: the shader quantizes as glReadPixels would.
  program.set("uMapIsDepth", mapIsDepth() ? 1 : 0);
  program.set("uReadbackNearest", nearest_ ? 1 : 0);
  program.set("uLinear", linear_ ? 1 : 0);
  program.set("uShadowMatrix", light_.textureMatrix());
  program.set("uLinearPlane", linearPlane());
  program.set("uTexgenBias", texgenBias(f));
}

const Program& DepthReadback::eyePass(const Frame& f, const Program& program, float dimming) const {
  program.set("uViewProjection", f.projection * f.view);
  bindForLookup(f, program);
  f.setLightingUniforms(program, dimming);
  return program;
}

bool DepthReadback::drawBasePass(Frame& f, const Program& program, bool color) const {
  auto timing = f.measure.pass("pass1", /*countPassed=*/true);
  PassState state;
  state.color_write = color || light_.off();
  state.apply();
  f.drawObjects(program, Objects::All);
  return !light_.off();
}

void DepthReadback::drawInset(const Frame& frame, bool fullscreen) const {
  if ((!inset_ || light_.off()) && !fullscreen) return;
  const Texture& map = lookupTexture();
  // OpenGL ES copied digits, not depth: the inset shows the depth they were made from.
  const bool copied_digits = throughColour() && path_ == "copy_texture";
  if (mapIsDepth() || copied_digits) {
    const LightFrustum& fr = light_.frustum();
    frame.drawDepthInset(copied_digits ? light_depth_ : map, fr.near, fr.far, !fr.directional,
                         fullscreen);
  } else {
    frame.drawImageInset(map, fullscreen);
  }
}

float DepthReadback::stepWorldAt(float distance) const {
  return depthStepWorld(light_.frustum(), distance, digits_ == 1 ? 255.0 : 65535.0, linear_);
}

void DepthReadback::report(JsonWriter& json) const {
  json.value("light_near_used", light_.frustum().near);
  json.value("light_far_used", light_.frustum().far);
  json.value("light_depth_bits", allocated_depth_bits_);
  json.value("light_offset_unit", offset_unit_);
  json.value("step_world_at_nearest_caster", stepWorldAt(light_.casterDistances().x));
  json.value("step_world_at_farthest_caster", stepWorldAt(light_.casterDistances().y));
}

void DepthReadback::precisionPanel() const {
  const LightFrustum& fr = light_.frustum();
  ImGui::Text("near %.3g  far %.4g in use", fr.near, fr.far);
  if (light_.fitted()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("fitted to the casters: light.near and light.far act with shadow.fit off");
    ImGui::PopStyleColor();
  }
  const glm::vec2 casters = light_.casterDistances();
  ImGui::TextWrapped(
      "one %d-bit step: %.3g world units at the nearest caster, %.3g at the "
      "farthest",
      8 * digits_, stepWorldAt(casters.x), stepWorldAt(casters.y));
}

}  // namespace shadows
