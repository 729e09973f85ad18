// User clip plane 0 in a vertex shader: gl_ClipDistance[0] where the GL has it (enabled by
// PassState::clip_plane). OpenGL ES 3.0 and WebGL have no clip distances: there the distance
// travels as a varying and clip_plane_in.glsl discards the fragments where it is negative,
// the same pixels the clipper would remove.
#if HAS_CLIP_DISTANCE
out float gl_ClipDistance[1];
void setClipDistance(float distance) {
  gl_ClipDistance[0] = distance;
}
#else
out float vClipDistance;
void setClipDistance(float distance) {
  vClipDistance = distance;
}
#endif
