#version 330 core
// Pass 1's store. STORE_DEPTH: nothing written here, the face keeps its hardware depth
// (hyperbolic in the distance along the face's axis). STORE_DISTANCE: the fragment writes its
// true distance to the light over far, linear, so one number means the same on every face
// (and the depth test keeps the nearest by that distance).
in vec3 vWorld;
uniform vec3 uLightPos;
uniform float uCubeFar;
void main() {
#if CUBE_STORE == CUBE_STORE_DISTANCE
  gl_FragDepth = length(vWorld - uLightPos) / uCubeFar;
#endif
}
