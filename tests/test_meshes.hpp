// Triangle soups the truth tests build their scenes from.
#pragma once

#include <cmath>
#include <glm/glm.hpp>
#include <vector>

namespace shadows::testing {

struct Mesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::uvec3> triangles;
};

// UV sphere with vertices on the sphere (inscribed): its shadow is a hair smaller than the
// analytic one, far below a pixel at this tessellation.
inline void addSphere(Mesh& m, glm::vec3 c, float r, int segments, int rings) {
  const auto base = static_cast<unsigned>(m.positions.size());
  for (int j = 0; j <= rings; ++j) {
    const double theta = 3.14159265358979323846 * j / rings;
    for (int i = 0; i <= segments; ++i) {
      const double phi = 2.0 * 3.14159265358979323846 * i / segments;
      m.positions.push_back(c + r * glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                                              std::sin(theta) * std::sin(phi)));
    }
  }
  const auto row = static_cast<unsigned>(segments + 1);
  for (unsigned j = 0; j < static_cast<unsigned>(rings); ++j) {
    for (unsigned i = 0; i < static_cast<unsigned>(segments); ++i) {
      const unsigned a = base + j * row + i, b = a + 1, d = a + row, e = d + 1;
      // Skip the zero-area triangles at the poles.
      if (j != 0) m.triangles.emplace_back(a, b, d);
      if (j + 1 != static_cast<unsigned>(rings)) m.triangles.emplace_back(b, e, d);
    }
  }
}

}  // namespace shadows::testing
