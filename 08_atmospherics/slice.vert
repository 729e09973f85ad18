#version 330 core
// Step 4 of the slide: slices facing the eye. One instance per slice, back to front; each a
// quad over its own rectangle (normalized device x0, y0, x1, y1: where the slice's plane
// cuts the lit cone, or the whole screen) at view depth uFar - (i + 0.5) * uStep.
layout(std140) uniform Rects {  // a uniform block: 256 vectors are more than ES 3.0 promises
  vec4 uRects[256];
};
uniform float uFar;
uniform float uStep;
uniform mat4 uProjection;
// Air at 1/k resolution: from the full picture's normalized device coordinates to the low-res
// target's, so that low-res pixel (x, y) is centred on the ray of pixel (k x, k y). 1, 0 at full.
uniform vec2 uNdcScale;
uniform vec2 uNdcOffset;
out vec2 vNdc;
flat out float vDepth;
flat out int vSlice;
void main() {
  vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1);  // a triangle strip of 4
  vec4 rect = uRects[gl_InstanceID];
  vNdc = mix(rect.xy, rect.zw, corner);
  vDepth = uFar - (float(gl_InstanceID) + 0.5) * uStep;
  vSlice = gl_InstanceID;
  vec4 plane = uProjection * vec4(0.0, 0.0, -vDepth, 1.0);
  gl_Position = vec4((vNdc * uNdcScale + uNdcOffset) * plane.w, plane.z, plane.w);
}
