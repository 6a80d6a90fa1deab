// The renderer: the CPU part (FrameComposer) turns a FrameState into a DrawList; this GL part draws it with
// flat, glyph and lit shapes and the sphere impostor (a program per look). All anti-aliasing is analytic, so the
// frame is a plain RGBA8 framebuffer: no MSAA resolve, no depth buffer. With a fixed camera the sphere is
// drawn once into a cached layer and copied into each frame (the same bytes as drawing it, at the cost of a
// copy). With a turning one, what does not depend on the camera's direction is cached as well: the plain opaque
// ball (the lights turn with the camera) and the glass ball are drawn once per panel and copied, and per frame only
// the opaque sphere's grid and poles are drawn over it, as lines tinting the lit ball (render/sphere_grid.hpp,
// shaders/sphere_grid.frag).

#include "render/renderer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <utility>

#include "render/color_map.hpp"
#include "render/draw_list.hpp"
#include "render/frame_composer.hpp"
#include "render/gl/gl.hpp"
#include "render/gl/gl_context.hpp"
#include "render/gl/shader_program.hpp"
#include "render/palette.hpp"
#include "render/sphere_grid.hpp"

namespace sl {
namespace {


// Each program: common.glsl (version line, shared functions) before its own stage files.
std::vector<std::string> stage(const char* file) { return {"common.glsl", file}; }
// The sphere: one program per look (the file before sphere.frag defines SPHERE_LOOK).
std::vector<std::string> sphereStage(const char* look) { return {"common.glsl", look, "sphere.frag"}; }
// The opaque sphere's grid: one program for its lines, one for its pole caps (the file before sphere_grid.frag).
std::vector<std::string> gridStage(const char* part) { return {"common.glsl", part, "sphere_grid.frag"}; }
// How every shape meets the frame: premultiplied colours over what is there.
void blendOver() { glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA); }

}  // namespace

struct Renderer::Impl {
  FrameComposer composer;
  ImageSize size;
  GlContext context;
  ShaderProgram flat, glyph, lit, sphereOpaque, sphereGlass, sphereColored, gridRibbons, poleCaps;
  GLuint vertexArray = 0, vertexBuffer = 0, indexBuffer = 0, glyphTexture = 0, fieldTexture = 0;
  mutable std::size_t vertexCapacity = 0, indexCapacity = 0;  // bytes of the buffers' storage
  mutable std::vector<ShapeVertex> corners;        // upload(): the batch's quad corners, each once
  mutable std::vector<std::uint32_t> cornerIndices;  // and its triangles' corners, one per vertex of the batch
  std::unique_ptr<GlLayer> sphereLayer;
  // The plain balls (opaque without grid, glass) of the panels, each drawn once: the same for every direction.
  struct BallLayer {
    SphereLook look;
    int x0, y0, x1, y1;  // the quad drawn, pixels
    double distance, focal;
    P2 centre;
    bool antialias;
    ColorRGB background;
    std::unique_ptr<GlLayer> layer;
  };
  std::vector<BallLayer> ballLayers;
  std::optional<SphereGridLines> gridLines;  // the opaque sphere's grid on the unit sphere, for the last step
  ViewSpace cachedSpace = ViewSpace::Sphere;
  ColorRGB cachedBackground;  // the background the cached sphere layer was cleared to
  Vec3 cachedEye;             // the camera the cached sphere layer was drawn by
  Vec3 lastEye{std::nan(""), 0, 0};  // the camera of this renderer's last frame (none yet: equal to no eye)
  const SphereDecoration* uploadedDecoration = nullptr;  // the field in fieldTexture
  const SphereDecoration* cachedDecoration = nullptr;    // the decoration the cached sphere layer shows
  bool frameBlank = false;  // the frame being drawn has no background yet (fillBackground, copyLayer)

  Impl(const ViewSettings& view, ImageSize frameSize, const std::string& shaderFolder)
      : composer(view, frameSize),
        size(frameSize),
        context(size.width, size.height),
        flat(stage("shapes.vert"), stage("flat.frag"), shaderFolder),
        glyph(stage("shapes.vert"), stage("glyph.frag"), shaderFolder),
        lit(stage("shapes.vert"), stage("lit.frag"), shaderFolder),
        sphereOpaque(stage("shapes.vert"), sphereStage("sphere_opaque.glsl"), shaderFolder),
        sphereGlass(stage("shapes.vert"), sphereStage("sphere_glass.glsl"), shaderFolder),
        sphereColored(stage("shapes.vert"), sphereStage("sphere_colored.glsl"), shaderFolder),
        gridRibbons(stage("shapes.vert"), gridStage("sphere_grid_lines.glsl"), shaderFolder),
        poleCaps(stage("shapes.vert"), gridStage("sphere_grid_poles.glsl"), shaderFolder) {
    createVertexArray();
    createGlyphTexture();
  }

  ~Impl() {
    glDeleteTextures(1, &glyphTexture);
    if (fieldTexture) glDeleteTextures(1, &fieldTexture);
    glDeleteBuffers(1, &vertexBuffer);
    glDeleteBuffers(1, &indexBuffer);
    glDeleteVertexArrays(1, &vertexArray);
  }

  void createVertexArray() {
    glGenVertexArrays(1, &vertexArray);
    glGenBuffers(1, &vertexBuffer);
    glGenBuffers(1, &indexBuffer);
    glBindVertexArray(vertexArray);
    glBindBuffer(GL_ARRAY_BUFFER, vertexBuffer);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indexBuffer);  // part of the vertex array's state
    const GLsizei stride = sizeof(ShapeVertex);
    auto attribute = [&](GLuint index, GLint count, std::size_t offset) {
      glEnableVertexAttribArray(index);
      glVertexAttribPointer(index, count, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offset));
    };
    attribute(0, 2, offsetof(ShapeVertex, x));
    attribute(1, 2, offsetof(ShapeVertex, localX));
    attribute(2, 4, offsetof(ShapeVertex, kind));
    attribute(3, 4, offsetof(ShapeVertex, r));
    attribute(4, 2, offsetof(ShapeVertex, axisX));
    attribute(5, 4, offsetof(ShapeVertex, wx));
  }

  void createGlyphTexture() {
    glGenTextures(1, &glyphTexture);
    glBindTexture(GL_TEXTURE_2D, glyphTexture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, composer.font().atlasSize(), composer.font().atlasSize(), 0, GL_RED,
                 GL_UNSIGNED_BYTE, composer.font().bitmap().data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }

  // The colours of a sphere field as a texture over (t, phi): repeated in t (periodic), clamped in phi, filtered
  // linearly between the cell-centre samples (frame_state.hpp's SphereField).
  void uploadField(const SphereField& field) {
    if (!fieldTexture) glGenTextures(1, &fieldTexture);
    glBindTexture(GL_TEXTURE_2D, fieldTexture);
    const std::vector<std::uint8_t> texels = fieldTexels(field);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, field.tCount, field.phiCount, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 texels.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }

  // Uniforms every program shares (shaders/common.glsl); without a camera they are inert.
  void setCommonUniforms(const ShaderProgram& program, const SphereCamera* camera, bool antialias) const {
    program.use();
    glUniform2f(program.uniform("uViewport"), float(size.width), float(size.height));
    glUniform1f(program.uniform("uAntialias"), antialias ? 1.0f : 0.0f);
    glUniform1f(program.uniform("uUnit"), frameUnit(size));
    if (!camera) return;
    const auto set3 = [&](const char* name, const Vec3& v, double scale) {
      glUniform3f(program.uniform(name), float(v.x * scale), float(v.y * scale), float(v.z * scale));
    };
    set3("uEye", camera->eye(), 1);
    set3("uForward", camera->forward(), camera->focal());
    set3("uRight", camera->right(), 1);
    set3("uUp", camera->up(), 1);
    glUniform2f(program.uniform("uCentre"), camera->centre().x, camera->centre().y);
  }

  // The batch's triangles as indexed quads: each quad's four corners once, and a quad that starts on the edge the
  // one before ended on (a polyline's sections) reuses those two corners. The same triangles, corners in the same
  // order (0 1 2, 0 2 3); a third of the vertices to copy and shade for a polyline, two thirds for the rest.
  void upload(const ShapeBatch& shapes) const {
    const auto& list = shapes.vertices();  // six a quad: corners 0 1 2 0 2 3 (ShapeBatch::quad)
    corners.clear();
    cornerIndices.resize(list.size());
    auto same = [](const ShapeVertex& a, const ShapeVertex& b) { return std::memcmp(&a, &b, sizeof a) == 0; };
    auto add = [&](const ShapeVertex& corner) {
      corners.push_back(corner);
      return std::uint32_t(corners.size() - 1);
    };
    for (std::size_t q = 0; q + 6 <= list.size(); q += 6) {
      const ShapeVertex* quad = &list[q];
      std::uint32_t c[4];
      const bool joined = q > 0 && same(quad[0], corners[cornerIndices[q - 5]]) &&
                          same(quad[5], corners[cornerIndices[q - 4]]);  // the last quad's corners 1 and 2
      if (joined) c[0] = cornerIndices[q - 5], c[3] = cornerIndices[q - 4];
      if (!joined) c[0] = add(quad[0]);
      c[1] = add(quad[1]);
      c[2] = add(quad[2]);
      if (!joined) c[3] = add(quad[5]);
      const std::uint32_t order[6] = {c[0], c[1], c[2], c[0], c[2], c[3]};
      std::copy(order, order + 6, cornerIndices.begin() + std::ptrdiff_t(q));
    }
    glBindVertexArray(vertexArray);
    glBindBuffer(GL_ARRAY_BUFFER, vertexBuffer);
    // The buffers only grow: storage allocated afresh for every batch cost page faults worth a tenth of a fan frame.
    const std::size_t bytes = corners.size() * sizeof(ShapeVertex), indexBytes = cornerIndices.size() * 4;
    if (bytes > vertexCapacity) {
      vertexCapacity = std::max(bytes, vertexCapacity + vertexCapacity / 2);
      glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertexCapacity), nullptr, GL_STREAM_DRAW);
    }
    glBufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(bytes), corners.data());
    if (indexBytes > indexCapacity) {
      indexCapacity = std::max(indexBytes, indexCapacity + indexCapacity / 2);
      glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indexCapacity), nullptr, GL_STREAM_DRAW);
    }
    glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, 0, GLsizeiptr(indexBytes), cornerIndices.data());
  }

  // Vertices [first, first + count) of the batch uploaded last, as triangles.
  static void drawTriangles(std::size_t first, std::size_t count) {
    glDrawElements(GL_TRIANGLES, GLsizei(count), GL_UNSIGNED_INT, reinterpret_cast<const void*>(first * 4));
  }

  void drawShapes(const DrawList& list, const ShapeBatch& shapes, const SphereCamera* camera) {
    if (shapes.vertices().empty()) return;
    upload(shapes);
    for (const ShaderProgram* program : {&flat, &glyph, &lit}) setCommonUniforms(*program, camera, list.antialias);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, glyphTexture);
    glUniform1i(glyph.uniform("uGlyphs"), 0);
    for (const ShapeSegment& segment : shapes.segments()) {
      const ShaderProgram& program = segment.program == ShapeProgram::Flat    ? flat
                                     : segment.program == ShapeProgram::Glyph ? glyph
                                                                              : lit;
      program.use();
      drawTriangles(segment.first, segment.count);
    }
  }

  // The sphere programs cast rays in the camera's own frame (sphere.frag): the camera's distance, focal length and
  // centre with a fixed basis, and its world basis to turn hit points into the world.
  void setSphereUniforms(const ShaderProgram& program, const DrawList& list, const SphereImpostor& view) const {
    setCommonUniforms(program, nullptr, list.antialias);
    const SphereCamera& camera = view.camera;
    const auto set3 = [&](const char* name, const Vec3& v, double scale) {
      glUniform3f(program.uniform(name), float(v.x * scale), float(v.y * scale), float(v.z * scale));
    };
    set3("uEye", {0, 0, camera.distance()}, 1);
    set3("uForward", {0, 0, -1}, camera.focal());
    set3("uRight", {1, 0, 0}, 1);
    set3("uUp", {0, 1, 0}, 1);
    glUniform2f(program.uniform("uCentre"), camera.centre().x, camera.centre().y);
    set3("uWorldRight", camera.right(), 1);
    set3("uWorldUp", camera.up(), 1);
    set3("uWorldBack", camera.forward(), -1);
    glUniform1f(program.uniform("uGridStep"), float(gridStep(camera)));
    const auto color = [&](const char* name, Rgba c) { glUniform3f(program.uniform(name), c.r, c.g, c.b); };
    color("uSphereColor", palette::sphereCream);
    color("uGridColor", view.look == SphereLook::Opaque ? palette::sphereGrid : palette::glass);
    color("uPoleColor", palette::poleMark);
  }

  void drawQuad(int x0, int y0, int x1, int y1) {
    ShapeBatch quad;
    quad.rect(float(x0), float(y0), float(x1), float(y1), {});
    upload(quad);
    drawTriangles(0, quad.vertices().size());
  }

  // The plain ball of a look (opaque without grid, or glass) for this panel and camera distance: drawn once on the
  // background into a layer of its own, then copied.
  const GlLayer& ballLayer(const DrawList& list, const SphereImpostor& view, int x0, int y0, int x1, int y1) {
    const SphereCamera& camera = view.camera;
    const P2 centre = camera.centre();
    const ColorRGB& bg = list.background;
    for (const BallLayer& cached : ballLayers)
      if (cached.look == view.look && cached.x0 == x0 && cached.y0 == y0 && cached.x1 == x1 && cached.y1 == y1 &&
          cached.distance == camera.distance() && cached.focal == camera.focal() && cached.centre.x == centre.x &&
          cached.centre.y == centre.y && cached.antialias == list.antialias && cached.background == bg)
        return *cached.layer;
    if (ballLayers.size() >= 4) ballLayers.clear();  // more sphere panels than any layout has: start over
    GLint previous = 0;
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous);
    auto layer = std::make_unique<GlLayer>(size.width, size.height);
    layer->bind();
    clearToBackground(list);
    const ShaderProgram& program = view.look == SphereLook::Glass ? sphereGlass : sphereOpaque;
    setSphereUniforms(program, list, view);
    drawQuad(x0, y0, x1, y1);
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previous));
    ballLayers.push_back({view.look, x0, y0, x1, y1, camera.distance(), camera.focal(), centre, list.antialias, bg,
                          std::move(layer)});
    return *ballLayers.back().layer;
  }

  void drawSphere(const DrawList& list, const SphereImpostor& view) {
    // The camera looks at the sphere's centre, so its outline is a circle of radius f / sqrt(D^2 - 1)
    // about the panel centre: a quad just around it saves the shader a quarter of the panel's pixels.
    const SphereCamera& camera = view.camera;
    const double outline = sphereOutlinePixels(camera);
    const float half = float(outline) + 2.0f;
    const P2 centre = camera.centre();
    const int x0 = int(std::floor(centre.x - half)), y0 = int(std::floor(centre.y - half));
    const int x1 = int(std::ceil(centre.x + half)), y1 = int(std::ceil(centre.y + half));
    if (view.look == SphereLook::Colored) {
      setSphereUniforms(sphereColored, list, view);
      if (list.sphereDecoration && list.sphereDecoration->field) {
        if (uploadedDecoration != list.sphereDecoration.get()) {
          uploadField(*list.sphereDecoration->field);
          uploadedDecoration = list.sphereDecoration.get();
        }
        glActiveTexture(GL_TEXTURE1);
        glBindTexture(GL_TEXTURE_2D, fieldTexture);
        glUniform1i(sphereColored.uniform("uField"), 1);
        glActiveTexture(GL_TEXTURE0);
      }
      fillBackground(list);
      return drawQuad(x0, y0, x1, y1);
    }
    copyLayer(ballLayer(list, view, x0, y0, x1, y1), PixelRect{float(x0), float(y0), float(x1 - x0), float(y1 - y0)});
    if (view.look != SphereLook::Opaque) return;
    const double step = gridStep(camera), piece = sphereGridPiece(outline);
    if (!gridLines || gridLines->step() != step || gridLines->piece() != piece) gridLines.emplace(step, piece);
    ShapeBatch grid;
    const std::size_t ribbons = gridLines->draw(grid, camera, frameUnit(size)), caps = grid.vertices().size() - ribbons;
    if (grid.vertices().empty()) return;
    upload(grid);
    if (ribbons > 0) {
      setSphereUniforms(gridRibbons, list, view);
      glUniform1f(gridRibbons.uniform("uOutline"), float(outline));
      glBlendFunc(GL_DST_COLOR, GL_ZERO);  // the ribbons tint the lit ball (shaders/sphere_grid.frag)
      drawTriangles(0, ribbons);
      blendOver();
    }
    if (caps > 0) {
      setSphereUniforms(poleCaps, list, view);
      drawTriangles(ribbons, caps);
    }
  }

  double gridStep(const SphereCamera& camera) const {
    return sphereGridStep(sphereOutlinePixels(camera), frameUnit(size));
  }

  // The sphere of a camera at rest does not change between frames: draw it once into `sphereLayer`
  // (on the background colour, as in the frame) and copy that rectangle into every frame. A camera that moved
  // since this renderer's last frame draws straight into the frame: a layer would be cleared, drawn and copied
  // for one use (a whole-frame fill and a panel's copy more per turning frame, same pixels).
  void drawSphereCached(const DrawList& list, const SphereImpostor& view, const PixelRect& rect) {
    if (!list.sphereIsStatic) return drawSphere(list, view);
    const Vec3 eye = view.camera.eye();
    const bool atRest = eye == lastEye;
    lastEye = eye;
    if (!sphereLayer || eye != cachedEye || cachedSpace != list.viewSpace ||
        cachedDecoration != list.sphereDecoration.get() || cachedBackground != list.background) {
      if (!atRest) return drawSphere(list, view);
      if (!sphereLayer) sphereLayer = std::make_unique<GlLayer>(size.width, size.height);
      const bool frameWaits = std::exchange(frameBlank, false);  // the layer gets its background; the frame waits
      sphereLayer->bind();
      clearToBackground(list);
      drawSphere(list, view);
      cachedSpace = list.viewSpace;
      cachedDecoration = list.sphereDecoration.get();
      cachedBackground = list.background;
      cachedEye = eye;
      context.bindFramebuffer();
      frameBlank = frameWaits;
    }
    copyLayer(*sphereLayer, rect);
  }

  // A layer's rectangle (within the scissor) into the bound framebuffer. A layer is the background outside what
  // it shows there, so into a frame that has no background yet it goes whole instead of the clear: one copy of
  // the frame where the clear filled it and the copy overwrote the rectangle again (the same bytes).
  void copyLayer(const GlLayer& layer, const PixelRect& rect) {
    GLint target = 0;
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &target);
    if (!std::exchange(frameBlank, false)) return layer.copyTo(GLuint(target), rect);
    glDisable(GL_SCISSOR_TEST);
    layer.copyTo(GLuint(target), PixelRect{0, 0, float(size.width), float(size.height)});
    glEnable(GL_SCISSOR_TEST);
  }

  void drawPanel(const DrawList& list, const PanelDrawing& panel) {
    const PixelRect& rect = panel.rect;
    glScissor(GLint(rect.x), GLint(rect.y), GLsizei(rect.width), GLsizei(rect.height));
    if (panel.sphere) drawSphereCached(list, *panel.sphere, rect);
    if (!panel.shapes.vertices().empty()) fillBackground(list);
    drawShapes(list, panel.shapes, panel.sphere ? &panel.sphere->camera : nullptr);
  }

  void clearToBackground(const DrawList& list) const {
    glDisable(GL_SCISSOR_TEST);
    glClearColor(list.background.r, list.background.g, list.background.b, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
  }

  // The frame's background, unless something already gave it (copyLayer).
  void fillBackground(const DrawList& list) {
    if (std::exchange(frameBlank, false)) clearToBackground(list);
  }

  void draw(const DrawList& list, Image& image) {
    context.bindFramebuffer();
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    blendOver();
    frameBlank = true;
    for (const PanelDrawing& panel : list.panels) drawPanel(list, panel);
    fillBackground(list);
    image.width = size.width;
    image.height = size.height;
    context.readRgb(image.rgb);
  }
};

// Mesa (libOSMesa or EGL's libEGL_mesa, the llvmpipe/gallium driver and the LLVM it JITs with; libglvnd's
// dispatch for EGL) keeps allocations alive for the life
// of the process (driver singletons, compiled shader caches), which LeakSanitizer reports in every sanitizer
// build of a program that renders. Not ours to fix: suppress exactly those libraries, never our own code. The
// one list of suppressions: every binary that links the renderer gets it, without LSAN_OPTIONS.
#if defined(__SANITIZE_ADDRESS__)
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libOSMesa.so\nleak:libgallium\nleak:libLLVM\nleak:swrast_dri\nleak:libglapi.so\n"
         "leak:libEGL_mesa.so\nleak:libEGL.so\nleak:libGLdispatch.so\nleak:libgbm.so\nleak:libdrm\n";
}
#endif

Renderer::Renderer(const ViewSettings& view, ImageSize size, const std::string& shaderFolder)
    : impl_(std::make_unique<Impl>(view, size, shaderFolder)) {}
Renderer::~Renderer() = default;

Image Renderer::render(const FrameState& frame) {
  Image image;
  render(frame, image);
  return image;
}
void Renderer::render(const FrameState& frame, Image& image) { impl_->draw(impl_->composer.compose(frame), image); }
std::string Renderer::glRenderer() const { return impl_->context.rendererName(); }
std::string Renderer::glVersion() const { return impl_->context.version(); }

}  // namespace sl
