// The C++ side of common/shaders/depth_digits.glsl: the very file the shaders include,
// compiled as C++ so tests can check the shaders' arithmetic.
#pragma once

#include <glm/glm.hpp>

namespace shadows::digits {

using glm::clamp;
using glm::floor;
using glm::fract;
using glm::min;
using glm::roundEven;
using glm::vec2;

#include "shaders/depth_digits.glsl"

}  // namespace shadows::digits
