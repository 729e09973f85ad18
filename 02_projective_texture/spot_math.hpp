// The C++ side of spot.glsl: the very file projector.frag includes, compiled as C++ so the
// tests can check the spotlight falloff the shader applies.
#pragma once

#include <glm/glm.hpp>

namespace shadows::spot {

using glm::cos;
using glm::dot;
using glm::length;
using glm::max;
using glm::smoothstep;
using glm::vec3;

#include "spot.glsl"

}  // namespace shadows::spot
