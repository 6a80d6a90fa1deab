// The renderer: lays out panels, turns each into shapes, and draws them with four programs (flat,
// glyph and lit shapes, and the sphere impostor). All anti-aliasing is analytic, so the frame is a plain
// RGBA8 framebuffer: no MSAA resolve, no depth buffer. With a fixed camera the sphere is drawn once into
// a cached layer and copied into each frame (the same bytes as drawing it, at the cost of a copy).

#include "render/renderer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <stdexcept>

#include "render/font_atlas.hpp"
#include "render/gl.hpp"
#include "render/gl_context.hpp"
#include "render/palette.hpp"
#include "render/panel_layout.hpp"
#include "render/panels.hpp"
#include "render/shader_program.hpp"

namespace sl {
namespace {

using namespace sl::render;

std::string fontPath(const std::string& resourceDir) {
  const std::string shipped = resourceDir + "/fonts/DejaVuSans.ttf";
  if (std::filesystem::exists(shipped)) return shipped;
  return "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";  // Debian's fonts-dejavu-core
}

void checkSize(const RenderSettings& s) {
  if (s.width < 16 || s.height < 16 || s.width > Renderer::maxSize() || s.height > Renderer::maxSize())
    throw std::invalid_argument("frame size " + std::to_string(s.width) + "x" + std::to_string(s.height) +
                                " outside 16.." + std::to_string(Renderer::maxSize()));
}

}  // namespace

struct Renderer::Impl {
  RenderSettings settings;
  std::vector<PanelSpec> panels;
  std::vector<PixelRect> rects;
  GlContext context;
  ShaderProgram flat, glyph, lit, sphere;
  FontAtlas font;
  GLuint vertexArray = 0, vertexBuffer = 0, glyphTexture = 0;
  ShapeBatch batch;
  std::unique_ptr<GlLayer> sphereLayer;
  ViewSpace cachedSpace = ViewSpace::Sphere;

  static std::string dir(const RenderSettings& s) {
    return s.resourceDir.empty() ? std::string(SL_DEFAULT_RESOURCE_DIR) : s.resourceDir;
  }
  static std::vector<std::string> files(const RenderSettings& s, std::initializer_list<const char*> names) {
    std::vector<std::string> paths;
    for (const char* name : names) paths.push_back(dir(s) + "/shaders/" + name);
    return paths;
  }
  // Small, Normal and Title text scale with the frame height (15, 18 and 24 px at 720p).
  static std::array<float, 3> textHeights(int height) {
    return {std::max(10.0f, 0.021f * height), std::max(10.0f, 0.025f * height), std::max(11.0f, 0.034f * height)};
  }

  explicit Impl(const RenderSettings& s)
      : settings((checkSize(s), s)),
        panels(effectivePanels(s)),
        rects(layoutPanels(panels, s.width, s.height)),
        context(s.width, s.height),
        flat(files(s, {"common.glsl", "shapes.vert"}), files(s, {"common.glsl", "flat.frag"})),
        glyph(files(s, {"common.glsl", "shapes.vert"}), files(s, {"common.glsl", "glyph.frag"})),
        lit(files(s, {"common.glsl", "shapes.vert"}), files(s, {"common.glsl", "lit.frag"})),
        sphere(files(s, {"common.glsl", "shapes.vert"}), files(s, {"common.glsl", "sphere.frag"})),
        font(fontPath(dir(s)), textHeights(s.height)) {
    createVertexArray();
    createGlyphTexture();
  }

  ~Impl() {
    glDeleteTextures(1, &glyphTexture);
    glDeleteBuffers(1, &vertexBuffer);
    glDeleteVertexArrays(1, &vertexArray);
  }

  void createVertexArray() {
    glGenVertexArrays(1, &vertexArray);
    glGenBuffers(1, &vertexBuffer);
    glBindVertexArray(vertexArray);
    glBindBuffer(GL_ARRAY_BUFFER, vertexBuffer);
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
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, font.atlasSize(), font.atlasSize(), 0, GL_RED, GL_UNSIGNED_BYTE,
                 font.bitmap().data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }

  // Uniforms every program shares (shaders/common.glsl); without a camera they are inert.
  void setCommonUniforms(const ShaderProgram& program, const SphereCamera* camera) const {
    program.use();
    glUniform2f(program.uniform("uViewport"), float(settings.width), float(settings.height));
    glUniform1f(program.uniform("uAntialias"), settings.antialias ? 1.0f : 0.0f);
    if (!camera) return;
    const auto set3 = [&](const char* name, const V3& v, double scale) {
      glUniform3f(program.uniform(name), float(v.x * scale), float(v.y * scale), float(v.z * scale));
    };
    set3("uEye", camera->eye(), 1);
    set3("uForward", camera->forward(), camera->focal());
    set3("uRight", camera->right(), 1);
    set3("uUp", camera->up(), 1);
    glUniform2f(program.uniform("uCentre"), camera->centre().x, camera->centre().y);
  }

  void upload(const ShapeBatch& shapes) const {
    const auto& vertices = shapes.vertices();
    glBindVertexArray(vertexArray);
    glBindBuffer(GL_ARRAY_BUFFER, vertexBuffer);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(ShapeVertex)), vertices.data(), GL_STREAM_DRAW);
  }

  void drawShapes(const ShapeBatch& shapes, const SphereCamera* camera) {
    if (shapes.vertices().empty()) return;
    upload(shapes);
    for (const ShaderProgram* program : {&flat, &glyph, &lit}) setCommonUniforms(*program, camera);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, glyphTexture);
    glUniform1i(glyph.uniform("uGlyphs"), 0);
    for (const ShapeSegment& segment : shapes.segments()) {
      const ShaderProgram& program = segment.program == ShapeProgram::Flat    ? flat
                                     : segment.program == ShapeProgram::Glyph ? glyph
                                                                              : lit;
      program.use();
      glDrawArrays(GL_TRIANGLES, GLint(segment.first), GLsizei(segment.count));
    }
  }

  void drawSphere(const SphereView& view) {
    setCommonUniforms(sphere, &view.camera);
    const auto color = [&](const char* name, Rgba c) { glUniform3f(sphere.uniform(name), c.r, c.g, c.b); };
    color("uSphereColor", palette::sphereCream);
    color("uGridColor", view.look == SphereLook::Opaque ? palette::sphereGrid : palette::glass);
    color("uPoleColor", palette::poleMark);
    glUniform1i(sphere.uniform("uMode"), int(view.look));
    // The camera looks at the sphere's centre, so its outline is a circle of radius f / sqrt(D^2 - 1)
    // about the panel centre: a quad just around it saves the shader a quarter of the panel's pixels.
    const V3 eye = view.camera.eye();
    const double outline =
        view.camera.focal() / std::sqrt(std::max(eye.x * eye.x + eye.y * eye.y + eye.z * eye.z - 1, 1e-6));
    const float half = float(outline) + 2.0f;
    const P2 centre = view.camera.centre();
    ShapeBatch quad;
    quad.rect(centre.x - half, centre.y - half, centre.x + half, centre.y + half, {});
    upload(quad);
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(quad.vertices().size()));
  }

  // The sphere of a fixed camera does not change between frames: draw it once into `sphereLayer`
  // (on the background colour, as in the frame) and copy that rectangle into every frame.
  void drawSphereCached(const SphereView& view, const PixelRect& rect, ViewSpace space) {
    if (settings.camera.orbitDegreesPerSecond != 0) return drawSphere(view);
    if (!sphereLayer || cachedSpace != space) {
      if (!sphereLayer) sphereLayer = std::make_unique<GlLayer>(settings.width, settings.height);
      sphereLayer->bind();
      clearToBackground();
      drawSphere(view);
      cachedSpace = space;
      context.bindFramebuffer();
    }
    sphereLayer->copyTo(context.framebuffer(), rect);
  }

  void drawPanel(const FrameState& frame, const PanelSpec& panel, const PixelRect& rect) {
    glScissor(GLint(rect.x), GLint(rect.y), GLsizei(rect.width), GLsizei(rect.height));
    batch.clear();
    const PanelContext context{frame, settings, font, rect};
    std::optional<SphereView> view;
    switch (panel.kind) {
      case PanelKind::Linkage:
        drawLinkagePanel(context, batch);
        break;
      case PanelKind::Sphere:
        view = drawSpherePanel(context, batch);
        break;
      case PanelKind::Plot:
        drawPlotPanel(context, panel.plotIndex, batch);
        break;
      case PanelKind::Text:
        drawTextPanel(context, batch);
        break;
    }
    if (view) drawSphereCached(*view, rect, frame.viewSpace);
    drawShapes(batch, view ? &view->camera : nullptr);
  }

  void clearToBackground() const {
    glDisable(GL_SCISSOR_TEST);
    glClearColor(settings.background.r, settings.background.g, settings.background.b, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
  }

  Image render(const FrameState& frame) {
    context.bindFramebuffer();
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // premultiplied alpha
    clearToBackground();
    for (std::size_t i = 0; i < panels.size(); ++i) drawPanel(frame, panels[i], rects[i]);
    Image image{settings.width, settings.height, {}};
    context.readRgb(image.rgb);
    return image;
  }
};

// Mesa (libOSMesa and its llvmpipe driver) keeps ~1.5 kB of allocations alive at exit, which
// LeakSanitizer reports in every sanitizer build of a program that renders. Not ours to fix: suppress
// exactly those libraries. (Lives here so that every binary using the Renderer gets it.)
#if defined(__SANITIZE_ADDRESS__)
extern "C" const char* __lsan_default_suppressions() { return "leak:libOSMesa.so\nleak:libgallium\nleak:libLLVM\n"; }
#endif

Renderer::Renderer(const RenderSettings& settings) : impl_(std::make_unique<Impl>(settings)) {}
Renderer::~Renderer() = default;

Image Renderer::render(const FrameState& frame) { return impl_->render(frame); }
std::string Renderer::glRenderer() const { return impl_->context.rendererName(); }
std::string Renderer::glVersion() const { return impl_->context.version(); }
int Renderer::maxSize() { return 8192; }  // llvmpipe allows 16384; 8192 keeps one frame under 256 MiB

}  // namespace sl
