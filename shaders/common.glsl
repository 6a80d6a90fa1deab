#version 330 core
// Prepended to every shader of the renderer: the sphere panel's camera and the three-light shading.
// Pixel coordinates run right and down from the frame's top-left corner; gl_FragCoord.xy uses the same
// convention because the vertex shader maps y down to framebuffer row y (read back top row first).

uniform vec2 uViewport;  // frame size in pixels
uniform vec3 uEye;       // camera position (world), sphere of radius 1 at the origin
uniform vec3 uForward;   // viewing direction times the focal length in pixels
uniform vec3 uRight;     // unit vectors spanning the image plane (world)
uniform vec3 uUp;
uniform vec2 uCentre;    // pixel where the viewing direction lands
uniform float uAntialias;
uniform float uUnit;     // pixels per 720 px of the frame's shorter side (render::frameUnit)

vec3 pixelRay(vec2 pixel) {
  return normalize(uForward + uRight * (pixel.x - uCentre.x) - uUp * (pixel.y - uCentre.y));
}

// World normal to screen space (x right, y down, z towards the viewer), where the lights live.
vec3 screenNormal(vec3 n) {
  return vec3(dot(n, uRight), -dot(n, uUp), -dot(n, normalize(uForward)));
}

// Coverage of a pixel whose centre is `inside` pixels inside an edge (negative: outside).
float edgeCoverage(float inside) {
  return uAntialias > 0.5 ? clamp(inside + 0.5, 0.0, 1.0) : step(0.0, inside);
}

// The unit sphere under a pixel: returns the pixel's coverage by its silhouette and sets `hit` to the surface point
// the ray meets (past the limb, where it misses, the ray's point closest to the centre, pushed onto the sphere).
float sphereHit(vec2 pixel, out vec3 hit) {
  vec3 ray = pixelRay(pixel);
  float closest = -dot(ray, uEye);
  float miss2 = dot(uEye, uEye) - closest * closest;
  float pixelSize = closest / length(uForward);
  hit = normalize(uEye + ray * (closest - sqrt(max(1.0 - miss2, 0.0))));
  return edgeCoverage((1.0 - sqrt(max(miss2, 0.0))) / pixelSize);
}

// Coverage of a pixel whose centre is `offAxis` pixels from the axis of a band `halfWidth` pixels wide on each side:
// the overlap of the pixel's span with the band, so a line thinner than a pixel is fainter instead of wider, and a
// frame downscaled from a larger one shows the same line. Equal to edgeCoverage(halfWidth - offAxis) for bands
// at least a pixel wide.
float bandCoverage(float halfWidth, float offAxis) {
  if (uAntialias < 0.5) return step(offAxis, max(halfWidth, 0.5));
  return clamp(min(offAxis + 0.5, halfWidth) - max(offAxis - 0.5, -halfWidth), 0.0, 1.0);
}

// Pixel distance from a capsule's axis segment [0, len] x {0} (len < 0: an endless ribbon, |y|).
float capsuleDistance(vec2 local, float len) {
  return len < 0.0 ? abs(local.y) : length(vec2(max(max(-local.x, local.x - len), 0.0), local.y));
}

// Soft studio lighting in screen space: a warm key light from the upper left, a cool fill from the
// right, a rim from behind, and a Blinn-Phong highlight of the key light.
vec3 lit(vec3 base, vec3 n, float specular) {
  const vec3 key = normalize(vec3(-0.45, -0.55, 0.70));
  const vec3 fill = normalize(vec3(0.75, 0.10, 0.65));
  const vec3 view = vec3(0.0, 0.0, 1.0);
  float diffuse = 0.30 + 0.62 * max(dot(n, key), 0.0) + 0.22 * max(dot(n, fill), 0.0);
  // Powers by products (llvmpipe's pow is a log and an exp per lane): x^3, and x^48 = (x^3)^16.
  float edge = 1.0 - clamp(n.z, 0.0, 1.0);
  float rim = 0.18 * edge * edge * edge;
  float h = max(dot(n, normalize(key + view)), 0.0);
  h = h * h * h;
  h *= h;
  h *= h;
  h *= h;
  h *= h;
  float highlight = specular * h;
  return min(base * diffuse * vec3(1.02, 1.0, 0.97) + vec3(rim + highlight), vec3(1.0));
}
