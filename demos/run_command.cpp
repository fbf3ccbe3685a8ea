#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "body_trace.hpp"
#include "commands.hpp"
#include "event_log.hpp"
#include "exit_codes.hpp"
#include "mink/engine/scene_file.hpp"
#include "mink/engine/scene_schedule.hpp"
#include "mink/error.hpp"
#include "mink/render/frame_sink.hpp"
#include "mink/render/gl_context.hpp"
#include "mink/render/renderer.hpp"
#include "mink/render/world_view.hpp"
#include "output_files.hpp"
#include "recording.hpp"
#include "run_state.hpp"
#include "scene_view.hpp"

namespace mink::cli {

namespace {

struct RunOptions {
  std::string scene = "tumbler_400";
  std::optional<long long> steps;
  std::optional<double> seconds;
  std::string out = "out";
  bool frames = false;
  std::string video;
  double fps = 30;
  std::string stats;
  std::string trace;
  std::uint64_t trace_every = 1;
  std::string events;
  std::string save;
  bool hash = false;
  std::string record;
  std::string gl = "osmesa";
  std::string size = "1280x720";
  int threads = 1;
  std::vector<std::string> world_settings;  // KEY=VALUE, in order
};

// A bar redrawn in place on a terminal; elsewhere (logs, pipes) a line every tenth of the run.
class Progress {
 public:
  Progress(std::ostream& err, long long total)
      : err_(err), total_(total), terminal_(&err == &std::cerr && isatty(STDERR_FILENO) != 0) {}
  void update(long long done) {
    if (terminal_) {
      const int width = 40;
      const int filled = static_cast<int>(width * done / total_);
      if (filled == last_ && done != total_) return;
      last_ = filled;
      err_ << "\r[" << std::string(filled, '#') << std::string(width - filled, '-') << "] " << done
           << '/' << total_ << (done == total_ ? "\n" : "") << std::flush;
    } else {
      const int tenth = static_cast<int>(10 * done / total_);
      if (tenth == last_) return;
      last_ = tenth;
      err_ << "progress: step " << done << " of " << total_ << " (" << 10 * tenth << "%)\n";
    }
  }

 private:
  std::ostream& err_;
  long long total_;
  bool terminal_;
  int last_ = -1;
};

// Counted from the bodies, so the frame before the first step shows it too.
std::size_t awake_bodies(const World& world) {
  std::size_t awake = 0;
  for (BodyId body : world.bodies()) {
    awake += world.body_type(body) != BodyType::static_body && world.is_awake(body);
  }
  return awake;
}

int run_scene(const RunOptions& options, Streams streams) {
  if (!(options.fps >= 1 && options.fps <= 1000)) {
    throw InvalidArgumentError("--fps must be in 1..1000");
  }
  int width = 0;
  int height = 0;
  parse_frame_size(options.size, width, height);
  const GlBackend backend = parse_gl_backend(options.gl);
  // The whole scene is read and checked before any output exists.
  SceneDef scene = resolve_scene(options.scene);
  for (const std::string& setting : options.world_settings) {
    const std::size_t equals = setting.find('=');
    if (equals == std::string::npos || equals == 0) {
      throw InvalidArgumentError(
          "--world takes KEY=VALUE (a key of the scene file's world "
          "object), got '" +
          setting + "'");
    }
    set_world_setting(scene.world, std::string_view(setting).substr(0, equals),
                      std::string_view(setting).substr(equals + 1));
  }
  scene.world.worker_count = options.threads;
  SceneRun run(scene);  // the scene's schedule, if any, runs before each step
  World& world = run.world();
  std::vector<BodyId> bodies = run.ids().bodies;   // body i of the scene is bodies[i]
  std::vector<JointId> joints = run.ids().joints;  // likewise joint i
  // A scene file saved by --save resumes from the state saved beside it, exactly.
  if (!is_builtin_scene(options.scene)) {
    if (std::optional<std::vector<std::uint8_t>> state =
            find_saved_state(options.scene, streams.err)) {
      if (options.world_settings.empty()) {
        world.restore(*state);
        // The file lists the live bodies and joints in slot order.
        bodies = world.bodies();
        joints = world.joints();
      } else {
        streams.err << "notice: --world changes the settings, so "
                    << state_file_for(options.scene).string()
                    << " is not used; contacts start cold\n";
      }
    }
  }
  const Real dt = scene.world.time_step;
  long long steps = 600;
  if (options.steps) steps = *options.steps;
  if (options.seconds) {
    if (!(*options.seconds > 0) || !std::isfinite(*options.seconds)) {
      throw InvalidArgumentError("--seconds must be positive");
    }
    steps = std::llround(*options.seconds / dt);
  }
  if (steps < 1) throw InvalidArgumentError("--steps must be at least 1");

  const std::filesystem::path out(options.out);
  std::unique_ptr<GlContext> context;
  std::unique_ptr<Renderer> renderer;
  std::unique_ptr<FrameSink> png_sink;
  std::unique_ptr<FrameSink> video_sink;
  // --no-render excludes both (the parser enforces it), so it never makes a GL context.
  const bool render = options.frames || !options.video.empty();
  if (render) {
    context = make_offscreen_context(backend, width, height);
    renderer = std::make_unique<Renderer>(*context);
    Vec2 lower;
    Vec2 upper;
    world_bounds(world, lower, upper);
    renderer->camera().fit(lower, upper, 24);
    if (options.frames) png_sink = open_frame_sink(out / "frames", width, height);
    if (!options.video.empty()) {
      VideoOptions video;
      video.fps = static_cast<int>(std::lround(options.fps));
      video_sink = open_frame_sink(options.video, width, height, video);
    }
  }
  // Every output goes to a temporary file until the run is complete: a run stopped part-way
  // leaves what was there before.
  std::optional<OutputFile> stats;
  if (!options.stats.empty()) {
    stats.emplace(options.stats, "--stats file");
    stats->stream()
        << "step,time,bodies,awake,pairs,contacts,kinetic_energy,step_ms,pairs_ms,collide_ms,"
           "islands_ms,prepare_ms,solve_ms,continuous_ms,finish_ms,fast_bodies,continuous_hits\n";
  }
  std::optional<BodyTrace> trace;
  if (!options.trace.empty()) {
    trace.emplace(options.trace, bodies, options.trace_every);
    trace->write_step(world);  // step 0: the initial state
  }
  std::optional<EventLog> events;
  if (!options.events.empty()) events.emplace(options.events, world, bodies, joints);
  // A frame every this many steps keeps video time equal to simulated time.
  const long long frame_every = std::max(1LL, std::llround(1.0 / (options.fps * dt)));
  Image image;
  auto write_frame = [&] {
    char overlay[256];
    std::snprintf(
        overlay, sizeof overlay, "%s  step %llu  t %.2f s\nbodies %zu  awake %zu  contacts %zu",
        options.scene.c_str(), static_cast<unsigned long long>(world.step_count()), world.time(),
        world.body_count(), awake_bodies(world), world.counters().touching_contacts);
    draw_world_frame(*renderer, world, overlay);
    renderer->read_pixels_into(image, 3);
    if (png_sink) png_sink->write(image);
    if (video_sink) video_sink->write(image);
  };
  if (render) write_frame();

  // Records from here: the state now, then every call the run makes (the schedule's
  // included) and every step's hash.
  std::optional<RunRecorder> recorder;
  if (!options.record.empty()) recorder.emplace(world);

  Progress progress(streams.err, steps);
  double total_ms = 0;
  std::size_t contacts_sum = 0;
  long long stopped_steps = 0;  // steps whose solve diverged (World::body_stopped_events)
  const auto started = std::chrono::steady_clock::now();
  char line[256];
  for (long long i = 1; i <= steps; ++i) {
    const auto before = std::chrono::steady_clock::now();
    run.step();
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - before)
            .count();
    total_ms += ms;
    const StepCounters& c = world.counters();
    contacts_sum += c.touching_contacts;
    if (const auto stopped = world.body_stopped_events(); !stopped.empty()) {
      // Said once as it happens, and counted in the summary: the run goes on.
      if (stopped_steps++ == 0) {
        const auto first = std::find_if(stopped.begin(), stopped.end(),
                                        [](const BodyStoppedEvent& e) { return e.diverged; });
        streams.err << "mink: warning: step " << world.step_count()
                    << ": the solve diverged on body slot " << first->body.index << "; "
                    << stopped.size()
                    << " bodies put back where the step began, at rest (constraints beyond "
                       "the single-precision solver: see BodyStoppedEvent)\n";
      }
    }
    if (stats) {
      const StepProfile& p = world.profile();
      std::snprintf(
          line, sizeof line,
          "%llu,%.17g,%zu,%zu,%zu,%zu,%.17g,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%zu,%zu\n",
          static_cast<unsigned long long>(world.step_count()), world.time(), world.body_count(),
          c.awake_bodies, c.broadphase_pairs, c.touching_contacts, kinetic_energy(world), ms,
          p.pairs, p.collide, p.islands, p.prepare, p.solve, p.continuous, p.finish, c.fast_bodies,
          c.continuous_hits);
      stats->stream() << line;
    }
    if (trace) trace->write_step(world);
    if (events) events->write_step(world);
    if (render && i % frame_every == 0) write_frame();
    progress.update(i);
  }
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  if (png_sink) png_sink->close();
  if (video_sink) video_sink->close();
  if (stats) stats->commit();
  if (trace) trace->close();
  if (events) events->close();
  if (!options.save.empty()) save_run(options.save, world);
  if (recorder) save_recording(options.record, recorder->recording());

  streams.out << "scene " << options.scene << '\n';
  std::snprintf(line, sizeof line,
                "steps %lld, simulated %.3f s, wall %.3f s, %.3f ms per step (physics only)\n",
                steps, world.time(), wall, total_ms / static_cast<double>(steps));
  streams.out << line;
  std::snprintf(
      line, sizeof line, "bodies %zu (%zu awake), contacts %zu at the end, %.1f on average\n",
      world.body_count(), world.counters().awake_bodies, world.counters().touching_contacts,
      static_cast<double>(contacts_sum) / static_cast<double>(steps));
  streams.out << line;
  if (stopped_steps > 0) {
    streams.out << "diverged: the solve diverged in " << stopped_steps
                << " steps; their bodies were stopped (warning above)\n";
  }
  if (png_sink) {
    streams.out << "frames: " << png_sink->frames_written() << " PNG files in "
                << (out / "frames").string() << '\n';
  }
  if (video_sink) {
    streams.out << "video: " << options.video << " (" << video_sink->frames_written()
                << " frames at " << std::lround(options.fps) << " fps)\n";
  }
  if (!options.stats.empty()) streams.out << "stats: " << options.stats << '\n';
  if (trace) {
    streams.out << "trace: " << options.trace << " (" << trace->rows_written() << " rows)\n";
  }
  if (events) {
    streams.out << "events: " << options.events << " (" << events->events_written() << " events)\n";
  }
  if (!options.save.empty()) {
    streams.out << "saved: " << options.save << " (state: " << state_file_for(options.save).string()
                << ")\n";
  }
  if (recorder) {
    streams.out << "recorded: " << options.record << " (" << recorder->steps() << " steps)\n";
  }
  if (options.hash) {
    std::snprintf(line, sizeof line, "state hash %016llx at step %llu\n",
                  static_cast<unsigned long long>(world.state_hash()),
                  static_cast<unsigned long long>(world.step_count()));
    streams.out << line;
  }
  return kSuccess;
}

}  // namespace

Action add_run_command(CLI::App& app, Streams streams) {
  auto options = std::make_shared<RunOptions>();
  CLI::App* command = app.add_subcommand("run",
                                         "Run a scene (a built-in name or a scene file) headless: "
                                         "frames, video, stats, traces, events.");
  add_scene_argument(*command, options->scene);
  auto* steps = command->add_option("--steps", options->steps, "steps to run (default 600)");
  command->add_option("--seconds", options->seconds, "simulated seconds to run")->excludes(steps);
  command->add_option("--out", options->out, "directory for --frames (default out)");
  auto* frames =
      command->add_flag("--frames", options->frames, "write every frame as a PNG in OUT/frames");
  auto* video =
      command->add_option("--video", options->video, "write the run as a video (e.g. demo.mp4)");
  command->add_option("--fps", options->fps, "frames per simulated second (default 30)");
  command->add_option("--stats", options->stats, "per-step statistics CSV");
  auto* trace = command->add_option(
      "--trace", options->trace,
      "per-body CSV for plotting: step,body,x,y,angle,vx,vy,w (step 0 is the initial state)");
  command->add_option("--trace-every", options->trace_every, "trace every K-th step (default 1)")
      ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1'000'000'000}))
      ->needs(trace);
  command->add_option("--events", options->events,
                      "events as JSON Lines: step, type (contact_begin, contact_end, hit, "
                      "sensor_begin, sensor_end, joint_break, body_stopped), shape_a, shape_b "
                      "or joint or body, body_a, body_b");
  command->add_option("--save", options->save,
                      "write the final world as a scene file FILE, and its solver state as "
                      "FILE.state beside it: `mink run FILE` resumes exactly");
  command->add_option("--record", options->record,
                      "record the run (its initial state, every call that changes the world, "
                      "each step's state hash) for `mink replay FILE`");
  command->add_flag("--hash", options->hash,
                    "print the final state hash (World::state_hash), equal for equal states");
  command->add_flag("--no-render")
      ->description("no GL at all, not even loaded: statistics, traces and events only")
      ->excludes(frames)
      ->excludes(video);
  command->add_option("--gl", options->gl, "headless GL backend: osmesa (default) or egl");
  command->add_option("--size", options->size, "frame size WIDTHxHEIGHT (default 1280x720)");
  command
      ->add_option("--threads", options->threads,
                   "workers the step runs on, this thread among them (default 1); the results "
                   "are bitwise the same at any count")
      ->check(CLI::Range(1, 256));
  command
      ->add_option("--world", options->world_settings,
                   "a world setting as KEY=VALUE, keys and values as in the scene file's "
                   "world object (e.g. --world substeps=4 --world enable_sleep=false); "
                   "repeatable, applied in order over the scene's own")
      ->allow_extra_args(false);  // one setting per --world: the scene may follow it
  return [options, streams] { return run_scene(*options, streams); };
}

namespace {

struct ReplayOptions {
  std::string file;
  int threads = 1;
};

int replay_file(const ReplayOptions& options, Streams streams) {
  const Recording recording = load_recording(options.file);
  const ReplayResult result = replay(recording, options.threads);
  if (result.diverged_at) {
    char line[160];
    std::snprintf(line, sizeof line,
                  "diverged at step %llu: recorded state hash %016llx, replayed %016llx\n",
                  static_cast<unsigned long long>(*result.diverged_at),
                  static_cast<unsigned long long>(result.recorded_hash),
                  static_cast<unsigned long long>(result.replayed_hash));
    streams.out << "replayed " << result.steps << " steps from step " << result.first_step
                << " with equal hashes, then\n"
                << line;
    return kDiverged;
  }
  streams.out << "replayed " << result.steps << " steps from step " << result.first_step
              << ": every state hash equals the recording's\n";
  return kSuccess;
}

}  // namespace

Action add_replay_command(CLI::App& app, Streams streams) {
  auto options = std::make_shared<ReplayOptions>();
  CLI::App* command = app.add_subcommand("replay",
                                         "Replay a recording (mink run or mink sandbox --record) "
                                         "and check the state hash of every step; exit "
                                         "code 6 names the first step that diverges.");
  command->add_option("file", options->file, "the recording")->required();
  command
      ->add_option("--threads", options->threads,
                   "workers the replay runs on (default 1); any count must agree")
      ->check(CLI::Range(1, 256));
  return [options, streams] { return replay_file(*options, streams); };
}

}  // namespace mink::cli
