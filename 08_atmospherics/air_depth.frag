#version 330 core
// The scene drawn at the low-res air's pixels (each the eye ray of one picture pixel): its depth
// is what the slices there are tested against, and its view depth, in alpha, is what the
// upsample compares with a picture pixel's own (the slices add 0 to alpha).
uniform vec2 uNearFar;  // the camera's near and far planes
out vec4 outDepth;
void main() {
  float z = 2.0 * gl_FragCoord.z - 1.0;
  outDepth = vec4(0.0, 0.0, 0.0,
                  2.0 * uNearFar.x * uNearFar.y / (uNearFar.y + uNearFar.x - z * (uNearFar.y - uNearFar.x)));
}
