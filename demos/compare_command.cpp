#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <ostream>
#include <string>

#include "commands.hpp"
#include "contact_compare.hpp"
#include "exit_codes.hpp"
#include "mink/engine/scene_file.hpp"
#include "mink/error.hpp"
#include "mink/render/gl_context.hpp"
#include "mink/render/png_file.hpp"
#include "mink/render/renderer.hpp"
#include "output_files.hpp"

namespace mink::cli {

namespace {

struct CompareOptions {
  std::string scene = "pyramid";
  long long steps = 600;
  std::string out = "out/compare";
  int every = 10;
  std::string gl = "osmesa";
};

constexpr double kBand = 1e-6;

// Contact counts over time, drawn by the render layer: the camera maps one world unit to one
// pixel (y up), so series are plotted in pixel units inside the plot box.
void plot_counts(const ContactComparison& c, const std::string& scene, GlBackend backend,
                 const std::filesystem::path& file) {
  const int width = 1000;
  const int height = 520;
  const auto context = make_offscreen_context(backend, width, height);
  RendererOptions options;
  options.samples = 4;
  Renderer r(*context, options);
  r.camera().fit(Vec2(0, 0), Vec2(width, height), 0);
  r.begin_frame(Color{1, 1, 1, 1});
  const Real left = 70, right = width - 20, bottom = 50, top = height - 60;
  std::size_t max_count = 1;
  for (const ContactCountRow& row : c.rows) {
    max_count = std::max(
        {max_count, row.mink_pairs, row.mink_contacts, row.box2d_pairs, row.box2d_touching});
  }
  // Headroom, and a round top: a flat line at the maximum stays visible, ticks stay whole.
  max_count = (max_count + max_count / 8 + 3) / 4 * 4;
  const double steps = static_cast<double>(c.rows.size());
  auto at = [&](double step, double count) {
    return Vec2(left + (right - left) * step / steps,
                bottom + (top - bottom) * count / static_cast<double>(max_count));
  };
  const Color axis{0.2f, 0.2f, 0.2f, 1};
  const Color grid{0.85f, 0.85f, 0.85f, 1};
  for (int k = 0; k <= 4; ++k) {
    const double count = max_count * k / 4.0;
    r.draw_segment(at(0, count), at(steps, count), grid);
    char label[32];
    std::snprintf(label, sizeof label, "%.0f", count);
    const Vec2 pixel = r.camera().world_to_pixel(at(0, count));
    r.draw_screen_text(Vec2(8, pixel.y() - 6), label, axis);
    std::snprintf(label, sizeof label, "%.0f", steps * k / 4.0);
    const Vec2 tick = r.camera().world_to_pixel(at(steps * k / 4.0, 0));
    r.draw_screen_text(Vec2(tick.x() - 12, tick.y() + 8), label, axis);
  }
  r.draw_segment(at(0, 0), at(steps, 0), axis);
  r.draw_segment(at(0, 0), at(0, max_count), axis);
  struct Series {
    std::size_t ContactCountRow::*field;
    Color color;
    const char* name;
    bool dashed;  // Box2D dashed over Minkowski solid: equal counts stay visible
  };
  const Series series[] = {
      {&ContactCountRow::mink_pairs, {0.55f, 0.7f, 1.0f, 1}, "mink pairs", false},
      {&ContactCountRow::box2d_pairs, {1.0f, 0.65f, 0.55f, 1}, "box2d pairs", true},
      {&ContactCountRow::mink_contacts, {0.1f, 0.3f, 0.85f, 1}, "mink touching", false},
      {&ContactCountRow::box2d_touching, {0.85f, 0.2f, 0.1f, 1}, "box2d touching", true},
  };
  int legend = 0;
  for (const Series& s : series) {
    const std::size_t dash = std::max<std::size_t>(1, c.rows.size() / 60);
    for (std::size_t i = 1; i < c.rows.size(); ++i) {
      if (s.dashed && (i / dash) % 2 == 1) continue;
      r.draw_segment(at(static_cast<double>(i), static_cast<double>(c.rows[i - 1].*s.field)),
                     at(static_cast<double>(i + 1), static_cast<double>(c.rows[i].*s.field)),
                     s.color);
    }
    const Vec2 key(left + 20 + 220 * legend++, 36);
    r.draw_screen_rect(key, key + Vec2(24, 6), s.color);
    r.draw_screen_text(key + Vec2(30, -4), s.name, axis);
  }
  r.draw_screen_text(Vec2(left, 10),
                     "contacts over time: " + scene + ", Minkowski vs Box2D 2.4.1 (x: step)", axis);
  r.end_frame();
  write_png(file, r.read_pixels(3));
}

int run_compare(const CompareOptions& options, Streams streams) {
  const GlBackend backend = parse_gl_backend(options.gl);
  const SceneDef scene = resolve_scene(options.scene);
  if (scene.schedule) {
    // Its actions act on our world only: Box2D 2.4.1 would run another scene.
    throw InvalidArgumentError("scene '" + options.scene +
                               "' changes as it runs (its schedule creates, destroys or steers "
                               "bodies), which Box2D 2.4.1 cannot follow");
  }
  const ContactComparison c = compare_contacts(scene, options.steps, options.every, kBand);
  const std::filesystem::path out(options.out);
  make_directories(out, "--out");
  {
    std::ofstream csv = open_output_file(out / "contacts.csv", "the contact counts");
    csv << "step,mink_pairs,mink_contacts,box2d_pairs,box2d_touching\n";
    for (const ContactCountRow& row : c.rows) {
      csv << row.step << ',' << row.mink_pairs << ',' << row.mink_contacts << ',' << row.box2d_pairs
          << ',' << row.box2d_touching << '\n';
    }
    close_output_file(csv, out / "contacts.csv", "the contact counts");
  }
  plot_counts(c, options.scene, backend, out / "contacts.png");

  // Averages over the last tenth of the run: where the scene has settled.
  const std::size_t tail = std::max<std::size_t>(1, c.rows.size() / 10);
  double mink = 0;
  double box2d = 0;
  for (std::size_t i = c.rows.size() - tail; i < c.rows.size(); ++i) {
    mink += static_cast<double>(c.rows[i].mink_contacts);
    box2d += static_cast<double>(c.rows[i].box2d_touching);
  }
  char line[320];
  std::snprintf(line, sizeof line,
                "%s, %lld steps: touching contacts over the last %zu steps average %.1f "
                "(Minkowski) and %.1f (Box2D)\n",
                options.scene.c_str(), options.steps, tail, mink / tail, box2d / tail);
  streams.out << line;
  for (const OracleMismatch& m : c.mismatches) {
    std::snprintf(line, sizeof line,
                  "mismatch at step %lld: bodies %zu and %zu, mink says %s, Box2D the other, "
                  "exact test %s; distance to touching %.3g%s\n",
                  m.step, m.body_a, m.body_b, m.mink_overlap ? "overlap" : "apart",
                  m.exact_overlap ? "overlap" : "apart", m.gap,
                  m.outside_band ? " (outside the band)" : " (inside the band)");
    streams.out << line;
    if (m.outside_band) {
      // Full precision, so the case can be replayed against the narrowphase alone.
      for (const auto* hull : {&m.world_a, &m.world_b}) {
        streams.out << "  hull " << (hull == &m.world_a ? m.body_a : m.body_b) << ':';
        for (const Vec2& v : *hull) {
          std::snprintf(line, sizeof line, " (%.17g, %.17g)", v.x(), v.y());
          streams.out << line;
        }
        streams.out << '\n';
      }
    }
  }
  std::snprintf(line, sizeof line,
                "overlap oracle: %zu configurations, %zu candidate pairs (%zu overlapping), %zu "
                "mismatches, %zu outside the %.0e band\n",
                c.oracle_checks, c.oracle_pairs, c.oracle_overlapping, c.mismatches.size(),
                c.outside_band, kBand);
  streams.out << line;
  streams.out << "wrote " << (out / "contacts.csv").string() << " and "
              << (out / "contacts.png").string() << '\n';
  return c.outside_band == 0 ? kSuccess : kInternalError;
}

}  // namespace

Action add_compare_command(CLI::App& app, Streams streams) {
  auto options = std::make_shared<CompareOptions>();
  CLI::App* command = app.add_subcommand(
      "compare",
      "Simulate a scene in Minkowski and Box2D 2.4.1: contact counts (CSV and PNG plot) and the "
      "overlap oracle (exit 1 when a verdict differs outside a 1e-6 band).");
  add_scene_argument(*command, options->scene);
  command->add_option("--steps", options->steps, "steps to run (default 600)")
      ->check(CLI::Range(1LL, 10'000'000LL));
  command->add_option("--out", options->out, "output directory (default out/compare)");
  command->add_option("--every", options->every, "oracle every K steps (default 10)")
      ->check(CLI::Range(1, 1'000'000));
  command->add_option("--gl", options->gl, "headless GL backend for the plot: osmesa or egl");
  return [options, streams] { return run_compare(*options, streams); };
}

}  // namespace mink::cli
