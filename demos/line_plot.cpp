#include "line_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "mink/render/gl_context.hpp"
#include "mink/render/png_file.hpp"
#include "mink/render/renderer.hpp"

namespace mink::cli {

namespace {

constexpr int kWidth = 1000;
constexpr int kPanelHeight = 520;

// The top of the y axis: headroom over the largest value, and a round top so that the four
// tick values stay short (whole for counts, 1, 2, 2.5 or 5 times a power of ten otherwise).
double axis_top(const PlotPanel& panel) {
  double largest = 0;
  for (const PlotLine& line : panel.lines) {
    for (const double v : line.values) largest = std::max(largest, v);
  }
  if (panel.whole_numbers) {
    const long long top = std::max(1LL, std::llround(largest));
    return static_cast<double>((top + top / 8 + 3) / 4 * 4);
  }
  if (!(largest > 0)) return 1;
  const double tick = largest * 1.125 / 4;
  const double power = std::pow(10.0, std::floor(std::log10(tick)));
  for (const double m : {1.0, 2.0, 2.5, 5.0}) {
    if (m * power >= tick) return 4 * m * power;
  }
  return 40 * power;
}

// One panel; world units are pixels (y up), `base` the panel's bottom edge, `row` its index
// from the top (screen text is placed in pixels from the image's top).
void draw_panel(Renderer& r, const PlotPanel& panel, double base, int row) {
  const double left = 70, right = kWidth - 30, bottom = base + 50, top = base + kPanelHeight - 60;
  const double screen_top = static_cast<double>(row) * kPanelHeight;
  std::size_t points = 0;
  for (const PlotLine& line : panel.lines) points = std::max(points, line.values.size());
  const double steps =
      std::max(1.0, static_cast<double>(panel.first_step) + static_cast<double>(points) - 1);
  const double y_top = axis_top(panel);
  auto at = [&](double step, double value) {
    return Vec2(left + (right - left) * step / steps, bottom + (top - bottom) * value / y_top);
  };
  const Color axis{0.2f, 0.2f, 0.2f, 1};
  const Color grid{0.85f, 0.85f, 0.85f, 1};
  for (int k = 0; k <= 4; ++k) {
    const double value = y_top * k / 4.0;
    r.draw_segment(at(0, value), at(steps, value), grid);
    char label[32];
    std::snprintf(label, sizeof label, panel.whole_numbers ? "%.0f" : "%.3g", value);
    const Vec2 pixel = r.camera().world_to_pixel(at(0, value));
    r.draw_screen_text(Vec2(8, pixel.y() - 6), label, axis);
    std::snprintf(label, sizeof label, "%.0f", steps * k / 4.0);
    const Vec2 tick = r.camera().world_to_pixel(at(steps * k / 4.0, 0));
    r.draw_screen_text(Vec2(tick.x() - 12, tick.y() + 8), label, axis);
  }
  r.draw_segment(at(0, 0), at(steps, 0), axis);
  r.draw_segment(at(0, 0), at(0, y_top), axis);
  int legend = 0;
  for (const PlotLine& line : panel.lines) {
    const std::size_t dash = std::max<std::size_t>(1, line.values.size() / 60);
    const double first = static_cast<double>(panel.first_step);
    for (std::size_t i = 1; i < line.values.size(); ++i) {
      if (line.dashed && (i / dash) % 2 == 1) continue;
      r.draw_segment(at(first + static_cast<double>(i) - 1, line.values[i - 1]),
                     at(first + static_cast<double>(i), line.values[i]), line.color);
    }
    const Vec2 key(left + 20 + 220 * legend++, screen_top + 36);
    r.draw_screen_rect(key, key + Vec2(24, 6), line.color);
    r.draw_screen_text(key + Vec2(30, -4), line.name, axis);
  }
  r.draw_screen_text(Vec2(left, screen_top + 10), panel.title, axis);
}

}  // namespace

void write_line_plot(const std::vector<PlotPanel>& panels, GlBackend backend,
                     const std::filesystem::path& file) {
  const int height = kPanelHeight * static_cast<int>(std::max<std::size_t>(1, panels.size()));
  const auto context = make_offscreen_context(backend, kWidth, height);
  RendererOptions options;
  options.samples = 4;
  Renderer r(*context, options);
  r.camera().fit(Vec2(0, 0), Vec2(kWidth, height), 0);
  r.begin_frame(Color{1, 1, 1, 1});
  for (std::size_t k = 0; k < panels.size(); ++k) {
    draw_panel(r, panels[k], static_cast<double>(height) - (k + 1.0) * kPanelHeight,
               static_cast<int>(k));
  }
  r.end_frame();
  write_png(file, r.read_pixels(3));
}

}  // namespace mink::cli
