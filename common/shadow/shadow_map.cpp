#include "shadow/shadow_map.hpp"

namespace shadows {

void ShadowMap::declare(Params& p) {
  const Params::SharedScope shared(p);
  light_.declareSize(p);
  format_ = p.addChoice("shadow.format", {"16", "24", "32f"}, "24", "depth bits of the map",
                        kDirtyShadowMap | kDirtyResources);
  filter_param_ =
      p.addChoice("shadow.filter", {"nearest", "linear"}, "nearest",
                  "linear = the hardware 2x2 compare filter (results averaged, never depths)");
  light_.declareFit(p);
  inset_ = p.addBool("inset", true, "show the depth map in a corner");
}

bool ShadowMap::prepare(Frame& f, std::uint32_t extraDirty) {
  const glm::ivec2 size = light_.mapSize();
  const std::string& format = format_.name();
  const int bits = format == "16" ? 16 : format == "24" ? 24 : 32;
  bool recreated = false;
  if (f.params.consume(kDirtyResources) || size != size_ || bits != bits_) {
    size_ = size, bits_ = bits;
    texture_ = Texture::depth(size.x, size.y, bits);
    texture_.setCompare(true);  // sampler2DShadow: the texture unit does the compare
    framebuffer_ = std::make_unique<Framebuffer>();
    framebuffer_->attachDepth(texture_);
    framebuffer_->check();
    recreated = true;
  }
  filter_ = filter_param_.name() == "linear" ? GL_LINEAR : GL_NEAREST;
  texture_.setFilter(filter_);
  return light_.update(f, size, recreated, extraDirty);
}

void ShadowMap::beginRender() const {
  framebuffer_->bind();
  glViewport(0, 0, size_.x, size_.y);
  glClear(GL_DEPTH_BUFFER_BIT);
}

void ShadowMap::renderCasters(Frame& f, const Program& depthProgram, const PassState& state,
                              Objects which) const {
  auto timing = f.measure.pass("shadow");
  f.measure.count("shadow_map_renders");
  beginRender();
  state.apply();
  const glm::mat4 light_view_projection = lightViewProjection();
  depthProgram.set("uLightViewProjection", light_view_projection);
  f.drawObjects(depthProgram, which, &light_view_projection);
  PassState{}.apply();
}

void ShadowMap::renderCasters(Frame& f, const PassState& state, Objects which) {
  renderCasters(f, depthOnly(), state, which);
}

void ShadowMap::renderObject(Frame& f, size_t index, const PassState& state) {
  const Program& program = depthOnly();
  auto timing = f.measure.pass("shadow");
  f.measure.count("shadow_map_renders");
  beginRender();
  state.apply();
  program.use();
  program.set("uLightViewProjection", lightViewProjection());
  f.drawObject(program, index);
  PassState{}.apply();
}

const Program& ShadowMap::depthOnly() {
  if (depth_only_.id() == 0) {
    depth_only_ =
        Program(commonShaderDir() / "light_depth.vert", commonShaderDir() / "depth_only.frag");
  }
  return depth_only_;
}

bool ShadowMap::drawDepthView(const Frame& frame) const {
  if (!frame.shows(views::kLightDepth)) return false;
  frame.clearTarget(glm::vec3(0.0f));
  drawInset(frame, /*fullscreen=*/true);
  return true;
}

void ShadowMap::drawInset(const Frame& frame, bool fullscreen) const {
  if ((!inset_() || light_.off()) && !fullscreen) return;
  const LightFrustum& fr = light_.frustum();
  frame.drawDepthInset(texture_, fr.near, fr.far, !fr.directional, fullscreen);
}

void BackFaceBias::declare(Params& p, const std::string& helpPrefix) {
  factor_ = p.addFloat("bias.factor", 1.1f, 0.0f, 20.0f, helpPrefix + "glPolygonOffset factor",
                       kDirtyShadowMap);
  units_ = p.addFloat("bias.units", 4.0f, 0.0f, 1e7f, helpPrefix + "glPolygonOffset units",
                      kDirtyShadowMap)
               .logScale();
}

}  // namespace shadows
