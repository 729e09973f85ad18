// Seed 000's shadow map for hardware without depth textures (lessons 06 and 07): the light's
// depth, offset with glPolygonOffset while it is built, moved into a texture of 8-bit digits
// (one: Heidrich's dual-texture test; two: McCool's multi-digit test) along one of 000's
// paths, each timed as its own pass and counted:
//   read_pixels        glReadPixels as unsigned bytes (or shorts), glTexSubImage2D into an
//                      8-bit texture: "un-extended OpenGL provides no direct depth copy"
//   copy_texture       glCopyTexSubImage2D from the depth buffer into a depth texture
//                      ("fast copies from depth buffer to texture"), quantized when read
//   render_to_texture  no copy: the light pass's own depth texture, quantized when read
// Whatever the path, the eye pass sees the same bits (depth_digits.glsl quantizes the two
// depth-texture paths exactly as the driver's glReadPixels does).
#pragma once

#include <vector>

#include "shadow/light_view.hpp"

namespace shadows {

class JsonWriter;

class DepthReadback {
 public:
  // The light view's shadow.* parameters plus map.path, map.depth_bits, bias.mode,
  // bias.factor, bias.steps, inset; with `linearChoice`, map.encoding (Heidrich's linear
  // depth in colour).
  void declare(Params& params, bool linearChoice);

  explicit DepthReadback(int digits) : digits_(digits) {}
  void init();  // programs and ramp textures (context current)

  // The light's view and the map's storage for this frame; true when the map must be
  // rendered again (see LightView::update).
  bool prepare(Frame& frame);
  // The light pass (pass "shadow": casters only, with the bias where bias.mode puts it,
  // counted as shadow_map_renders), then the move into the lookup texture (pass "readback",
  // counting readback_bytes).
  void render(Frame& frame);
  // The eye passes read this map (LightView::sampledBy).
  void sampledBy(Frame& frame) const { light_.sampledBy(frame); }

  // Binds Tex0 (the map) to unit 0, Tex1 (the ramp) to unit 1 (two digits: pass 2's 1D ramp
  // to unit 2), and sets what the eye shaders of 06/07 read: uMap, uRamp(Big), uMapIsDepth,
  // uReadbackNearest, uLinear, uShadowMatrix, uLinearPlane, uTexgenBias.
  void bindForLookup(const Frame& frame, const Program& program) const;
  // An eye pass of 06/07 ready to draw: bindForLookup, the camera and the lighting (with
  // `dimming`) set on `program`, which it returns.
  const Program& eyePass(const Frame& frame, const Program& program, float dimming) const;
  // Pass 1 of the slides' multi-pass compare, timed as "pass1": everything drawn dimmed with
  // `program`, laying the depth the lit passes must GL_EQUAL (with `color` off it still lays
  // it, in no colour). With shadow.off the baseline instead: `program` (the lesson's pass 1
  // compiled with SHADOW_OFF) lights everything once, and this returns false: no lit passes
  // follow.
  bool drawBasePass(Frame& frame, const Program& program, bool color) const;
  // The map over the whole target (view "map") or in a corner, when `inset` is on.
  void drawInset(const Frame& frame, bool fullscreen = false) const;

  const LightView& light() const { return light_; }
  bool linear() const { return linear_; }
  const std::string& path() const { return path_; }
  // Whether this driver's glReadPixels rounds depth to the nearest step (else it truncates).
  bool readbackRoundsToNearest() const { return nearest_; }
  // One glPolygonOffset unit in window depth on this driver and depth buffer (measured).
  float offsetUnit() const { return offset_unit_; }
  // The report fields of the map: `light_near_used`, `light_far_used`, the light pass's depth
  // buffer as the driver gives it (`light_depth_bits`, GL_TEXTURE_DEPTH_SIZE of what
  // map.depth_bits allocated; `light_offset_unit`, offsetUnit()), and the world size of one
  // step of the map at the nearest and the farthest caster (`step_world_at_nearest_caster`,
  // `step_world_at_farthest_caster`): where precision is spent, near decides.
  void report(JsonWriter& json) const;
  // The panel's lines on the same: the near and far in use (and whether the sliders act),
  // and the step at the casters.
  void precisionPanel() const;
  // One step of this map (8 or 16 bits, projective or linear) at `distance` from the light.
  float stepWorldAt(float distance) const;
  long long bytesPerFrame() const {
    return static_cast<long long>(light_.size().x) * light_.size().y * digits_;
  }
  // The 8-bit steps of a read back map (read_pixels path only; empty otherwise): tests
  // compare them with what the other paths quantize.
  const std::vector<std::uint8_t>& lastBytes() const { return bytes_; }

 private:
  void recreate(glm::ivec2 size);
  void transfer(Frame& frame);
  // OpenGL ES reads and copies no depth: the projective map goes through colour there.
  bool throughColour() const { return !caps().depth_readback && !linear_; }
  void writeDigits() const;  // the light depth's digits into digits_color_
  // Whether the eye pass reads depth (and quantizes it) rather than 8-bit digits.
  bool mapIsDepth() const {
    return !linear_ &&
           (path_ == "render_to_texture" || (path_ == "copy_texture" && caps().depth_readback));
  }
  glm::vec4 linearPlane() const;
  float texgenBias(const Frame& frame) const;
  const Texture& lookupTexture() const;

  int digits_;
  LightView light_;
  Program light_program_, probe_program_;
  Program bits_program_, digits_program_;  // OpenGL ES: depth through colour
  GlName<deleteVertexArray> empty_vao_;
  Texture ramp_;                       // Tex1: 1D (one digit) or 2D (two digits) ramp
  Texture ramp_big_;                   // two digits: the 1D ramp of pass 2 (big digit only)
  Texture light_depth_, light_color_;  // what the light pass renders into
  std::unique_ptr<Framebuffer> light_target_;
  Texture digits_color_;  // OpenGL ES: the map's digits, written from its depth
  std::unique_ptr<Framebuffer> digits_target_;
  Texture digits_texture_;  // read_pixels: R8 or RG8 (big digit in r)
  Texture copied_;          // copy_texture: GL_DEPTH_COMPONENT24 (R8 for linear depth)
  std::vector<std::uint8_t> bytes_;
  std::vector<std::uint16_t> shorts_;
  glm::ivec2 size_{0};
  int depth_bits_ = 24;
  int allocated_depth_bits_ = 0;  // asked of the driver after allocating
  std::string path_, storage_key_;
  bool linear_ = false, inset_ = true;
  ChoiceParam<> encoding_, path_param_, depth_bits_param_, bias_mode_;
  FloatParam bias_factor_, bias_steps_;
  BoolParam inset_param_;
  bool nearest_ = true;  // whether glReadPixels rounds to nearest on this driver (depthToSteps)
  float offset_unit_ = 1.0f / 16777215.0f;  // one glPolygonOffset unit, measured (window depth)
};

}  // namespace shadows
