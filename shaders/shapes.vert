// Pixel-space shapes (see src/render/shape_batch.hpp); also carries the full-panel quad of the sphere.
layout(location = 0) in vec2 aPosition;
layout(location = 1) in vec2 aLocal;
layout(location = 2) in vec4 aParams;  // kind, size, extra, specular
layout(location = 3) in vec4 aColor;
layout(location = 4) in vec2 aAxis;
layout(location = 5) in vec4 aWorld;

out vec2 vLocal;
flat out int vKind;
out vec3 vParams;
out vec4 vColor;
out vec2 vAxis;
out vec4 vWorld;

void main() {
  vLocal = aLocal;
  vKind = int(aParams.x + 0.5);
  vParams = aParams.yzw;
  vColor = aColor;
  vAxis = aAxis;
  vWorld = aWorld;
  gl_Position = vec4(2.0 * aPosition / uViewport - 1.0, 0.0, 1.0);
}
