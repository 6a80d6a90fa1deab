// The opaque sphere's chart grid and pole caps over its cached ball (render/gl/renderer.cpp,
// render/sphere_grid.hpp): ribbons along the projected parallels and meridians (kind 0, vParams.x their half width)
// and squares about the poles (kind 1) holding the pole caps. vColor: the line's colour, and in alpha how much of it
// covers the ball (0.75 for the grid, faded where the meridians crowd at the poles; 1 for the caps). Camera uniforms
// as sphere.frag's (the camera's own frame, uWorld* its basis in the world).
// GRID_PART (defined by the file before this one: sphere_grid_lines.glsl or sphere_grid_poles.glsl) selects the
// ribbons (0) or the caps (1): one program each, because llvmpipe shades both sides of a branch on vKind.
// The ribbons tint the lit ball already in the frame instead of lighting a line colour of their own: the renderer
// blends them by multiplication (the frame's colour times this one), and the ball's pixel is the cream colour times
// its light plus the rim and highlight, so multiplying by mix(1, grid / cream, a) gives the lit line colour's share
// a of the light with no ray or light per pixel (the rim and highlight dimmed under a line as the colour is). A ray
// and three lights for every pixel of about 1,900 thin quads was a third of a turning frame (docs/rendering.md).
// The outline cuts them by the circle the ball's silhouette is (radius uOutline pixels about uCentre), a pixel in.
in vec2 vLocal;
flat in int vKind;
in vec3 vParams;
in vec4 vColor;

uniform vec3 uWorldRight;
uniform vec3 uWorldUp;
uniform vec3 uWorldBack;
uniform vec3 uSphereColor;
uniform float uOutline;
out vec4 fragColor;

// A chart pole's cap (phi = +-90deg, x1 = x2 = 0, where t is undefined): a dark cap measured on the surface, so that
// it is foreshortened towards the limb.
float poleCap(vec3 hit) {
  vec3 p = hit.x * uWorldRight + hit.y * uWorldUp + hit.z * uWorldBack;
  float across = max(length(vec2(length(dFdx(p.xy)), length(dFdy(p.xy)))), 1e-6);
  return edgeCoverage(min(0.035 / across, 7.0 * uUnit) - length(p.xy) / across);
}

void main() {
#if GRID_PART == 0
  // Only where the ball covers the whole pixel (a pixel inside its anti-aliased edge): at the edge the frame holds
  // the background too, which a tint would darken, and a transparent frame would not.
  float cover = edgeCoverage(uOutline - 1.0 - length(gl_FragCoord.xy - uCentre));
  float alpha = vColor.a * bandCoverage(vParams.x, abs(vLocal.y)) * cover;
  if (alpha <= 0.0) discard;
  fragColor = vec4(mix(vec3(1.0), min(vColor.rgb / uSphereColor, vec3(1.0)), alpha), 1.0);
#else
  vec3 hit;
  float cover = sphereHit(gl_FragCoord.xy, hit);
  float alpha = vColor.a * poleCap(hit) * cover;
  if (alpha <= 0.0) discard;
  fragColor = vec4(lit(vColor.rgb, vec3(hit.x, -hit.y, hit.z), 0.18) * alpha, alpha);
#endif
}
