// Flat-coloured shapes with analytic anti-aliasing (see lit.frag): capsules, discs, rectangles.
in vec2 vLocal;
flat in int vKind;
in vec3 vParams;  // size (half width or radius), extra (capsule length, < 0 for ribbons)
in vec4 vColor;

out vec4 fragColor;

void main() {
  float cover = 1.0;
  if (vKind == 0) {
    cover = bandCoverage(vParams.x, capsuleDistance(vLocal, vParams.y));
  } else if (vKind == 1) {
    cover = edgeCoverage(vParams.x - length(vLocal));
  }
  float alpha = vColor.a * cover;
  fragColor = vec4(vColor.rgb * alpha, alpha);
}
