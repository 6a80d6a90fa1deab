// The configuration sphere as a ray-traced impostor on a panel-sized quad: exact silhouette coverage,
// per-pixel normals, and for the coloured look the (phi, t) chart grid drawn analytically (lines of constant width
// in frame units).
// SPHERE_LOOK (defined by the file before this one, sphere_opaque.glsl, sphere_glass.glsl or sphere_colored.glsl;
// one program per look, because llvmpipe runs both sides of a branch on a uniform and the unused looks cost as
// much as the used one): 0, the opaque cream ball, whose grid and poles sphere_grid.frag draws over it as lines, so
// that the ball, the same from every direction (the lights turn with the camera), is drawn once and cached; 1, a
// faint glassy reference sphere (also the same from every direction); 2, the colours of a scalar field (uField: a
// texture over (t, phi), render/color_map.hpp) under a fainter grid, the pole caps drawn here too.
// The ray is cast in the camera's own frame (uEye on +z, uRight = x, uUp = y: the same numbers for every direction,
// so a cached ball does not depend on the frame that drew it) and the hit point turned into the world by
// uWorldRight, uWorldUp, uWorldBack (the camera's basis; back = from the centre towards the eye).
uniform vec3 uSphereColor;
uniform vec3 uGridColor;
uniform vec3 uPoleColor;
uniform sampler2D uField;
uniform vec3 uWorldRight;
uniform vec3 uWorldUp;
uniform vec3 uWorldBack;
uniform float uGridStep;  // radians between grid lines, in phi and in t (render/sphere_grid.hpp)
out vec4 fragColor;

const float PI = 3.14159265358979;

// Coverage of a grid line where f = 0, from the screen gradient of f (pixels across = |f| / |grad f|).
float gridLine(float f, vec2 gradient, float halfWidth) {
  return bandCoverage(halfWidth * uUnit, abs(f) / max(length(gradient), 1e-6));
}

float gridCoverage(vec3 p) {
  // Parallels phi = k * 15deg: f = z - sin(phi_k).
  float k = round(asin(clamp(p.z, -1.0, 1.0)) / uGridStep);
  float parallel = gridLine(p.z - sin(k * uGridStep), vec2(dFdx(p.z), dFdy(p.z)), k == 0.0 ? 0.9 : 0.55);
  // Meridians t = j * 15deg: f = distance from the meridian's plane; faded where they crowd at the poles.
  float j = round(atan(p.y, p.x) / uGridStep);
  vec2 across = vec2(-sin(j * uGridStep), cos(j * uGridStep));
  vec2 gradient = vec2(dot(dFdx(p.xy), across), dot(dFdy(p.xy), across));
  float meridian = gridLine(dot(p.xy, across), gradient, j == 0.0 ? 0.9 : 0.55);
  meridian *= 1.0 - smoothstep(0.92, 0.985, abs(p.z));
  return max(parallel, meridian);
}

void main() {
  vec3 hit;
  float cover = sphereHit(gl_FragCoord.xy, hit);  // camera frame
  if (cover <= 0.0) discard;
  vec3 n = vec3(hit.x, -hit.y, hit.z);  // screenNormal(hit) in the camera frame
#if SPHERE_LOOK == 0
  fragColor = vec4(lit(uSphereColor, n, 0.18) * cover, cover);
#elif SPHERE_LOOK == 1
  float glass = 0.07 + 0.25 * pow(1.0 - clamp(n.z, 0.0, 1.0), 2.5);
  fragColor = vec4(uGridColor * glass * cover, glass * cover);
#else
  vec3 p = hit.x * uWorldRight + hit.y * uWorldUp + hit.z * uWorldBack;  // world
  vec2 chart = vec2(atan(p.y, p.x), asin(clamp(p.z, -1.0, 1.0)));          // (t, phi)
  vec3 field = texture(uField, vec2(chart.x / (2.0 * PI) + 0.5, chart.y / PI + 0.5)).rgb;
  vec3 base = mix(field, uGridColor, 0.3 * gridCoverage(p));
  // The chart's poles phi = +-90deg (x1 = x2 = 0), where t is undefined: small dark caps.
  float poleDistance = length(p.xy) / max(length(vec2(length(dFdx(p.xy)), length(dFdy(p.xy)))), 1e-6);
  float poleRadius = 0.035 / max(length(vec2(length(dFdx(p.xy)), length(dFdy(p.xy)))), 1e-6);
  base = mix(base, uPoleColor, edgeCoverage(min(poleRadius, 7.0 * uUnit) - poleDistance));
  // A colour-mapped surface keeps its colours on the colour bar: ambient-heavy light that darkens it by at most 7%
  // away from the key light, no coloured highlight or rim that would bleach or tint it.
  const vec3 key = normalize(vec3(-0.45, -0.55, 0.70));
  fragColor = vec4(base * (0.93 + 0.07 * max(dot(n, key), 0.0)) * cover, cover);
#endif
}
