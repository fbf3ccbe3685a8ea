#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "event_log.hpp"
#include "exit_codes.hpp"
#include "mink/engine/scene_file.hpp"
#include "mink/engine/world.hpp"
#include "mink/render/render_error.hpp"
#include "recording.hpp"

namespace {

using namespace mink;
using namespace mink_test;

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    lines.push_back(text.substr(start, end - start));
    start = end == std::string::npos ? text.size() : end + 1;
  }
  return lines;
}

TEST(RunCommand, StatsCsvHasOneRowPerStepAndTheIssueColumns) {
  const auto dir = fresh_dir("stats");
  const CliResult r = run_cli(
      {"run", "pyramid", "--steps", "30", "--no-render", "--stats", (dir / "stats.csv").string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto lines = split_lines(read_text(dir / "stats.csv"));
  ASSERT_EQ(lines.size(), 31u);
  EXPECT_EQ(lines[0],
            "step,time,bodies,awake,pairs,contacts,kinetic_energy,step_ms,pairs_ms,collide_ms,"
            "islands_ms,prepare_ms,solve_ms,continuous_ms,finish_ms,fast_bodies,continuous_hits");
  const std::size_t bodies = builtin_scene("pyramid").bodies.size();
  for (std::size_t i = 1; i < lines.size(); ++i) {
    unsigned long long step = 0;
    double time = 0, energy = 0, ms = 0;
    std::size_t count = 0, awake = 0, pairs = 0, contacts = 0;
    ASSERT_EQ(std::sscanf(lines[i].c_str(), "%llu,%lf,%zu,%zu,%zu,%zu,%lf,%lf", &step, &time,
                          &count, &awake, &pairs, &contacts, &energy, &ms),
              8)
        << lines[i];
    EXPECT_EQ(step, i);
    EXPECT_NEAR(time, static_cast<double>(i) / 60.0, 1e-12);
    EXPECT_EQ(count, bodies);
    EXPECT_LE(awake, bodies);
    EXPECT_LE(contacts, pairs);
    EXPECT_GE(energy, 0);
    EXPECT_GE(ms, 0);
  }
  // The summary names steps, simulated time and bodies.
  EXPECT_NE(r.out.find("steps 30, simulated 0.500 s"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("bodies " + std::to_string(bodies)), std::string::npos) << r.out;
  // Not a terminal here: plain progress lines.
  EXPECT_NE(r.err.find("progress: step 30 of 30 (100%)"), std::string::npos) << r.err;
}

// rain's schedule drops 25 ragdolls (275 bodies) before steps 0, 8, 16, ...: `mink run` runs
// it, and the stats count what it made. The trace has the scene's own body, the ground.
TEST(RunCommand, RunsTheScenesScheduleBeforeEachStep) {
  const auto dir = fresh_dir("schedule");
  const CliResult r =
      run_cli({"run", "rain", "--steps", "17", "--no-render", "--stats",
               (dir / "stats.csv").string(), "--trace", (dir / "trace.csv").string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto lines = split_lines(read_text(dir / "stats.csv"));
  ASSERT_EQ(lines.size(), 18u);
  for (std::size_t step = 1; step <= 17; ++step) {
    unsigned long long at = 0;
    std::size_t bodies = 0;
    ASSERT_EQ(std::sscanf(lines[step].c_str(), "%llu,%*[^,],%zu", &at, &bodies), 2) << lines[step];
    EXPECT_EQ(bodies, 1 + 275 * ((step - 1) / 8 + 1)) << lines[step];
  }
  EXPECT_NE(r.out.find("bodies 826 "), std::string::npos) << r.out;
  EXPECT_EQ(split_lines(read_text(dir / "trace.csv")).size(), 1u + 18u);  // steps 0..17
}

std::vector<double> parse_numbers(const std::string& row) {
  std::vector<double> numbers;
  std::istringstream in(row);
  std::string field;
  while (std::getline(in, field, ',')) numbers.push_back(std::stod(field));
  return numbers;
}

// The trace is the in-process run's state exactly: step 0, then every K-th step.
TEST(RunCommand, TraceHasEveryBodyAtStepZeroAndEveryKthStep) {
  const auto dir = fresh_dir("trace");
  const auto trace = (dir / "trace.csv").string();
  const CliResult r = run_cli(
      {"run", "pyramid", "--steps", "7", "--no-render", "--trace", trace, "--trace-every", "3"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto lines = split_lines(read_text(trace));
  const SceneDef scene = builtin_scene("pyramid");
  const std::size_t bodies = scene.bodies.size();
  ASSERT_EQ(lines.size(), 1 + 3 * bodies);  // steps 0, 3 and 6
  EXPECT_EQ(lines[0], "step,body,x,y,angle,vx,vy,w");
  EXPECT_NE(r.out.find("trace: " + trace + " (" + std::to_string(3 * bodies) + " rows)"),
            std::string::npos)
      << r.out;
  World world = build_world(scene);
  const auto ids = world.bodies();
  std::size_t line = 1;
  for (int step = 0; step <= 6; ++step) {
    if (step > 0) world.step();
    if (step % 3 != 0) continue;
    for (std::size_t i = 0; i < bodies; ++i, ++line) {
      const std::vector<double> row = parse_numbers(lines[line]);
      ASSERT_EQ(row.size(), 8u) << lines[line];
      EXPECT_EQ(row[0], step);
      EXPECT_EQ(row[1], static_cast<double>(i));
      // Pyramid boxes have their centre of mass at the origin: the origin's velocity is the
      // world's linear velocity.
      const std::vector<double> want = {world.position(ids[i]).x(),
                                        world.position(ids[i]).y(),
                                        world.angle(ids[i]),
                                        world.linear_velocity(ids[i]).x(),
                                        world.linear_velocity(ids[i]).y(),
                                        world.angular_velocity(ids[i])};
      for (std::size_t k = 0; k < want.size(); ++k) {
        EXPECT_EQ(row[2 + k], want[k]) << lines[line];  // 17 digits: exact round trip
      }
    }
  }
}

// vx, vy are the origin's velocity, as in scene files: a body spinning about its origin, with
// its mass off to one side, starts with an origin at rest.
TEST(RunCommand, TraceVelocityIsTheOriginsAsInSceneFiles) {
  const auto dir = fresh_dir("trace_origin");
  SceneDef scene;
  scene.world.gravity = Vec2(0, 0);
  SceneBody body;
  body.body.type = BodyType::dynamic;
  body.body.position = Vec2(1, 1);
  body.body.angular_velocity = 1;
  body.shapes.push_back(ShapeDef::box(0.5, 0.5, Vec2(2, 0)));
  scene.bodies.push_back(body);
  save_scene_file(dir / "spin.json", scene);
  const auto trace = (dir / "trace.csv").string();
  const CliResult r = run_cli(
      {"run", (dir / "spin.json").string(), "--steps", "1", "--no-render", "--trace", trace});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto lines = split_lines(read_text(trace));
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(parse_numbers(lines[1]), (std::vector<double>{0, 0, 1, 1, 0, 0, 0, 1}));
  // A step later the origin has swung about the centre of mass, which moves at (0, 2): the
  // origin's velocity is that plus w x (origin - centre), with w still 1. The centre's motion
  // and the origin's offset from it are each rounded to the position grid.
  const std::vector<double> after = parse_numbers(lines[2]);
  const double turned = after[4];
  EXPECT_GT(turned, 0);
  EXPECT_NEAR(after[5], 2 * std::sin(turned), 2 * position_grid_step);
  EXPECT_NEAR(after[6], 2 - 2 * std::cos(turned), 2 * position_grid_step);
}

struct EventLine {
  std::uint64_t step;
  std::string type;
  std::size_t shape_a, shape_b, body_a, body_b;
  bool operator==(const EventLine&) const = default;
};

std::ostream& operator<<(std::ostream& out, const EventLine& e) {
  return out << e.step << ' ' << e.type << ' ' << e.shape_a << ' ' << e.shape_b << ' ' << e.body_a
             << ' ' << e.body_b;
}

// The events file lists the in-process run's events, step by step, bodies by index: contacts
// (begin events with their manifold), hits and sensor events, in the `shapes` scene, which has
// a sensor band.
TEST(RunCommand, EventsAreTheWorldsEventsAsJsonLines) {
  const auto dir = fresh_dir("events");
  const auto events = (dir / "events.jsonl").string();
  SceneDef scene = builtin_scene("shapes");
  for (SceneBody& body : scene.bodies) {
    for (ShapeDef& shape : body.shapes) shape.enable_hit_events = true;
  }
  const auto scene_path = (dir / "shapes.json").string();
  save_scene_file(scene_path, scene);
  const CliResult r =
      run_cli({"run", scene_path, "--steps", "120", "--no-render", "--events", events});
  ASSERT_EQ(r.code, 0) << r.err;
  std::vector<EventLine> got;
  std::vector<nlohmann::json> begins, hits;
  for (const std::string& line : split_lines(read_text(events))) {
    const auto json = nlohmann::json::parse(line);
    got.push_back({json.at("step").get<std::uint64_t>(), json.at("type").get<std::string>(),
                   json.at("shape_a").get<std::size_t>(), json.at("shape_b").get<std::size_t>(),
                   json.at("body_a").get<std::size_t>(), json.at("body_b").get<std::size_t>()});
    if (json.at("type") == "contact_begin") begins.push_back(json);
    if (json.at("type") == "hit") hits.push_back(json);
  }
  World world = build_world(scene);
  const auto ids = world.bodies();
  const auto index = [&](ShapeId shape) {
    return static_cast<std::size_t>(std::find(ids.begin(), ids.end(), world.shape_body(shape)) -
                                    ids.begin());
  };
  std::vector<EventLine> want;
  std::vector<Manifold> manifolds;
  std::vector<ContactHitEvent> hit_events;
  std::size_t ends = 0, sensor_events = 0;
  const auto add = [&](std::string_view type, ShapeId a, ShapeId b) {
    want.push_back({world.step_count(), std::string(type), a.index, b.index, index(a), index(b)});
  };
  for (int step = 1; step <= 120; ++step) {
    world.step();
    for (const ContactBeginEvent& e : world.contact_begin_events()) {
      add("contact_begin", e.shape_a, e.shape_b);
      manifolds.push_back(e.manifold);
    }
    for (const ContactEndEvent& e : world.contact_end_events()) {
      add("contact_end", e.shape_a, e.shape_b);
      ++ends;
    }
    for (const ContactHitEvent& e : world.contact_hit_events()) {
      add("hit", e.shape_a, e.shape_b);
      hit_events.push_back(e);
    }
    for (const SensorBeginEvent& e : world.sensor_begin_events()) {
      add("sensor_begin", e.sensor, e.visitor);
      ++sensor_events;
    }
    for (const SensorEndEvent& e : world.sensor_end_events()) {
      add("sensor_end", e.sensor, e.visitor);
      ++sensor_events;
    }
  }
  EXPECT_GT(ends, 0u);  // every kind is exercised
  EXPECT_GT(sensor_events, 0u);
  EXPECT_FALSE(hit_events.empty());
  EXPECT_EQ(got, want);
  ASSERT_EQ(begins.size(), manifolds.size());
  for (std::size_t i = 0; i < begins.size(); ++i) {
    const Manifold& m = manifolds[i];
    EXPECT_EQ(begins[i].at("normal"), nlohmann::json::array({m.normal.x(), m.normal.y()}));
    ASSERT_EQ(begins[i].at("points").size(), static_cast<std::size_t>(m.point_count));
    for (int j = 0; j < m.point_count; ++j) {
      const ManifoldPoint& p = m.points[static_cast<std::size_t>(j)];
      EXPECT_EQ(begins[i].at("points")[j], nlohmann::json::array({p.point.x(), p.point.y()}));
      EXPECT_EQ(begins[i].at("separations")[j], p.separation);
    }
  }
  ASSERT_EQ(hits.size(), hit_events.size());
  for (std::size_t i = 0; i < hits.size(); ++i) {
    EXPECT_EQ(hits[i].at("speed"), hit_events[i].approach_speed);
    EXPECT_EQ(hits[i].at("point"),
              nlohmann::json::array({hit_events[i].point.x(), hit_events[i].point.y()}));
  }
}

// joint_break lines are the world's joint break events, joints and bodies by scene index, with
// the force and torque exactly: the chain with a threshold on every other joint (the others
// never report).
TEST(RunCommand, EventsReportJointBreaksByJointIndex) {
  const auto dir = fresh_dir("joint_events");
  const auto events = (dir / "events.jsonl").string();
  SceneDef scene = builtin_scene("chain");
  for (std::size_t i = 0; i < scene.joints.size(); i += 2) {
    std::visit([](auto& def) { def.break_force = 120; }, scene.joints[i].def);
  }
  const auto scene_path = (dir / "chain.json").string();
  save_scene_file(scene_path, scene);
  const CliResult r =
      run_cli({"run", scene_path, "--steps", "90", "--no-render", "--events", events});
  ASSERT_EQ(r.code, 0) << r.err;
  std::vector<nlohmann::json> got;
  for (const std::string& line : split_lines(read_text(events))) {
    const auto json = nlohmann::json::parse(line);
    if (json.at("type") == "joint_break") got.push_back(json);
  }
  World world = build_world(scene);
  const auto bodies = world.bodies();
  const auto joints = world.joints();
  const auto index = [](const auto& ids, auto id) {
    return static_cast<std::size_t>(std::find(ids.begin(), ids.end(), id) - ids.begin());
  };
  std::vector<nlohmann::json> want;
  for (int i = 0; i < 90; ++i) {
    world.step();
    for (const JointBreakEvent& e : world.joint_break_events()) {
      const std::size_t joint = index(joints, e.joint);
      EXPECT_EQ(joint % 2, 0u) << "joint " << joint << " has no threshold";
      want.push_back({{"step", world.step_count()},
                      {"type", "joint_break"},
                      {"joint", joint},
                      {"body_a", index(bodies, world.joint_body_a(e.joint))},
                      {"body_b", index(bodies, world.joint_body_b(e.joint))},
                      {"force", {e.force.x(), e.force.y()}},
                      {"torque", e.torque}});
    }
  }
  EXPECT_FALSE(want.empty());
  EXPECT_LT(want.size(), 90u * 16u);  // not every thresholded joint at every step
  EXPECT_EQ(got, want);
  ASSERT_FALSE(got.empty());
  EXPECT_EQ(got.front().at("body_b"), got.front().at("joint").get<std::size_t>() + 1)
      << "the chain's joint i holds link i, body i + 1";
}

// A solve that diverges is said once on stderr, counted in the summary, and each stopped body
// is a body_stopped line as the world reports it; the run goes on and succeeds.
TEST(RunCommand, ADivergedSolveIsAWarningAndBodyStoppedLines) {
  const auto dir = fresh_dir("diverged");
  const auto events = (dir / "events.jsonl").string();
  const std::string scene_path = MINK_FUZZ_CORPUS_DIR "/scene_reader/far_hinge_300m.json";
  const CliResult r =
      run_cli({"run", scene_path, "--steps", "30", "--no-render", "--events", events});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err.find("the solve diverged"), r.err.rfind("the solve diverged")) << r.err;
  EXPECT_NE(r.err.find("warning: step"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("diverged: the solve diverged in"), std::string::npos) << r.out;
  std::vector<nlohmann::json> got;
  for (const std::string& line : split_lines(read_text(events))) {
    const auto json = nlohmann::json::parse(line);
    if (json.at("type") == "body_stopped") got.push_back(json);
  }
  World world = build_world(load_scene_file(scene_path));
  const auto bodies = world.bodies();
  std::vector<nlohmann::json> want;
  for (int i = 0; i < 30; ++i) {
    world.step();
    for (const BodyStoppedEvent& e : world.body_stopped_events()) {
      const auto index = std::find(bodies.begin(), bodies.end(), e.body) - bodies.begin();
      want.push_back({{"step", world.step_count()},
                      {"type", "body_stopped"},
                      {"body", index},
                      {"diverged", e.diverged}});
    }
  }
  EXPECT_FALSE(want.empty());
  EXPECT_EQ(got, want);
}

// An end event may name a shape destroyed since: the log still names its body, from the
// start of the run, and does not reach into the world for it.
TEST(EventLog, EndEventsOfDestroyedShapesKeepTheirBodies) {
  const auto dir = fresh_dir("event_log");
  SceneDef scene = pyramid_scene(2);  // ground, two boxes, one on top
  World world = build_world(scene);
  const auto ids = world.bodies();
  cli::EventLog log(dir / "events.jsonl", world, ids);
  for (int i = 0; i < 5; ++i) {
    world.step();
    log.write_step(world);
  }
  const ShapeId top = world.body_shapes(ids[3])[0];
  world.destroy_body(ids[3]);
  ASSERT_FALSE(world.is_valid(top));
  ASSERT_FALSE(world.contact_end_events().empty());
  log.write_step(world);
  log.close();
  std::size_t ends = 0;
  for (const std::string& line : split_lines(read_text(dir / "events.jsonl"))) {
    const auto json = nlohmann::json::parse(line);
    if (json.at("type") != "contact_end") continue;
    ++ends;
    EXPECT_EQ(json.at("step"), 5);
    const bool top_is_a = json.at("shape_a") == top.index;
    EXPECT_TRUE(top_is_a || json.at("shape_b") == top.index) << line;
    EXPECT_EQ(json.at(top_is_a ? "body_a" : "body_b"), 3) << line;
    EXPECT_TRUE(json.contains("body_a") && json.contains("body_b")) << line;
  }
  EXPECT_EQ(ends, world.contact_end_events().size());
}

// Each bad command line exits 2 and says what is wrong, naming the options or values at fault.
TEST(RunCommand, SecondsAndStepsAreExclusiveAndBadOptionsExit2) {
  const auto expect_usage_error = [](std::vector<std::string> args,
                                     std::vector<std::string> mentions) {
    args.insert(args.begin(), "run");
    const CliResult r = run_cli(args);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_EQ(r.err.rfind("mink: ", 0), 0u) << r.err;
    for (const std::string& mention : mentions) {
      EXPECT_NE(r.err.find(mention), std::string::npos) << "no '" << mention << "' in " << r.err;
    }
  };
  expect_usage_error({"pyramid", "--steps", "3", "--seconds", "1", "--no-render"},
                     {"--steps", "--seconds", "excludes"});
  expect_usage_error({"no_such_scene", "--no-render"},
                     {"'no_such_scene' is neither a built-in scene", "tumbler", "scene file"});
  expect_usage_error({"pyramid", "--no-render", "--frames"}, {"--no-render", "--frames"});
  expect_usage_error({"pyramid", "--no-render", "--video", "x.mp4"}, {"--no-render", "--video"});
  expect_usage_error({"pyramid", "--size", "101x100", "--frames"},
                     {"--size '101x100'", "both even and in 64..8192"});
  expect_usage_error({"pyramid", "--trace-every", "2"}, {"--trace-every", "--trace"});
  expect_usage_error({"pyramid", "--trace", "t.csv", "--trace-every", "0"}, {"--trace-every"});
  expect_usage_error({"pyramid", "--no-render", "--threads", "0"}, {"--threads"});
  expect_usage_error({"pyramid", "--no-render", "--world", "substeps"},
                     {"--world takes KEY=VALUE", "'substeps'"});
  expect_usage_error({"pyramid", "--no-render", "--world", "sub_steps=4"},
                     {"world.sub_steps: unknown key"});
  expect_usage_error({"pyramid", "--no-render", "--world", "substeps=0"},
                     {"world.substeps", "1..1000"});
  expect_usage_error({"pyramid", "--no-render", "--world", "enable_sleep=maybe"},
                     {"world.enable_sleep", "not valid JSON"});
}

// --world changes the scene's settings before the run, in order, and a saved run keeps them.
TEST(RunCommand, WorldSettingsApplyToAnyScene) {
  const auto dir = fresh_dir("world_settings");
  const CliResult r =
      run_cli({"run", "--world", "substeps=4", "--world", "contact_hertz=30", "--world",
               "substeps=3", "--world", "gravity=[0,-9.8]", "--world", "enable_sleep=false",
               "pyramid", "--steps", "2", "--no-render", "--save", (dir / "s.json").string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const WorldDef world = load_scene_file(dir / "s.json").world;
  EXPECT_EQ(world.substeps, 3);
  EXPECT_EQ(world.contact_hertz, 30);
  EXPECT_EQ(world.gravity, Vec2(0, -9.8));
  EXPECT_FALSE(world.enable_sleep);
}

// Any worker count gives the same run: the traces are byte for byte equal.
TEST(RunCommand, ThreadsGiveTheSameTrace) {
  const auto dir = fresh_dir("threads");
  std::string traces[3];
  for (int i = 0; i < 3; ++i) {
    const auto file = dir / ("trace" + std::to_string(i) + ".csv");
    const CliResult r =
        run_cli({"run", "tumbler_400", "--steps", "120", "--no-render", "--threads",
                 std::to_string(i + 1), "--trace", file.string(), "--trace-every", "10"});
    ASSERT_EQ(r.code, 0) << r.err;
    traces[i] = read_text(file);
  }
  EXPECT_GT(traces[0].size(), 10000u);
  EXPECT_EQ(traces[1], traces[0]);
  EXPECT_EQ(traces[2], traces[0]);
}

// The file system failing is exit 5 with the path named, and nothing is run first.
TEST(RunCommand, UnwritableOutputsExit5NamingThePath) {
  const auto dir = fresh_dir("unwritable");
  const auto file = (dir / "plain_file").string();
  write_text(file, "not a directory\n");
  const auto expect_runtime_failure = [](const std::vector<std::string>& args,
                                         const std::string& mention) {
    std::vector<std::string> full = {"run", "pyramid", "--steps", "2", "--no-render"};
    full.insert(full.end(), args.begin(), args.end());
    const CliResult r = run_cli(full);
    EXPECT_EQ(r.code, 5) << r.err;
    EXPECT_NE(r.err.find(mention), std::string::npos) << "no '" << mention << "' in " << r.err;
  };
  // A directory under a regular file cannot be made.
  expect_runtime_failure({"--stats", file + "/sub/stats.csv"},
                         "cannot create the directory '" + file + "/sub' for --stats file");
  expect_runtime_failure({"--trace", file + "/trace.csv"},
                         "cannot create the directory '" + file + "' for --trace file");
  expect_runtime_failure({"--save", file + "/end.json"},
                         "cannot create the directory '" + file + "' for --save state file");
  // A directory where the file should be cannot be written (even by root).
  expect_runtime_failure({"--stats", dir.string()},
                         "cannot write --stats file '" + dir.string() + "': Is a directory");
  expect_runtime_failure({"--events", dir.string()},
                         "cannot write --events file '" + dir.string() + "': Is a directory");
}

TEST(RunCommand, FrameDirectoryUnderAFileExits5) {
  const auto dir = fresh_dir("frames_under_file");
  const auto file = dir / "plain_file";
  write_text(file, "not a directory\n");
  const CliResult r = run_cli({"run", "pyramid", "--steps", "2", "--frames", "--size", "64x64",
                               "--out", (file / "out").string()});
  EXPECT_EQ(r.code, 5) << r.err;
  EXPECT_NE(r.err.find("cannot make the frame directory " + (file / "out" / "frames").string()),
            std::string::npos)
      << r.err;
}

TEST(ExitCodes, EnvironmentFailuresAreRuntimeFailures) {
  std::ostringstream err;
  EXPECT_EQ(cli::report_error(GlContextError("osmesa backend: cannot open libOSMesa.so.8"), err),
            cli::kRuntimeFailure);
  EXPECT_EQ(cli::report_error(OutputError("cannot start ffmpeg"), err), cli::kRuntimeFailure);
  EXPECT_EQ(cli::report_error(std::filesystem::filesystem_error(
                                  "mkdir", std::make_error_code(std::errc::not_a_directory)),
                              err),
            cli::kRuntimeFailure);
  EXPECT_EQ(cli::report_error(FileWriteError("cannot write x: No space left on device"), err),
            cli::kOutputFailure);
  EXPECT_EQ(cli::report_error(InvalidArgumentError("bad"), err), cli::kBadInput);
  EXPECT_EQ(cli::report_error(DegenerateInputError("flat"), err), cli::kDegenerate);
  EXPECT_EQ(cli::report_error(std::logic_error("bug"), err), cli::kInternalError);
  EXPECT_NE(err.str().find("mink: osmesa backend: cannot open libOSMesa.so.8\n"),
            std::string::npos);
}

// `mink` as a process, its standard error captured, with `environment` before the command.
CliResult run_process(const std::string& environment, const std::string& args,
                      const std::filesystem::path& dir) {
  const auto out = dir / "stdout.txt";
  const auto err = dir / "stderr.txt";
  const std::string command = environment + " '" + std::string(MINK_BINARY) + "' " + args + " > '" +
                              out.string() + "' 2> '" + err.string() + "'";
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_text(out), read_text(err)};
}

// --no-render loads no GL library at all (the dynamic loader's log says what was loaded);
// the same run with --frames does, which shows the log would tell.
TEST(RunCommand, NoRenderLoadsNoGlLibrary) {
  const auto dir = fresh_dir("no_gl");
  const CliResult plain = run_process("LD_DEBUG=libs", "run pyramid --steps 2 --no-render", dir);
  ASSERT_EQ(plain.code, 0) << plain.err;
  EXPECT_NE(plain.err.find("libstdc++"), std::string::npos);  // the log is there
  EXPECT_EQ(plain.err.find("libOSMesa"), std::string::npos);
  EXPECT_EQ(plain.err.find("libEGL.so"), std::string::npos);
  const CliResult drawn = run_process(
      "LD_DEBUG=libs",
      "run pyramid --steps 2 --frames --size 64x64 --out '" + (dir / "out").string() + "'", dir);
  ASSERT_EQ(drawn.code, 0) << drawn.err;
  EXPECT_NE(drawn.err.find("libOSMesa"), std::string::npos);
}

TEST(RunCommand, MissingFfmpegExits4) {
  const auto dir = fresh_dir("no_ffmpeg");
  const CliResult r = run_process(
      "PATH=/nonexistent",
      "run pyramid --steps 2 --size 64x64 --video '" + (dir / "run.mp4").string() + "'", dir);
  EXPECT_EQ(r.code, 4) << r.err;
  EXPECT_NE(r.err.find("mink: cannot start ffmpeg"), std::string::npos) << r.err;
}

// The "state hash H at step N" line --hash prints.
std::string hash_line(const CliResult& r) {
  const std::size_t at = r.out.find("state hash ");
  return at == std::string::npos ? std::string("none in: " + r.out)
                                 : r.out.substr(at, r.out.find('\n', at) - at);
}

// Resuming from --save is exact: the scene file carries the poses and velocities, FILE.state
// beside it the rest (warm-start impulses, contact points, sleep timers, the broadphase's
// order), so 90 steps, a save and 60 resumed steps end in the state of 150 uninterrupted steps,
// bitwise, at any worker count. At step 90 rain_mixed has bodies in flight and contacts
// sliding, which a cold start would change at once.
TEST(RunCommand, SaveThenResumeEndsInTheUninterruptedState) {
  World direct = build_world(builtin_scene("rain_mixed"));
  for (int i = 0; i < 90; ++i) direct.step();
  std::size_t flying = 0, sliding = 0;
  for (const BodyId id : direct.bodies()) {
    if (direct.body_type(id) != BodyType::dynamic) continue;
    const std::vector<ContactData> contacts = direct.body_contacts(id);
    const Real speed = direct.linear_velocity(id).norm();
    if (contacts.empty() && speed > 1) ++flying;
    for (const ContactData& c : contacts) {
      const Vec2 tangent(-c.manifold.normal.y(), c.manifold.normal.x());
      if (c.manifold.point_count > 0 && std::abs(direct.linear_velocity(id).dot(tangent)) > 0.05) {
        ++sliding;
      }
    }
  }
  ASSERT_GT(flying, 10u);
  ASSERT_GT(sliding, 10u);

  const auto dir = fresh_dir("resume");
  const auto half = (dir / "half.json").string();
  CliResult r = run_cli({"run", "rain_mixed", "--steps", "90", "--no-render", "--save", half});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(half + ".state"));
  EXPECT_NE(r.out.find("saved: " + half + " (state: " + half + ".state)"), std::string::npos);
  const CliResult whole = run_cli({"run", "rain_mixed", "--steps", "150", "--no-render", "--hash",
                                   "--save", (dir / "whole.json").string()});
  ASSERT_EQ(whole.code, 0) << whole.err;
  EXPECT_NE(hash_line(whole).find("at step 150"), std::string::npos) << whole.out;
  for (const char* threads : {"1", "2"}) {
    const auto end = (dir / (std::string("end") + threads + ".json")).string();
    r = run_cli({"run", half, "--steps", "60", "--no-render", "--hash", "--threads", threads,
                 "--save", end});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err.find("notice"), std::string::npos) << r.err;
    EXPECT_EQ(hash_line(r), hash_line(whole)) << threads << " threads";
    EXPECT_EQ(read_text(end), read_text(dir / "whole.json"));
  }
  // Without the state the run starts its contacts cold, and ends elsewhere.
  const auto copy = (dir / "copy.json").string();
  std::filesystem::copy_file(half, copy);
  r = run_cli({"run", copy, "--steps", "60", "--no-render", "--hash"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(hash_line(r), hash_line(whole));
  // A scene edited after saving still loads, cold, with a notice saying so.
  {
    std::ofstream edit(half, std::ios::app);
    edit << "\n";
  }
  r = run_cli({"run", half, "--steps", "60", "--no-render", "--hash"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("notice: " + half + " changed since " + half + ".state was saved"),
            std::string::npos)
      << r.err;
  EXPECT_NE(hash_line(r), hash_line(whole));
  // A state file that is not one is refused as bad input.
  {
    std::ofstream junk(copy + ".state", std::ios::binary);
    junk << "not a state";
  }
  r = run_cli({"run", copy, "--steps", "1", "--no-render"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("not a state file"), std::string::npos) << r.err;
}

// A recorded run replays with the recorded hash at every step (the schedule's ragdolls made
// and destroyed through the recorded calls); a tampered hash is named as the first divergence.
TEST(RunCommand, RecordThenReplay) {
  const auto dir = fresh_dir("record");
  const auto file = (dir / "rain.rec").string();
  CliResult r = run_cli({"run", "rain", "--steps", "20", "--no-render", "--record", file});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("recorded: " + file + " (20 steps)"), std::string::npos) << r.out;
  r = run_cli({"replay", file, "--threads", "2"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("replayed 20 steps from step 0: every state hash equals"), std::string::npos)
      << r.out;
  cli::Recording recording = cli::load_recording(file);
  for (cli::Recording::Entry& entry : recording.entries) {
    if (entry.is_step && entry.step == 13) entry.hash ^= 1;
  }
  cli::save_recording(file, recording);
  r = run_cli({"replay", file});
  EXPECT_EQ(r.code, 6);
  EXPECT_NE(r.out.find("replayed 12 steps"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("diverged at step 13"), std::string::npos) << r.out;
}

bool have_program(const char* name) {
  return std::system((std::string("command -v ") + name + " > /dev/null 2>&1").c_str()) == 0;
}

TEST(RunCommand, FramesAndVideoOfAShortRun) {
  if (!have_program("ffmpeg") || !have_program("ffprobe")) GTEST_SKIP() << "no ffmpeg/ffprobe";
  const auto dir = fresh_dir("video");
  const auto video = (dir / "run.mp4").string();
  // 30 steps at 60 Hz, 30 fps: the first frame plus one every second step.
  const CliResult r = run_cli({"run", "tumbler_400", "--steps", "30", "--frames", "--out",
                               dir.string(), "--video", video, "--fps", "30", "--size", "320x240"});
  ASSERT_EQ(r.code, 0) << r.err;
  int pngs = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "frames")) {
    pngs += entry.path().extension() == ".png";
  }
  EXPECT_EQ(pngs, 16);
  const std::string probe = (dir / "probe.txt").string();
  ASSERT_EQ(std::system(("ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                         "stream=nb_read_frames,width,height -of csv=p=0 '" +
                         video + "' > '" + probe + "'")
                            .c_str()),
            0);
  EXPECT_EQ(split_lines(read_text(probe)).at(0), "320,240,16");
}

}  // namespace
