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

/// @brief How a Renderer draws; checked by its constructor.
struct RendererOptions {
  /// Multisampling of the frame's framebuffer (0 or 1: none; at most 16). Smoother edges for
  /// figures; tests compare exact pixels without it.
  int samples = 0;
  Real line_width_pixels = 2;  ///< segments, outlines and circles
  int text_scale = 2;          ///< font pixels are text_scale x text_scale screen pixels
  /// An opaque polygon with an opaque outline is drawn as two fans (outline colour grown,
  /// fill shrunk) instead of a fill and a band of quads: fewer triangles, the same pixels.
  /// False always draws the band, the slow twin the tests compare against.
  bool opaque_outline_fast_path = true;
};

/// The OpenGL 3.3 core renderer: one path for OSMesa, EGL and an SDL2 window. Every draw
/// call of a frame is turned into pixel-space triangles on the CPU and drawn in one batch, in call
/// order, so later calls paint over earlier ones and alpha blends as expected.
///
/// World shapes go through camera(); text and draw_screen_* are in pixels (x right, y down).
class Renderer final : public DebugDraw {
 public:
  /// @brief Makes the context current and sets up the shader, buffers and the framebuffer frames
  /// are drawn into (a window's frames are then copied to the window).
  /// @param context must outlive the renderer
  /// @param options see RendererOptions
  /// @throws GlContextError when a GL step fails
  /// @throws InvalidArgumentError for options out of range
  explicit Renderer(GlContext& context, RendererOptions options = {});
  ~Renderer() override;
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  /// @brief The frame's width: the context's at the last begin_frame (a window may be resized).
  int width() const { return width_; }
  /// @brief The frame's height, likewise.
  int height() const { return height_; }
  /// @brief Maps world coordinates to pixels for the draw_* calls; adjust it freely.
  Camera& camera() { return camera_; }
  /// @brief The camera, read only.
  const Camera& camera() const { return camera_; }
  /// @brief The options the renderer was made with.
  const RendererOptions& options() const { return options_; }

  /// @brief Starts a frame: forgets what was recorded; the frame is cleared to `background`.
  void begin_frame(Color background);
  /// @brief Draws what was recorded since begin_frame (a window then presents it).
  void end_frame();
  /// @brief The last finished frame, rows top to bottom. `channels` is 3 (RGB) or 4 (RGBA).
  /// @throws InvalidArgumentError for other channel counts.
  Image read_pixels(int channels = 4);
  /// @brief Same into an existing image (no allocation when its size already fits).
  void read_pixels_into(Image& image, int channels = 4);

  /// @name DebugDraw, in world coordinates
  /// Throws NonFiniteInputError naming a non-finite vertex, InvalidArgumentError for a polygon
  /// of fewer than 3 vertices, a negative radius or size, or a character outside ASCII 32..126
  /// (and '\n').
  /// @{

  /// @brief A convex polygon, counter-clockwise, filled and outlined.
  void draw_polygon(std::span<const Vec2> vertices, Color fill, Color outline) override;
  /// @brief A segment line_width_pixels wide.
  void draw_segment(const Vec2& a, const Vec2& b, Color color) override;
  /// @brief A dot of `pixels` diameter at a world position.
  void draw_point(const Vec2& position, float pixels, Color color) override;
  /// @brief A circle outline, `radius` in world units.
  void draw_circle(const Vec2& center, Real radius, Color color) override;
  /// @brief A label in the bitmap font.
  /// draw_text starts the label at the anchor, its first line centred on it vertically.
  void draw_text(const Vec2& position, std::string_view text, Color color) override;

  /// @}

  /// @brief Screen space: the top-left corner of the text at `pixel`; '\n' starts a new line.
  void draw_screen_text(const Vec2& pixel, std::string_view text, Color color);
  /// @brief Lines of text at the top-left corner on a translucent backing, for step, time, counts.
  void draw_overlay(std::string_view text, Color color = {1, 1, 1, 1},
                    Color backing = {0, 0, 0, 0.55f});
  /// @brief An axis-aligned filled rectangle in pixels.
  void draw_screen_rect(const Vec2& top_left, const Vec2& bottom_right, Color color);

  /// @brief Triangles recorded in the current frame (for tests and benchmarks).
  std::size_t triangle_count() const { return vertices_.size() / 3; }

 private:
  struct Vertex {
    float x, y;
    std::uint32_t rgba;
  };
  void triangle(const Vec2& a, const Vec2& b, const Vec2& c, std::uint32_t rgba);
  void fan(std::span<const Vec2> ring, std::uint32_t rgba);
  void quad(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d, std::uint32_t rgba);
  void rect(const Vec2& top_left, const Vec2& bottom_right, std::uint32_t rgba);
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
  std::vector<Vec2> scratch_;  ///< per-polygon work space, kept to avoid allocations
  std::vector<Vec2> normals_;  ///< outward unit normal of each edge
  std::vector<Vec2> offsets_;
  std::vector<Vec2> grown_;
  std::vector<Vec2> shrunk_;
  std::vector<std::uint8_t> readback_;
  unsigned program_ = 0;
  unsigned vertex_array_ = 0;
  unsigned vertex_buffer_ = 0;
  int viewport_uniform_ = -1;
  unsigned framebuffer_ = 0;  ///< drawn into (multisampled when samples > 1)
  unsigned color_buffer_ = 0;
  unsigned resolve_framebuffer_ = 0;  ///< single-sampled copy read back when multisampling
  unsigned resolve_color_buffer_ = 0;
};

}  // namespace mink
