// Lit shapes (tubes and balls) with analytic anti-aliasing: each shape knows its pixel distance to its
// own edge, so coverage is exact without multisampling. Output is premultiplied alpha. Points of the
// sphere panel (vWorld.w = 1) are hidden per pixel where the unit sphere is in front of them; those known to be
// clear of it (vWorld.w = -1, render/shape_batch.cpp) skip the test.
in vec2 vLocal;
flat in int vKind;
in vec3 vParams;  // size (half width or radius), extra (capsule length, < 0 for ribbons; ball world radius), specular
in vec4 vColor;
in vec2 vAxis;
in vec4 vWorld;

out vec4 fragColor;

// Distance along the ray to this fragment's surface: for a ball (disc with a world radius in
// vParams.y) where the ray meets the ball, else the distance to the point vWorld itself.
float fragmentDistance(vec3 ray) {
  float toPoint = distance(uEye, vWorld.xyz);
  if (vKind != 1 || vParams.y <= 0.0) return toPoint;
  float along = dot(vWorld.xyz - uEye, ray);
  float offAxis2 = max(toPoint * toPoint - along * along, 0.0);
  return along - sqrt(max(vParams.y * vParams.y - offAxis2, 0.0));
}

// 1 where the unit sphere lies in front of this fragment along its pixel's ray.
float hiddenBySphere() {
  vec3 ray = pixelRay(gl_FragCoord.xy);
  float closest = -dot(ray, uEye);
  float miss2 = dot(uEye, uEye) - closest * closest;  // squared distance of the ray from the centre
  float pixel = closest / length(uForward);            // world size of a pixel at the sphere
  float sphereCover = edgeCoverage((1.0 - sqrt(max(miss2, 0.0))) / pixel);
  float nearHit = closest - sqrt(max(1.0 - miss2, 0.0));
  float behind = smoothstep(-pixel, pixel, fragmentDistance(ray) - nearHit);
  return sphereCover * behind;
}

void main() {
  float size = max(vParams.x, 1e-3);
  float cover;
  vec3 n;
  if (vKind == 0) {  // capsule, or ribbon of a polyline (no caps): lit as a cylinder
    cover = bandCoverage(vParams.x, capsuleDistance(vLocal, vParams.y));
    vec2 across = vAxis * clamp(vLocal.y / size, -1.0, 1.0);
    n = vec3(across, sqrt(max(1.0 - dot(across, across), 0.0)));
  } else {  // disc, lit as a ball
    cover = edgeCoverage(vParams.x - length(vLocal));
    vec2 q = vLocal / size;
    n = vec3(q, sqrt(max(1.0 - dot(q, q), 0.0)));
  }
  if (cover <= 0.0) discard;
  float alpha = vColor.a * cover;
  if (vWorld.w > 0.5) alpha *= 1.0 - hiddenBySphere();
  fragColor = vec4(lit(vColor.rgb, n, vParams.z) * alpha, alpha);
}
