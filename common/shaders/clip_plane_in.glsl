// The fragment side of clip_plane_out.glsl: nothing where the GL clips; on OpenGL ES the
// fragments on the negative side of the plane are discarded.
#if !HAS_CLIP_DISTANCE
in float vClipDistance;
#endif
void clipFragment() {
#if !HAS_CLIP_DISTANCE
  if (vClipDistance < 0.0) discard;
#endif
}
