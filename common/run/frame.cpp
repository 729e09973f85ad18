// What a lesson draws with: Frame's helpers (the runner's half is SceneHost, scene_host.cpp).
#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>

#include "lesson/lesson.hpp"

namespace shadows {

// ---------------------------------------------------------------- Frame helpers

std::vector<std::string> Frame::viewDefines() const {
  std::vector<std::string> views = params.at("view").choices;
  // Views the runner renders for itself (air, texels) are not offered as choices.
  const std::string name = shown.str();
  if (std::find(views.begin(), views.end(), name) == views.end()) views.push_back(name);
  return choiceDefines("view", views, name);
}

void Frame::bindTarget() const {
  glBindFramebuffer(GL_FRAMEBUFFER, target);
  glViewport(0, 0, width, height);
}

void Frame::clearTarget(glm::vec3 color) const {
  bindTarget();
  glClearColor(color.r, color.g, color.b, 1.0f);
  glClearStencil(0);
  glStencilMask(0xFF);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

void Frame::drawObjects(const Program& program, Objects which, const glm::mat4* cull) const {
  runner.drawObjects(*this, program, which, cull);
}

void Frame::setLightingUniforms(const Program& program, float dimming) const {
  program.set("uLightPos", light.position);
  program.set("uLightDir", light.direction);
  program.set("uLightDirectional", light.directional ? 1 : 0);
  program.set("uEye", eye);
  program.set("uDimming", dimming);
}

void Frame::drawDepthInset(const Texture& depth, float near, float far, bool perspective,
                           bool fullscreen) const {
  runner.drawInset(*this, depth, near, far, perspective, fullscreen);
}

void Frame::drawObject(const Program& program, size_t index) const {
  program.use();
  runner.drawObject(program, index);
}

void Frame::drawImageInset(const Texture& image, bool fullscreen) const {
  runner.drawImageInset(*this, image, fullscreen);
}

void Frame::placeMoved(size_t moving, glm::vec3 offset) const {
  const glm::mat4 moved = glm::translate(glm::mat4(1.0f), offset);
  for (size_t k = 0; k < scene.objects.size(); ++k) {
    runner.setObjectModel(k, (k == moving ? moved : glm::mat4(1.0f)) * runner.presetModel(k));
  }
}

void Frame::drawFullscreen(const Program& program, bool inset) const {
  runner.drawFullscreen(*this, program, inset);
}

}  // namespace shadows
