#version 330 core
// Pass 1 in one draw per caster (cube.passes=layered): each triangle is sent to every face
// this frame renders, gl_Layer picking the cube face, and only to faces whose frustum it can
// reach (all three corners outside one of the face's planes: skipped, as the six passes cull
// whole casters).
layout(triangles) in;
layout(triangle_strip, max_vertices = 18) out;
in vec3 vWorldIn[];
out vec3 vWorld;
uniform mat4 uFaceViewProjection[6];
uniform int uFaceMask;  // bit i: face i is rendered this frame

bool outside(vec4 a, vec4 b, vec4 c) {
  for (int axis = 0; axis < 3; ++axis) {
    if (a[axis] > a.w && b[axis] > b.w && c[axis] > c.w) return true;
    if (a[axis] < -a.w && b[axis] < -b.w && c[axis] < -c.w) return true;
  }
  return false;
}

void main() {
  for (int face = 0; face < 6; ++face) {
    if (((uFaceMask >> face) & 1) == 0) continue;
    vec4 clip[3];
    for (int k = 0; k < 3; ++k) clip[k] = uFaceViewProjection[face] * vec4(vWorldIn[k], 1.0);
    if (outside(clip[0], clip[1], clip[2])) continue;
    for (int k = 0; k < 3; ++k) {
      gl_Layer = face;
      vWorld = vWorldIn[k];
      gl_Position = clip[k];
      EmitVertex();
    }
    EndPrimitive();
  }
}
