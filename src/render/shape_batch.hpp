#pragma once
// Anti-aliased 2D shapes in pixel coordinates (y down), collected on the CPU and drawn in one call.
// Every shape carries its own analytic coverage (the fragment shader knows the distance to its edge in
// pixels), so the frame needs no multisampling: see shaders/flat.frag and shaders/lit.frag.

#include <cstddef>
#include <vector>

namespace sl {

struct P2 {
  float x = 0, y = 0;
};
struct Rgba {
  float r = 0, g = 0, b = 0, a = 1;
};

// A 3D point that may be hidden by the unit sphere of the sphere panel (w = 1), or none (w = 0); w = -1 marks one
// of the sphere panel known to be clear of the sphere (drawn lit, as w = 1, without the per-pixel test).
struct Occludable {
  float x = 0, y = 0, z = 0, w = 0;
};

// Shape kinds, mirrored in shaders/flat.frag and shaders/lit.frag (vKind).
enum class ShapeKind { Capsule = 0, Disc = 1, Glyph = 3, Rect = 4 };

struct ShapeVertex {
  float x, y;                         // pixel position
  float localX, localY;               // shape-local coordinates (pixels; texture coordinates for glyphs)
  float kind, size, extra, specular;  // size: half width / radius; extra: capsule length / ball radius (world)
  float r, g, b, a;
  float axisX, axisY;    // screen direction across a tube (for its shading)
  float wx, wy, wz, ww;  // Occludable
  float shaded;          // 1 = lit as a tube or ball, 0 = flat colour
};

// How the sphere of the sphere panel covers an occludable polyline point and the pixels about it (decided by the
// caller, who knows the camera): test per pixel, or known to be clear of it, or known to be wholly hidden by it.
enum class SphereCover { PerPixel = 0, Clear = 1, Hidden = 2 };

struct PolylinePoint {
  P2 at;
  float halfWidth = 1;
  Rgba color;
  Occludable world;
  SphereCover cover = SphereCover::PerPixel;
};

// Drops the points of `points` that lie within `tolerance` pixels of the straight section joining the points kept on
// either side, where the colour and width there are what that section interpolates (within half a level and a
// hundredth of a pixel) and the sphere covers them alike: fewer vertices for the same line (a family's many thin
// paths). The first and last points stay.
void mergeStraightRuns(std::vector<PolylinePoint>& points, float tolerance);

// Which fragment shader draws a shape: flat colour (cheap), font atlas, or lit and occludable. On
// llvmpipe a fragment costs the whole shader, so cheap shapes never run the lighting code.
enum class ShapeProgram { Flat = 0, Glyph = 1, Lit = 2 };

// Consecutive vertices drawn by one program; segments are drawn in order (painter's algorithm).
struct ShapeSegment {
  ShapeProgram program;
  std::size_t first, count;
};

// Every shape is drawn as quads: six vertices a quad, its corners 0 1 2 0 2 3 (two triangles), which the renderer
// turns into four indexed corners (and a polyline's sections into shared ones).
class ShapeBatch {
 public:
  // A segment with round ends; `shaded` lights it as a cylinder.
  void capsule(P2 a, P2 b, float halfWidth, Rgba color, bool shaded = false, float specular = 0, Occludable world = {});
  // A disc; `shaded` lights it as a ball. With `world`, a ball of `worldRadius` about that point, hidden
  // per pixel by the sphere of the sphere panel.
  void disc(P2 centre, float radius, Rgba color, bool shaded = false, float specular = 0, Occludable world = {},
            float worldRadius = 0);
  // Joined strip through the points (mitred), width and colour interpolated; no double blending at
  // joints, so translucent fading paths stay smooth. A section between two points the sphere hides wholly is left
  // out; one between two points clear of it skips the per-pixel occlusion test.
  void polyline(const std::vector<PolylinePoint>& points, bool shaded = false, float specular = 0);
  // The polyline as dashes of `dash` pixels with `gap` pixels between them (measured along it), flat.
  void dashedPolyline(const std::vector<PolylinePoint>& points, float dash, float gap);
  // A hollow circle: a flat stroke of `halfWidth` about `radius`, nothing inside.
  void ring(P2 centre, float radius, float halfWidth, Rgba color);
  void rect(float x0, float y0, float x1, float y1, Rgba color);
  // Everything in `other`, drawn after what is here.
  void append(const ShapeBatch& other);
  void glyph(float x0, float y0, float x1, float y1, float u0, float v0, float u1, float v1, Rgba color);

  const std::vector<ShapeVertex>& vertices() const { return vertices_; }
  const std::vector<ShapeSegment>& segments() const { return segments_; }
  void clear() {
    vertices_.clear();
    segments_.clear();
  }

 private:
  void quad(const ShapeVertex corners[4]);
  void strip(const std::vector<PolylinePoint>& points, std::size_t begin, std::size_t end, bool shaded, float specular);
  std::vector<ShapeVertex> vertices_;
  std::vector<ShapeSegment> segments_;
};

}  // namespace sl
