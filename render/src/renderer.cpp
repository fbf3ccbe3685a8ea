#include "mink/render/renderer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "gl_functions.hpp"
#include "mink/error.hpp"
#include "mink/geometry/hull_input.hpp"
#include "mink/geometry/polygon.hpp"
#include "mink/render/bitmap_font.hpp"
#include "mink/render/render_error.hpp"

namespace mink {

namespace {

// Pixel coordinates (x right, y down) to clip space; the pixel grid's top row is drawn at the
// top of the framebuffer, which GL stores last (read_pixels flips it back).
constexpr const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec2 position;
layout(location = 1) in vec4 color;
uniform vec2 viewport;
out vec4 vertex_color;
void main() {
  gl_Position = vec4(position.x / viewport.x * 2.0 - 1.0, 1.0 - position.y / viewport.y * 2.0,
                     0.0, 1.0);
  vertex_color = color;
}
)";

constexpr const char* kFragmentShader = R"(#version 330 core
in vec4 vertex_color;
out vec4 fragment_color;
void main() { fragment_color = vertex_color; }
)";

std::uint32_t pack(Color color) {
  const auto channel = [](float value, const char* name) {
    if (!(value >= 0.0f && value <= 1.0f)) {
      std::ostringstream message;
      message << "colour channel " << name << " = " << value << " is outside [0, 1]";
      throw InvalidArgumentError(message.str());
    }
    return static_cast<std::uint32_t>(std::lround(value * 255.0f));
  };
  // Memory order r, g, b, a on a little-endian machine, as the vertex format reads it.
  return channel(color.r, "r") | channel(color.g, "g") << 8 | channel(color.b, "b") << 16 |
         channel(color.a, "a") << 24;
}

bool transparent(std::uint32_t rgba) {
  return (rgba >> 24) == 0;
}

bool opaque(std::uint32_t rgba) {
  return (rgba >> 24) == 255;
}

GLuint compile(const detail::GlFunctions& gl, GLenum type, const char* source, const char* name) {
  const GLuint shader = gl.CreateShader(type);
  gl.ShaderSource(shader, 1, &source, nullptr);
  gl.CompileShader(shader);
  GLint ok = GL_FALSE;
  gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    char log[1024] = {};
    gl.GetShaderInfoLog(shader, sizeof log, nullptr, log);
    gl.DeleteShader(shader);
    throw GlContextError(std::string(name) + " shader does not compile: " + log);
  }
  return shader;
}

}  // namespace

Renderer::Renderer(GlContext& context, RendererOptions options)
    : context_(context), options_(options), camera_(context.width(), context.height()) {
  if (options.samples < 0 || options.samples > 16) {
    throw InvalidArgumentError("multisampling " + std::to_string(options.samples) +
                               " is outside 0..16");
  }
  if (!std::isfinite(options.line_width_pixels) || options.line_width_pixels <= 0) {
    throw InvalidArgumentError("line width must be finite and positive");
  }
  if (options.text_scale < 1 || options.text_scale > 16) {
    throw InvalidArgumentError("text scale " + std::to_string(options.text_scale) +
                               " is outside 1..16");
  }
  context_.make_current();
  gl_ = std::make_unique<detail::GlFunctions>(context_);
  const detail::GlFunctions& gl = *gl_;
  try {
    const GLuint vertex = compile(gl, GL_VERTEX_SHADER, kVertexShader, "vertex");
    GLuint fragment = 0;
    try {
      fragment = compile(gl, GL_FRAGMENT_SHADER, kFragmentShader, "fragment");
    } catch (...) {
      gl.DeleteShader(vertex);
      throw;
    }
    program_ = gl.CreateProgram();
    gl.AttachShader(program_, vertex);
    gl.AttachShader(program_, fragment);
    gl.LinkProgram(program_);
    gl.DeleteShader(vertex);
    gl.DeleteShader(fragment);
    GLint linked = GL_FALSE;
    gl.GetProgramiv(program_, GL_LINK_STATUS, &linked);
    if (linked != GL_TRUE) {
      char log[1024] = {};
      gl.GetProgramInfoLog(program_, sizeof log, nullptr, log);
      throw GlContextError(std::string("shader program does not link: ") + log);
    }
    viewport_uniform_ = gl.GetUniformLocation(program_, "viewport");

    gl.GenVertexArrays(1, &vertex_array_);
    gl.BindVertexArray(vertex_array_);
    gl.GenBuffers(1, &vertex_buffer_);
    gl.BindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
    gl.VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                           reinterpret_cast<const void*>(offsetof(Vertex, x)));
    gl.VertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(Vertex),
                           reinterpret_cast<const void*>(offsetof(Vertex, rgba)));
    gl.EnableVertexAttribArray(0);
    gl.EnableVertexAttribArray(1);
    gl.check("vertex buffer setup");
    create_framebuffers();
  } catch (...) {
    destroy_gl_objects();
    throw;
  }
}

Renderer::~Renderer() {
  try {
    context_.make_current();
  } catch (const Error&) {
    return;  // the context is gone; its objects went with it
  }
  destroy_gl_objects();
}

void Renderer::destroy_gl_objects() {
  destroy_framebuffers();
  const detail::GlFunctions& gl = *gl_;
  if (vertex_buffer_ != 0) gl.DeleteBuffers(1, &vertex_buffer_);
  if (vertex_array_ != 0) gl.DeleteVertexArrays(1, &vertex_array_);
  if (program_ != 0) gl.DeleteProgram(program_);
  vertex_buffer_ = vertex_array_ = program_ = 0;
}

void Renderer::destroy_framebuffers() {
  const detail::GlFunctions& gl = *gl_;
  if (resolve_framebuffer_ != 0) gl.DeleteFramebuffers(1, &resolve_framebuffer_);
  if (resolve_color_buffer_ != 0) gl.DeleteRenderbuffers(1, &resolve_color_buffer_);
  if (framebuffer_ != 0) gl.DeleteFramebuffers(1, &framebuffer_);
  if (color_buffer_ != 0) gl.DeleteRenderbuffers(1, &color_buffer_);
  resolve_framebuffer_ = resolve_color_buffer_ = framebuffer_ = color_buffer_ = 0;
}

void Renderer::create_framebuffers() {
  const detail::GlFunctions& gl = *gl_;
  width_ = context_.width();
  height_ = context_.height();
  const auto make = [&](GLuint& framebuffer, GLuint& color, int samples) {
    gl.GenFramebuffers(1, &framebuffer);
    gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    gl.GenRenderbuffers(1, &color);
    gl.BindRenderbuffer(GL_RENDERBUFFER, color);
    if (samples > 1) {
      gl.RenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, width(), height());
    } else {
      gl.RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width(), height());
    }
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
    const GLenum status = gl.CheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
      throw GlContextError(std::string(context_.name()) + ": framebuffer of " +
                           std::to_string(width()) + " x " + std::to_string(height()) + " with " +
                           std::to_string(samples) + " samples is incomplete (status " +
                           std::to_string(status) + ")");
    }
  };
  if (options_.samples > 1) {
    GLint max_samples = 0;
    gl.GetIntegerv(GL_MAX_SAMPLES, &max_samples);
    if (options_.samples > max_samples) {
      throw GlContextError(std::string(context_.name()) + ": " + std::to_string(options_.samples) +
                           " samples asked, at most " + std::to_string(max_samples) + " offered");
    }
    make(resolve_framebuffer_, resolve_color_buffer_, 0);
  }
  make(framebuffer_, color_buffer_, options_.samples);
  gl.check("framebuffer setup");
}

void Renderer::begin_frame(Color background) {
  pack(background);  // validates
  background_ = background;
  if (context_.width() != width_ || context_.height() != height_) {
    // A window was resized: frames follow its new size, the camera keeps its centre.
    context_.make_current();
    destroy_framebuffers();
    create_framebuffers();
    camera_.resize(width_, height_);
  }
  vertices_.clear();
  runs_.clear();
}

void Renderer::end_frame() {
  context_.make_current();
  const detail::GlFunctions& gl = *gl_;
  gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  gl.Viewport(0, 0, width(), height());
  gl.Disable(GL_DEPTH_TEST);
  gl.Disable(GL_CULL_FACE);
  gl.Enable(GL_BLEND);
  // Straight alpha over what is below; the destination keeps an alpha that composites too.
  gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  gl.ClearColor(background_.r, background_.g, background_.b, background_.a);
  gl.Clear(GL_COLOR_BUFFER_BIT);
  if (!vertices_.empty()) {
    gl.UseProgram(program_);
    gl.Uniform2f(viewport_uniform_, static_cast<float>(width()), static_cast<float>(height()));
    gl.BindVertexArray(vertex_array_);
    gl.BindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
    gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices_.size() * sizeof(Vertex)),
                  vertices_.data(), GL_STREAM_DRAW);
    for (const Run& run : runs_) {
      if (run.blend) {
        gl.Enable(GL_BLEND);
      } else {
        gl.Disable(GL_BLEND);
      }
      gl.DrawArrays(GL_TRIANGLES, static_cast<GLint>(run.first), static_cast<GLsizei>(run.count));
    }
  }
  gl.check("drawing a frame");
  if (!context_.offscreen()) {
    // A window shows the frame: copy it to the window's framebuffer and swap.
    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
    gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    gl.BlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT,
                       GL_NEAREST);
    gl.check("copying the frame to the window");
    context_.present();
  }
}

Image Renderer::read_pixels(int channels) {
  Image image;
  read_pixels_into(image, channels);
  return image;
}

void Renderer::read_pixels_into(Image& image, int channels) {
  if (channels != 3 && channels != 4) {
    throw InvalidArgumentError("read_pixels: channels " + std::to_string(channels) +
                               " must be 3 or 4");
  }
  context_.make_current();
  const detail::GlFunctions& gl = *gl_;
  const int w = width();
  const int h = height();
  GLuint source = framebuffer_;
  if (resolve_framebuffer_ != 0) {
    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
    gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_framebuffer_);
    gl.BlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    source = resolve_framebuffer_;
  }
  gl.BindFramebuffer(GL_READ_FRAMEBUFFER, source);
  gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
  const std::size_t row_bytes = static_cast<std::size_t>(w) * 4;
  readback_.resize(row_bytes * static_cast<std::size_t>(h));
  gl.ReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, readback_.data());
  gl.check("reading pixels back");

  if (image.width != w || image.height != h || image.channels != channels) {
    image = Image(w, h, channels);
  }
  // GL's first row is the bottom one.
  for (int y = 0; y < h; ++y) {
    const std::uint8_t* from = readback_.data() + row_bytes * static_cast<std::size_t>(h - 1 - y);
    std::uint8_t* to = image.pixels.data() + static_cast<std::size_t>(y) *
                                                 static_cast<std::size_t>(w) *
                                                 static_cast<std::size_t>(channels);
    if (channels == 4) {
      std::copy(from, from + row_bytes, to);
    } else {
      for (int x = 0; x < w; ++x, from += 4, to += 3) {
        to[0] = from[0];
        to[1] = from[1];
        to[2] = from[2];
      }
    }
  }
}

void Renderer::triangle(const Vec2& a, const Vec2& b, const Vec2& c, std::uint32_t rgba) {
  // Opaque triangles skip blending (the same pixels, less work per fragment); runs of
  // triangles that agree on it are drawn together, in order.
  const bool blend = !opaque(rgba);
  if (runs_.empty() || runs_.back().blend != blend) runs_.push_back({vertices_.size(), 0, blend});
  runs_.back().count += 3;
  vertices_.push_back({static_cast<float>(a.x()), static_cast<float>(a.y()), rgba});
  vertices_.push_back({static_cast<float>(b.x()), static_cast<float>(b.y()), rgba});
  vertices_.push_back({static_cast<float>(c.x()), static_cast<float>(c.y()), rgba});
}

void Renderer::quad(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d,
                    std::uint32_t rgba) {
  triangle(a, b, c, rgba);
  triangle(a, c, d, rgba);
}

void Renderer::rect(const Vec2& top_left, const Vec2& bottom_right, std::uint32_t rgba) {
  quad(top_left, Vec2(bottom_right.x(), top_left.y()), bottom_right,
       Vec2(top_left.x(), bottom_right.y()), rgba);
}

void Renderer::thick_segment_pixels(const Vec2& a, const Vec2& b, Real width, std::uint32_t rgba) {
  const Real half = width / 2;
  const Vec2 along = b - a;
  const Real length = along.norm();
  if (length < 1e-9) {
    // A zero-length segment still shows, as a square dot.
    rect(a - Vec2(half, half), a + Vec2(half, half), rgba);
    return;
  }
  const Vec2 side = Vec2(-along.y(), along.x()) * (half / length);
  quad(a + side, b + side, b - side, a - side, rgba);
}

void Renderer::disc_pixels(const Vec2& center, Real radius, std::uint32_t rgba) {
  const int sides = std::clamp(static_cast<int>(std::ceil(radius * 2)), 8, 64);
  Vec2 previous = center + Vec2(radius, 0);
  for (int i = 1; i <= sides; ++i) {
    const Real angle = 2 * std::numbers::pi * i / sides;
    const Vec2 next = center + radius * Vec2(std::cos(angle), std::sin(angle));
    triangle(center, previous, next, rgba);
    previous = next;
  }
}

void Renderer::text_pixels(const Vec2& top_left, std::string_view text, std::uint32_t rgba) {
  const int scale = options_.text_scale;
  // Whole pixels keep the glyphs crisp.
  const Real left = std::round(top_left.x());
  Real top = std::round(top_left.y());
  Real x = left;
  for (char c : text) {
    if (c == '\n') {
      x = left;
      top += BitmapFont::line_height * scale;
      continue;
    }
    for (int r = 0; r < BitmapFont::glyph_height; ++r) {
      const std::uint8_t bits = BitmapFont::row(c, r);
      const Real y = top + r * scale;
      // One quad per horizontal run of lit pixels.
      for (int column = 0; column < BitmapFont::glyph_width;) {
        if (((bits >> (BitmapFont::glyph_width - 1 - column)) & 1u) == 0) {
          ++column;
          continue;
        }
        int end = column + 1;
        while (end < BitmapFont::glyph_width &&
               ((bits >> (BitmapFont::glyph_width - 1 - end)) & 1u) != 0) {
          ++end;
        }
        const Real x0 = x + column * scale;
        const Real x1 = x + end * scale;
        rect(Vec2(x0, y), Vec2(x1, y + scale), rgba);
        column = end;
      }
    }
    x += BitmapFont::advance * scale;
  }
}

void Renderer::fan(std::span<const Vec2> ring, std::uint32_t rgba) {
  for (std::size_t i = 1; i + 1 < ring.size(); ++i) triangle(ring[0], ring[i], ring[i + 1], rgba);
}

void Renderer::draw_polygon(std::span<const Vec2> vertices, Color fill, Color outline) {
  if (vertices.size() < 3) {
    throw InvalidArgumentError("polygon of " + std::to_string(vertices.size()) +
                               " vertices: at least 3 needed");
  }
  const std::uint32_t fill_rgba = pack(fill);
  const std::uint32_t outline_rgba = pack(outline);
  require_finite(vertices);
  scratch_.clear();
  for (const Vec2& vertex : vertices) scratch_.push_back(camera_.world_to_pixel(vertex));
  const std::span<const Vec2> pixels(scratch_);
  const std::size_t n = pixels.size();
  const bool show_fill = !transparent(fill_rgba);
  if (transparent(outline_rgba)) {
    if (show_fill) fan(pixels, fill_rgba);
    return;
  }

  // The outline is a band centred on the boundary with mitred corners, so corners close.
  // Normals point out of the polygon whichever way it winds on screen.
  const Real twice_area = 2 * signed_area(pixels);
  const Real half = options_.line_width_pixels / 2;
  bool degenerate = std::abs(twice_area) < 1e-9;
  normals_.clear();
  for (std::size_t i = 0; i < n && !degenerate; ++i) {
    const Vec2 edge = pixels[(i + 1) % n] - pixels[i];
    const Real length = edge.norm();
    degenerate = length < 1e-9;
    const Vec2 normal = Vec2(edge.y(), -edge.x()) / length;
    normals_.push_back(twice_area >= 0 ? normal : Vec2(-normal));
  }
  if (degenerate) {
    // Repeated vertices or no area on screen: plain segments say the same without mitres.
    if (show_fill) fan(pixels, fill_rgba);
    for (std::size_t i = 0; i < n; ++i) {
      thick_segment_pixels(pixels[i], pixels[(i + 1) % n], options_.line_width_pixels,
                           outline_rgba);
    }
    return;
  }
  offsets_.clear();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& before = normals_[(i + n - 1) % n];
    const Vec2& after = normals_[i];
    // |miter| = half / cos(turn / 2); capped so a needle-sharp corner stays short.
    const Real denominator = std::max<Real>(1 + before.dot(after), 0.25);
    offsets_.push_back((before + after) * (half / denominator));
  }

  if (options_.opaque_outline_fast_path && opaque(fill_rgba) && opaque(outline_rgba)) {
    // Both opaque: the outline colour over the polygon grown by half the line width, then the
    // fill over the polygon shrunk by as much covers the same pixels as fill plus band, with
    // 2 (n - 2) triangles instead of 3n - 2. Valid while the shrunk polygon keeps every
    // edge's direction; a polygon thinner than the line takes the band below.
    shrunk_.clear();
    for (std::size_t i = 0; i < n; ++i) shrunk_.push_back(pixels[i] - offsets_[i]);
    bool shrinks = true;
    for (std::size_t i = 0; i < n && shrinks; ++i) {
      const std::size_t j = (i + 1) % n;
      shrinks = (shrunk_[j] - shrunk_[i]).dot(pixels[j] - pixels[i]) > 0;
    }
    if (shrinks) {
      grown_.clear();
      for (std::size_t i = 0; i < n; ++i) grown_.push_back(pixels[i] + offsets_[i]);
      fan(grown_, outline_rgba);
      fan(shrunk_, fill_rgba);
      return;
    }
  }
  if (show_fill) fan(pixels, fill_rgba);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    quad(pixels[i] + offsets_[i], pixels[j] + offsets_[j], pixels[j] - offsets_[j],
         pixels[i] - offsets_[i], outline_rgba);
  }
}

void Renderer::draw_segment(const Vec2& a, const Vec2& b, Color color) {
  const std::uint32_t rgba = pack(color);
  require_finite(std::array{a, b});
  thick_segment_pixels(camera_.world_to_pixel(a), camera_.world_to_pixel(b),
                       options_.line_width_pixels, rgba);
}

void Renderer::draw_point(const Vec2& position, float pixels, Color color) {
  const std::uint32_t rgba = pack(color);
  require_finite({&position, 1});
  if (!(pixels >= 0) || !std::isfinite(pixels)) {
    throw InvalidArgumentError("point size " + std::to_string(pixels) +
                               " must be finite and not negative");
  }
  disc_pixels(camera_.world_to_pixel(position), pixels / 2.0, rgba);
}

void Renderer::draw_circle(const Vec2& center, Real radius, Color color) {
  const std::uint32_t rgba = pack(color);
  require_finite({&center, 1});
  if (!(radius >= 0) || !std::isfinite(radius)) {
    throw InvalidArgumentError("circle radius " + std::to_string(radius) +
                               " must be finite and not negative");
  }
  const Vec2 c = camera_.world_to_pixel(center);
  const Real r = radius * camera_.pixels_per_unit();
  const Real half = options_.line_width_pixels / 2;
  const Real inner = std::max<Real>(r - half, 0);
  const Real outer = r + half;
  const int sides = std::clamp(static_cast<int>(std::ceil(outer)), 12, 256);
  Vec2 previous(1, 0);
  for (int i = 1; i <= sides; ++i) {
    const Real angle = 2 * std::numbers::pi * i / sides;
    const Vec2 next(std::cos(angle), std::sin(angle));
    quad(c + outer * previous, c + outer * next, c + inner * next, c + inner * previous, rgba);
    previous = next;
  }
}

void Renderer::draw_text(const Vec2& position, std::string_view text, Color color) {
  const std::uint32_t rgba = pack(color);
  require_finite({&position, 1});
  BitmapFont::text_width(text);  // validates every character before anything is recorded
  // The label starts at the anchor, its first line centred on it vertically.
  const Vec2 anchor = camera_.world_to_pixel(position);
  text_pixels(anchor - Vec2(0, BitmapFont::glyph_height * options_.text_scale / 2.0), text, rgba);
}

void Renderer::draw_screen_text(const Vec2& pixel, std::string_view text, Color color) {
  const std::uint32_t rgba = pack(color);
  require_finite({&pixel, 1});
  BitmapFont::text_width(text);
  text_pixels(pixel, text, rgba);
}

void Renderer::draw_overlay(std::string_view text, Color color, Color backing) {
  const int scale = options_.text_scale;
  const Real pad = 3 * scale;
  const Real w = BitmapFont::text_width(text) * scale;
  const Real h = BitmapFont::text_height(text) * scale;
  if (w == 0) return;
  draw_screen_rect(Vec2(0, 0), Vec2(w + 2 * pad, h + 2 * pad - 2 * scale), backing);
  draw_screen_text(Vec2(pad, pad), text, color);
}

void Renderer::draw_screen_rect(const Vec2& top_left, const Vec2& bottom_right, Color color) {
  const std::uint32_t rgba = pack(color);
  require_finite(std::array{top_left, bottom_right});
  rect(top_left, bottom_right, rgba);
}

}  // namespace mink
