// The runner's half of Frame's draw helpers: the scene's meshes, insets and full-screen passes.
#include "run/scene_host.hpp"

#include <algorithm>
#include <numeric>

#include "run/truth_measure.hpp"

namespace shadows {

void SceneHost::load(Scene scene) {
  scene_ = std::move(scene);
  preset_models_.clear();
  for (const auto& object : scene_.objects) preset_models_.push_back(object.model);
  if (!gl_) return;
  meshes_.clear();
  for (const auto& object : scene_.objects) meshes_.emplace_back(object.mesh);
}

void SceneHost::initGl() {
  const auto dir = commonShaderDir();
  image_ = Program(dir / "fullscreen.vert", dir / "image.frag");
  depth_inset_ = Program(dir / "fullscreen.vert", dir / "depth_inset.frag");
  glGenVertexArrays(1, &empty_vao_);
  gl_ = true;
  meshes_.clear();
  for (const auto& object : scene_.objects) meshes_.emplace_back(object.mesh);
}

void SceneHost::releaseGl() {
  meshes_.clear();
  image_ = Program();
  depth_inset_ = Program();
  shown_ = Texture();
  if (empty_vao_ != 0) glDeleteVertexArrays(1, &empty_vao_);
  empty_vao_ = 0;
  gl_ = false;
}

void SceneHost::showImage(const Frame& frame, const Image& image) {
  if (image.width == 0) return;
  if (shown_.width() != image.width || shown_.height() != image.height) {
    shown_ = Texture::color(image.width, image.height, GL_RGBA8);
  }
  glBindTexture(GL_TEXTURE_2D, shown_.id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE,
                  image.rgba.data());
  frame.drawImageInset(shown_, /*fullscreen=*/true);
}

void SceneHost::drawCovering() const {
  glBindVertexArray(empty_vao_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

const ErrorState& SceneHost::lastError() const {
  return truth_.error();
}

void SceneHost::drawFullscreen(const Frame& frame, const Program& program, bool inset) const {
  frame.bindTarget();
  const int side = std::max(16, std::min(frame.width, frame.height) / 4);
  if (inset) glViewport(frame.width - side - 8, 8, side, side);
  glDisable(GL_DEPTH_TEST);
  program.use();
  glBindVertexArray(empty_vao_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  countDrawCall();
  glEnable(GL_DEPTH_TEST);
  frame.bindTarget();
}

void SceneHost::drawImageInset(const Frame& frame, const Texture& image, bool fullscreen) const {
  const int side = std::max(16, std::min(frame.width, frame.height) / 4);
  const int wide = std::max(1, side * image.width() / std::max(image.height(), 1));
  frame.bindTarget();
  if (!fullscreen) glViewport(frame.width - wide - 8, 8, wide, side);
  glDisable(GL_DEPTH_TEST);
  image.bind(0);
  image_.use();
  image_.set("uImage", 0);
  image_.set("uHasBorder", image.border() ? 1 : 0);
  image_.set("uBorder", image.border().value_or(glm::vec4(0.0f)));
  image_.set("uLinear", image.filter() == GL_LINEAR ? 1 : 0);
  // The texture's swizzle, where the GL did not apply it: output channel i reads source
  // channel swizzle[i] (column j of the matrix is source channel j), or the constant 0 or 1.
  glm::mat4 swizzle(1.0f);
  glm::vec4 constant(0.0f);
  if (!caps().texture_swizzle) {
    swizzle = glm::mat4(0.0f);
    for (int i = 0; i < 4; ++i) {
      switch (image.swizzle()[i]) {
        case GL_RED:
          swizzle[0][i] = 1.0f;
          break;
        case GL_GREEN:
          swizzle[1][i] = 1.0f;
          break;
        case GL_BLUE:
          swizzle[2][i] = 1.0f;
          break;
        case GL_ALPHA:
          swizzle[3][i] = 1.0f;
          break;
        case GL_ONE:
          constant[i] = 1.0f;
          break;
        default:
          break;  // GL_ZERO
      }
    }
  }
  image_.set("uSwizzle", swizzle);
  image_.set("uSwizzleConstant", constant);
  glBindVertexArray(empty_vao_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  countDrawCall();
  glEnable(GL_DEPTH_TEST);
  frame.bindTarget();
}

void SceneHost::drawObjects(const Frame& frame, const Program& program, Objects which,
                            const glm::mat4* cull) const {
  program.use();
  std::vector<size_t> order(scene_.objects.size());
  std::iota(order.begin(), order.end(), size_t{0});
  // The eye's view, drawn so the depth test rejects hidden fragments before they are shaded:
  // solids front to back, then the one-sided planes they stand on (which cover most of the
  // screen and lie behind them).
  const bool eye_view = which == Objects::All;
  // A closed solid's nearest surface, from the eye or from the light, is always a face turned
  // toward it: its back faces can only fail the depth test, and skipping them changes no
  // depth. Unless the pass culls for its own reasons (a bias that keeps only back faces), or
  // offsets each polygon by its slope (glPolygonOffset): then a steep back face at a
  // silhouette may end up nearer than its front face, and a map must keep it.
  const bool offset_map = !eye_view && glIsEnabled(GL_POLYGON_OFFSET_FILL) == GL_TRUE;
  const bool pass_culls = glIsEnabled(GL_CULL_FACE) == GL_TRUE;
  const bool cull_solids = !pass_culls && !offset_map;
  // A one-sided plane is its own back face: the light's passes draw it whatever they cull.
  const bool light_view = which == Objects::Casters || which == Objects::Occluders;
  if (cull_solids) glCullFace(GL_BACK);
  if (eye_view) {
    std::vector<std::pair<bool, float>> key(order.size());  // bounds walk every vertex: once
    for (size_t i = 0; i < key.size(); ++i) {
      const SceneObject& o = scene_.objects[i];
      key[i] = {!o.caster, glm::distance(frame.eye, o.worldBounds().center())};
    }
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return key[a] < key[b]; });
  }
  for (const size_t i : order) {
    const SceneObject& object = scene_.objects[i];
    const Light& l = frame.light;
    if (which == Objects::Casters && !object.castsFrom(l.position, l.directional, l.direction)) {
      continue;
    }
    if (which == Objects::Receivers && !object.receiver) continue;
    if (cull != nullptr) {
      const Bounds b = object.worldBounds();
      if (sphereOutsideFrustum(*cull, b.center(), b.radius())) {
        frame.measure.count("culled_objects");
        continue;
      }
    }
    // Every caster is a closed solid wound counter-clockwise from outside (the winding is
    // tested; seams close up to float rounding, so a silhouette pixel may move).
    if (cull_solids) object.caster ? glEnable(GL_CULL_FACE) : glDisable(GL_CULL_FACE);
    const bool unculled_plane = pass_culls && light_view && !object.caster;
    if (unculled_plane) glDisable(GL_CULL_FACE);
    drawObject(program, i);
    if (unculled_plane) glEnable(GL_CULL_FACE);
  }
  if (cull_solids) glDisable(GL_CULL_FACE);
}

void SceneHost::drawObject(const Program& program, size_t index) const {
  const SceneObject& object = scene_.objects.at(index);
  program.set("uModel", object.model);
  program.set("uNormalMatrix", glm::transpose(glm::inverse(object.model)));
  program.set("uColor", object.color);
  program.set("uObject", static_cast<int>(index));
  meshes_[index].draw();
}

void SceneHost::setObjectModel(size_t index, const glm::mat4& model) {
  SceneObject& object = scene_.objects.at(index);
  if (object.model == model) return;
  object.model = model;
  truth_.forgetScene();                // the truth's triangles are in world space
  params_.markDirty(kDirtyShadowMap);  // a moved caster moves its shadow
}

void SceneHost::bake(BakeRequest request) {
  baker_.start(std::move(request), /*wait=*/!bake_in_background_);
}

void SceneHost::drawInset(const Frame& frame, const Texture& depth, float near, float far,
                          bool perspective, bool fullscreen) const {
  const int side = std::max(16, std::min(frame.width, frame.height) / 4);
  frame.bindTarget();
  if (!fullscreen) glViewport(frame.width - side - 8, 8, side, side);
  glDisable(GL_DEPTH_TEST);
  // The lesson samples this texture with a compare; a plain read needs the compare off.
  GLint compare_mode = GL_NONE;
  glBindTexture(GL_TEXTURE_2D, depth.id());
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, &compare_mode);
  depth.setCompare(false);
  depth.bind(0);
  depth_inset_.use();
  depth_inset_.set("uDepth", 0);
  depth_inset_.set("uNear", near);
  depth_inset_.set("uFar", far);
  depth_inset_.set("uPerspective", perspective ? 1 : 0);
  glBindVertexArray(empty_vao_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  countDrawCall();
  depth.setCompare(compare_mode == GL_COMPARE_REF_TO_TEXTURE);
  glEnable(GL_DEPTH_TEST);
  frame.bindTarget();
}

}  // namespace shadows
