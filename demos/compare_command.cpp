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
#include "line_plot.hpp"
#include "mink/engine/scene_file.hpp"
#include "mink/error.hpp"
#include "mink/render/gl_backend.hpp"
#include "output_files.hpp"
#include "trajectory_compare.hpp"

namespace mink::cli {

namespace {

struct CompareOptions {
  std::string scene = "pyramid";
  long long steps = 600;
  std::string out = "out/compare";
  int every = 10;
  std::string gl = "osmesa";
  bool trajectories = false;  // also without joints
  int box2d_substeps = 0;     // 0: the scene's WorldDef::substeps
  int velocity_iterations = Box2dStepping{}.velocity;
  int position_iterations = Box2dStepping{}.position;
};

constexpr double kBand = 1e-6;

// A built-in's name, or a scene file's name without its folders: plot titles stay short.
std::string plot_name(const std::string& scene) {
  return std::filesystem::path(scene).filename().string();
}

// Contact counts over time.
PlotPanel count_panel(const ContactComparison& c, const std::string& scene) {
  PlotPanel panel;
  panel.title = "contacts over time: " + scene + ", Minkowski vs Box2D 2.4.1 (x: step)";
  panel.whole_numbers = true;
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
  for (const Series& s : series) {
    PlotLine line{s.name, s.color, s.dashed, {}};
    for (const ContactCountRow& row : c.rows)
      line.values.push_back(static_cast<double>(row.*s.field));
    panel.lines.push_back(std::move(line));
  }
  return panel;
}

// Position differences over time and, with pinning joints, both engines' joint gaps.
std::vector<PlotPanel> trajectory_panels(const TrajectoryRecorder& t, const std::string& scene) {
  std::vector<PlotPanel> panels(1);
  panels[0].title = "position difference (m): " + scene + ", Minkowski vs Box2D 2.4.1 (x: step)";
  panels[0].first_step = 0;
  PlotLine max{"max over bodies", {0.85f, 0.2f, 0.1f, 1}, false, {}};
  PlotLine mean{"mean over bodies", {0.1f, 0.3f, 0.85f, 1}, false, {}};
  for (const StepDifference& d : step_differences(t.rows())) {
    max.values.push_back(d.max);
    mean.values.push_back(d.mean);
  }
  panels[0].lines = {std::move(max), std::move(mean)};
  if (!t.gaps().empty()) {
    PlotPanel gaps;
    gaps.title = "joint gap (m, revolute and weld joints summed): " + scene + " (x: step)";
    gaps.first_step = 0;
    PlotLine mink{"Minkowski", {0.1f, 0.3f, 0.85f, 1}, false, {}};
    PlotLine box2d{"Box2D 2.4.1", {0.85f, 0.2f, 0.1f, 1}, false, {}};
    for (const JointGapRow& g : t.gaps()) {
      mink.values.push_back(g.mink);
      box2d.values.push_back(g.box2d);
    }
    gaps.lines = {std::move(mink), std::move(box2d)};
    panels.push_back(std::move(gaps));
  }
  return panels;
}

// Writes trajectories.csv (and joint_gaps.csv) and the plot; prints the summary.
void report_trajectories(const TrajectoryRecorder& t, const CompareOptions& options,
                         const SceneDef& scene, GlBackend backend, std::ostream& out) {
  const std::filesystem::path dir(options.out);
  {
    OutputFile file(dir / "trajectories.csv", "the trajectories");
    std::ostream& csv = file.stream();
    csv << "step,body,mink_x,mink_y,box2d_x,box2d_y,distance\n";
    char line[256];
    for (const TrajectoryRow& row : t.rows()) {
      std::snprintf(line, sizeof line, "%lld,%zu,%.9g,%.9g,%.9g,%.9g,%.9g\n", row.step, row.body,
                    row.mink.x(), row.mink.y(), row.box2d.x(), row.box2d.y(), row.distance);
      csv << line;
    }
    file.commit();
  }
  if (!t.gaps().empty()) {
    OutputFile file(dir / "joint_gaps.csv", "the joint gaps");
    std::ostream& csv = file.stream();
    csv << "step,mink,box2d\n";
    char line[128];
    for (const JointGapRow& g : t.gaps()) {
      std::snprintf(line, sizeof line, "%lld,%.9g,%.9g\n", g.step, g.mink, g.box2d);
      csv << line;
    }
    file.commit();
  }
  write_line_plot(trajectory_panels(t, plot_name(options.scene)), backend,
                  dir / "trajectories.png");

  const double dt = scene.world.time_step;
  const long long second = std::max(1LL, std::llround(1.0 / dt));
  const WorstDifference first = worst_difference(t.rows(), second);
  const WorstDifference all = worst_difference(t.rows(), options.steps);
  char line[400];
  std::snprintf(line, sizeof line,
                "trajectories of %zu dynamic bodies: worst position difference %.3g m over the "
                "first second (body %zu, step %lld), %.3g m over the whole run (body %zu, step "
                "%lld)\n",
                t.body_count(), first.distance, first.body, first.step, all.distance, all.body,
                all.step);
  out << line;
  if (!t.gaps().empty()) {
    double mink = 0, box2d = 0;
    for (const JointGapRow& g : t.gaps()) {
      mink = std::max(mink, g.mink);
      box2d = std::max(box2d, g.box2d);
    }
    std::snprintf(line, sizeof line,
                  "joint gap (revolute and weld joints summed): Minkowski %.3g m at most, %.3g m "
                  "at the end (%.4g s); Box2D 2.4.1 %.3g m at most, %.3g m at the end\n",
                  mink, t.gaps().back().mink, static_cast<double>(options.steps) * dt, box2d,
                  t.gaps().back().box2d);
    out << line;
  }
  out << "wrote " << (dir / "trajectories.csv").string()
      << (t.gaps().empty() ? "" : ", " + (dir / "joint_gaps.csv").string()) << " and "
      << (dir / "trajectories.png").string() << '\n';
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
  const bool trajectories = options.trajectories || !scene.joints.empty();
  TrajectoryRecorder recorder(scene);
  CompareObserver observe;
  if (trajectories) {
    observe = [&recorder](long long step, const World& ours, const interop::Box2dScene& rival) {
      recorder.record(step, ours, rival);
    };
  }
  const Box2dStepping stepping{
      options.box2d_substeps > 0 ? options.box2d_substeps : scene.world.substeps,
      options.velocity_iterations, options.position_iterations};
  const ContactComparison c =
      compare_contacts(scene, options.steps, options.every, kBand, stepping, observe);
  const std::filesystem::path out(options.out);
  make_directories(out, "--out");
  {
    OutputFile file(out / "contacts.csv", "the contact counts");
    std::ostream& csv = file.stream();
    csv << "step,mink_pairs,mink_contacts,box2d_pairs,box2d_touching\n";
    for (const ContactCountRow& row : c.rows) {
      csv << row.step << ',' << row.mink_pairs << ',' << row.mink_contacts << ',' << row.box2d_pairs
          << ',' << row.box2d_touching << '\n';
    }
    file.commit();
  }
  write_line_plot({count_panel(c, plot_name(options.scene))}, backend, out / "contacts.png");

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
                "Box2D 2.4.1 per step: %d b2World::Step of %.4g s, %d velocity and %d position "
                "iterations each\n",
                stepping.substeps, scene.world.time_step / stepping.substeps, stepping.velocity,
                stepping.position);
  streams.out << line;
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
  if (trajectories) report_trajectories(recorder, options, scene, backend, streams.out);
  return c.outside_band == 0 ? kSuccess : kInternalError;
}

}  // namespace

Action add_compare_command(CLI::App& app, Streams streams) {
  auto options = std::make_shared<CompareOptions>();
  CLI::App* command = app.add_subcommand(
      "compare",
      "Simulate a scene in Minkowski and Box2D 2.4.1: contact counts (CSV and PNG plot) and the "
      "overlap oracle (exit 1 when a verdict differs outside a 1e-6 band). A scene with joints "
      "(or --trajectories) also gets every dynamic body's position in both engines per step "
      "(trajectories.csv: step,body,mink_x,mink_y,box2d_x,box2d_y,distance), the summed gap of "
      "its revolute and weld joints (joint_gaps.csv: step,mink,box2d), a plot of both "
      "(trajectories.png) and the worst difference over the first second and the whole run.");
  add_scene_argument(*command, options->scene);
  command->add_option("--steps", options->steps, "steps to run (default 600)")
      ->check(CLI::Range(1LL, 10'000'000LL));
  command->add_option("--out", options->out, "output directory (default out/compare)");
  command->add_option("--every", options->every, "oracle every K steps (default 10)")
      ->check(CLI::Range(1, 1'000'000));
  command->add_option("--gl", options->gl, "headless GL backend for the plot: osmesa or egl");
  command->add_flag("--trajectories", options->trajectories,
                    "compare trajectories for a scene without joints too");
  command
      ->add_option("--box2d-substeps", options->box2d_substeps,
                   "b2World::Step calls per step, each of a substep's time (default: the scene's "
                   "substeps, so both engines integrate at the same rate; 1 is how Box2D 2.4.1 "
                   "is usually run)")
      ->check(CLI::Range(1, 1000));
  command
      ->add_option("--velocity-iterations", options->velocity_iterations,
                   "Box2D 2.4.1 velocity iterations per b2World::Step (default 8)")
      ->check(CLI::Range(1, 1000));
  command
      ->add_option("--position-iterations", options->position_iterations,
                   "Box2D 2.4.1 position iterations per b2World::Step (default 3)")
      ->check(CLI::Range(0, 1000));
  return [options, streams] { return run_compare(*options, streams); };
}

}  // namespace mink::cli
