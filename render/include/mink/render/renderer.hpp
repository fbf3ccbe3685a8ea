#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "mink/engine/debug_draw.hpp"
#include "mink/render/camera.hpp"
#include "mink/render/gl_context.hpp"
#include "mink/render/image.hpp"

namespace mink {

namespace detail {
struct GlFunctions;
}

struct RendererOptions {
  // Multisampling of the frame's framebuffer (0 or 1: none). Smoother edges for figures;
  // tests compare exact pixels without it.
  int samples = 0;
  Real line_width_pixels = 2;  // segments, outlines and circles
  int text_scale = 2;          // font pixels are text_scale x text_scale screen pixels
  // An opaque polygon with an opaque outline is drawn as two fans (outline colour grown,
  // fill shrunk) instead of a fill and a band of quads: fewer triangles, the same pixels.
  // False always draws the band, the slow twin the tests compare against.
  bool opaque_outline_fast_path = true;
};

// The OpenGL 3.3 core renderer: one path for OSMesa, EGL and an SDL2 window. Every draw call
// of a frame is turned into pixel-space triangles on the CPU and drawn in one batch, in call
// order, so later calls paint over earlier ones and alpha blends as expected.
//
// World shapes go through camera(); text and draw_screen_* are in pixels (x right, y down).
class Renderer final : public DebugDraw {
 public:
  // Makes the context current and sets up the shader, buffers and the framebuffer frames are
  // drawn into (a window's frames are then copied to the window). Throws GlContextError when a GL
  // step fails, InvalidArgumentError for options out of range.
  explicit Renderer(GlContext& context, RendererOptions options = {});
  ~Renderer() override;
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // The frame's size: the context's at the last begin_frame (a window may be resized).
  int width() const { return width_; }
  int height() const { return height_; }
  Camera& camera() { return camera_; }
  const Camera& camera() const { return camera_; }
  const RendererOptions& options() const { return options_; }

  // Starts a frame: forgets what was recorded; the frame is cleared to `background`.
  void begin_frame(Color background);
  // Draws what was recorded since begin_frame (a window then presents it).
  void end_frame();
  // The last finished frame, rows top to bottom. `channels` is 3 (RGB) or 4 (RGBA).
  Image read_pixels(int channels = 4);
  // Same into an existing image (no allocation when its size already fits).
  void read_pixels_into(Image& image, int channels = 4);

  // DebugDraw, in world coordinates. Throws NonFiniteInputError naming a non-finite vertex,
  // InvalidArgumentError for a polygon of fewer than 3 vertices, a negative radius or size,
  // or a character outside ASCII 32..126 (and '\n').
  void draw_polygon(std::span<const Vec2> vertices, Color fill, Color outline) override;
  void draw_segment(const Vec2& a, const Vec2& b, Color color) override;
  void draw_point(const Vec2& position, float pixels, Color color) override;
  void draw_circle(const Vec2& center, Real radius, Color color) override;
  void draw_text(const Vec2& position, std::string_view text, Color color) override;

  // draw_text starts the label at the anchor, its first line centred on it vertically.

  // Screen space: the top-left corner of the text at `pixel`; '\n' starts a new line.
  void draw_screen_text(const Vec2& pixel, std::string_view text, Color color);
  // Lines of text at the top-left corner on a translucent backing, for step, time, counts.
  void draw_overlay(std::string_view text, Color color = {1, 1, 1, 1},
                    Color backing = {0, 0, 0, 0.55f});
  // An axis-aligned filled rectangle in pixels.
  void draw_screen_rect(const Vec2& top_left, const Vec2& bottom_right, Color color);

  // Triangles recorded in the current frame (for tests and benchmarks).
  std::size_t triangle_count() const { return vertices_.size() / 3; }

 private:
  struct Vertex {
    float x, y;
    std::uint32_t rgba;
  };
  void triangle(const Vec2& a, const Vec2& b, const Vec2& c, std::uint32_t rgba);
  void fan(std::span<const Vec2> ring, std::uint32_t rgba);
  void quad(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d, std::uint32_t rgba);
  void thick_segment_pixels(const Vec2& a, const Vec2& b, Real width, std::uint32_t rgba);
  void disc_pixels(const Vec2& center, Real radius, std::uint32_t rgba);
  void text_pixels(const Vec2& top_left, std::string_view text, std::uint32_t rgba);
  void create_framebuffers();
  void destroy_framebuffers();
  void destroy_gl_objects();

  GlContext& context_;
  RendererOptions options_;
  Camera camera_;
  std::unique_ptr<detail::GlFunctions> gl_;
  Color background_{0, 0, 0, 1};
  int width_ = 0;
  int height_ = 0;
  std::vector<Vertex> vertices_;
  struct Run {
    std::size_t first;
    std::size_t count;
    bool blend;
  };
  std::vector<Run> runs_;
  std::vector<Vec2> scratch_;  // per-polygon work space, kept to avoid allocations
  std::vector<Vec2> offsets_;
  std::vector<Vec2> grown_;
  std::vector<Vec2> shrunk_;
  std::vector<std::uint8_t> readback_;
  unsigned program_ = 0;
  unsigned vertex_array_ = 0;
  unsigned vertex_buffer_ = 0;
  int viewport_uniform_ = -1;
  unsigned framebuffer_ = 0;  // drawn into (multisampled when samples > 1)
  unsigned color_buffer_ = 0;
  unsigned resolve_framebuffer_ = 0;  // single-sampled copy read back when multisampling
  unsigned resolve_color_buffer_ = 0;
};

}  // namespace mink
