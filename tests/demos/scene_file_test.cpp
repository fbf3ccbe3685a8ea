#include <gtest/gtest.h>

#include <string>

#include "cli_test_support.hpp"
#include "mink/engine/world.hpp"
#include "scene_file.hpp"

namespace {

using namespace mink;
using namespace mink_test;

void expect_same_scene(const SceneDef& a, const SceneDef& b) {
  // Every field, exactly: the file keeps doubles in shortest round-trip form.
  const WorldDef& x = a.world;
  const WorldDef& y = b.world;
  EXPECT_EQ(x.gravity, y.gravity);
  EXPECT_EQ(x.time_step, y.time_step);
  EXPECT_EQ(x.substeps, y.substeps);
  EXPECT_EQ(x.contact_hertz, y.contact_hertz);
  EXPECT_EQ(x.contact_damping_ratio, y.contact_damping_ratio);
  EXPECT_EQ(x.contact_push_max_velocity, y.contact_push_max_velocity);
  EXPECT_EQ(x.restitution_threshold, y.restitution_threshold);
  EXPECT_EQ(x.linear_slop, y.linear_slop);
  EXPECT_EQ(x.max_linear_speed, y.max_linear_speed);
  EXPECT_EQ(x.enable_sleep, y.enable_sleep);
  EXPECT_EQ(x.time_to_sleep, y.time_to_sleep);
  EXPECT_EQ(x.linear_sleep_tolerance, y.linear_sleep_tolerance);
  EXPECT_EQ(x.angular_sleep_tolerance, y.angular_sleep_tolerance);
  EXPECT_EQ(x.max_steps_per_advance, y.max_steps_per_advance);
  EXPECT_EQ(x.simd_solver, y.simd_solver);
  EXPECT_EQ(x.reuse_manifolds, y.reuse_manifolds);
  ASSERT_EQ(a.bodies.size(), b.bodies.size());
  for (std::size_t i = 0; i < a.bodies.size(); ++i) {
    const BodyDef& p = a.bodies[i].body;
    const BodyDef& q = b.bodies[i].body;
    ASSERT_EQ(p.type, q.type) << "body " << i;
    ASSERT_EQ(p.position, q.position) << "body " << i;
    ASSERT_EQ(p.angle, q.angle) << "body " << i;
    ASSERT_EQ(p.linear_velocity, q.linear_velocity) << "body " << i;
    ASSERT_EQ(p.angular_velocity, q.angular_velocity) << "body " << i;
    ASSERT_EQ(p.linear_damping, q.linear_damping);
    ASSERT_EQ(p.angular_damping, q.angular_damping);
    ASSERT_EQ(p.gravity_scale, q.gravity_scale);
    ASSERT_EQ(p.allow_sleep, q.allow_sleep);
    ASSERT_EQ(p.awake, q.awake);
    ASSERT_EQ(p.user_data, q.user_data);
    ASSERT_EQ(a.bodies[i].shapes.size(), b.bodies[i].shapes.size());
    for (std::size_t k = 0; k < a.bodies[i].shapes.size(); ++k) {
      const ShapeDef& s = a.bodies[i].shapes[k];
      const ShapeDef& t = b.bodies[i].shapes[k];
      ASSERT_EQ(s.points, t.points) << "body " << i << " shape " << k;
      ASSERT_EQ(s.algorithm, t.algorithm);
      ASSERT_EQ(s.density, t.density);
      ASSERT_EQ(s.friction, t.friction);
      ASSERT_EQ(s.restitution, t.restitution);
      ASSERT_EQ(s.scale.has_value(), t.scale.has_value());
      if (s.scale) {
        ASSERT_EQ(s.scale->fixed_point, t.scale->fixed_point);
        ASSERT_EQ(s.scale->factor, t.scale->factor);
      }
    }
  }
}

// Big scenes (thousands of bodies) get a couple of steps only: same code, shorter test.
#ifdef MINK_SANITIZED_BUILD
constexpr int kSteps = 5;
constexpr int kBigSteps = 0;
#else
constexpr int kSteps = 30;
constexpr int kBigSteps = 2;
#endif

TEST(SceneFile, EveryBuiltinRoundTripsAndSimulatesTheSame) {
  for (std::string_view name : builtin_scene_names()) {
    SCOPED_TRACE(std::string(name));
    const SceneDef original = builtin_scene(name);
    const std::string text = cli::scene_to_json(original);
    const SceneDef loaded = cli::parse_scene_json(text);
    expect_same_scene(original, loaded);
    EXPECT_EQ(cli::scene_to_json(loaded), text);
    World a = build_world(original);
    World b = build_world(loaded);
    const int steps = original.bodies.size() > 1000 ? kBigSteps : kSteps;
    for (int i = 0; i < steps; ++i) {
      a.step();
      b.step();
    }
    const auto ids_a = a.bodies();
    const auto ids_b = b.bodies();
    ASSERT_EQ(ids_a.size(), ids_b.size());
    for (std::size_t i = 0; i < ids_a.size(); ++i) {
      ASSERT_EQ(a.position(ids_a[i]), b.position(ids_b[i])) << "body " << i;
      ASSERT_EQ(a.angle(ids_a[i]), b.angle(ids_b[i])) << "body " << i;
    }
  }
}

TEST(SceneFile, ExportSceneWritesAFileThatLoads) {
  const auto dir = fresh_dir("export");
  const CliResult r = run_cli({"export-scene", "pyramid", "--out", (dir / "p.json").string()});
  ASSERT_EQ(r.code, 0) << r.err;
  expect_same_scene(builtin_scene("pyramid"), cli::load_scene_file(dir / "p.json"));
  const CliResult listed = run_cli({"scenes"});
  ASSERT_EQ(listed.code, 0);
  for (std::string_view name : builtin_scene_names()) {
    EXPECT_NE(listed.out.find(std::string(name) + " ("), std::string::npos) << name;
  }
  EXPECT_EQ(run_cli({"export-scene", "no_such_scene"}).code, 2);
}

TEST(SceneFile, HelpersAndDefaults) {
  const SceneDef scene = cli::parse_scene_json(R"({
    "world": {"gravity": [0, -9.8]},
    "bodies": [
      {"type": "static", "shapes": [{"box": {"half_extents": [5, 0.5]}}]},
      {"type": "dynamic", "position": [1, 2], "angle": 0.5, "linear_velocity": [3, 0],
       "shapes": [{"polygon": {"count": 6, "radius": 0.5}, "friction": 0.2},
                  {"points": [[0, 0], [1, 0], [0, 1], [0.2, 0.2]], "density": 2}]}
    ]})");
  ASSERT_EQ(scene.bodies.size(), 2u);
  EXPECT_EQ(scene.world.gravity, Vec2(0, -9.8));
  EXPECT_EQ(scene.world.substeps, WorldDef{}.substeps);
  EXPECT_EQ(scene.bodies[0].shapes[0].points, ShapeDef::box(5, 0.5).points);
  EXPECT_EQ(scene.bodies[1].body.type, BodyType::dynamic);
  EXPECT_EQ(scene.bodies[1].body.angle, 0.5);
  EXPECT_EQ(scene.bodies[1].body.linear_velocity, Vec2(3, 0));
  EXPECT_EQ(scene.bodies[1].shapes[0].points, ShapeDef::regular_polygon(6, 0.5).points);
  EXPECT_EQ(scene.bodies[1].shapes[0].friction, 0.2);
  EXPECT_EQ(scene.bodies[1].shapes[1].density, 2);
}

struct BadScene {
  const char* name;
  const char* json;
  const char* path;     // expected at the start of the message
  const char* problem;  // expected in the message
};

// A valid two-body scene with one defect each.
const BadScene kBadScenes[] = {
    {"missing_bodies", R"({"world": {}})", "bodies", "missing field"},
    {"missing_type", R"({"bodies": [{"shapes": []}]})", "bodies[0].type", "missing field"},
    {"missing_shape_form", R"({"bodies": [{"type": "dynamic", "shapes": [{"density": 1}]}]})",
     "bodies[0].shapes[0]", "missing field"},
    {"missing_half_extents", R"({"bodies": [{"type": "static", "shapes": [{"box": {}}]}]})",
     "bodies[0].shapes[0].box.half_extents", "missing field"},
    {"wrong_type_number", R"({"bodies": [{"type": "dynamic", "angle": "0.5", "shapes": []}]})",
     "bodies[0].angle", "expected a number"},
    {"wrong_type_point",
     R"({"bodies": [{"type": "dynamic", "shapes": [{"points": [[0,0],[1,0],[0,1],[1,"a"]]}]}]})",
     "bodies[0].shapes[0].points[3][1]", "expected a number"},
    {"wrong_type_body", R"({"bodies": [{"type": "dynamic", "shapes": []}, 7]})", "bodies[1]",
     "expected an object"},
    {"bad_body_type", R"({"bodies": [{"type": "wobbly", "shapes": []}]})", "bodies[0].type",
     "expected \"static\""},
    {"nan_coordinate",
     R"({"bodies": [{"type": "dynamic", "shapes": [{"points": [[0,0],[1,0],[0,1e999]]}]}]})",
     "bodies[0].shapes[0].points[2][1]", "not a finite number"},
    {"nan_gravity", R"({"world": {"gravity": [0, -1e999]}, "bodies": []})", "world.gravity[1]",
     "not a finite number"},
    {"degenerate_hull",
     R"({"bodies": [{"type": "static", "shapes": []}, {"type": "dynamic", "shapes": [
        {"points": [[0,0],[1,1],[2,2],[3,3]]}]}]})",
     "bodies[1].shapes[0].points", "degenerate hull"},
    {"unknown_key", R"({"bodies": [{"type": "dynamic", "shapes": [], "velocity": [1, 0]}]})",
     "bodies[0].velocity", "unknown key"},
    {"unknown_top_key", R"({"bodies": [], "gravity": [0, -10]})", "gravity", "unknown key"},
    {"bad_world_value", R"({"world": {"time_step": -1}, "bodies": []})", "world", "time_step"},
    {"negative_density",
     R"({"bodies": [{"type": "dynamic", "shapes": [{"box": {"half_extents": [1, 1]},
        "density": -1}]}]})",
     "bodies[0].shapes[0]", "density"},
    {"not_json", R"({"bodies": [)", "", "not valid JSON"},
};

TEST(SceneFile, EveryBadFileGetsItsPathProblemAndExitCode2WithNoOutput) {
  const auto dir = fresh_dir("bad");
  for (const BadScene& bad : kBadScenes) {
    SCOPED_TRACE(bad.name);
    try {
      (void)cli::parse_scene_json(bad.json, "file.json");
      ADD_FAILURE() << "accepted";
    } catch (const cli::SceneFileError& error) {
      const std::string message = error.what();
      if (*bad.path != '\0') {
        EXPECT_EQ(error.json_path(), bad.path) << message;
        EXPECT_EQ(message.rfind(std::string(bad.path) + ": ", 0), 0u) << message;
      }
      EXPECT_NE(message.find(bad.problem), std::string::npos) << message;
    }
    const auto file = dir / (std::string(bad.name) + ".json");
    write_text(file, bad.json);
    const auto stats = dir / (std::string(bad.name) + ".csv");
    const CliResult r =
        run_cli({"run", file.string(), "--steps", "5", "--no-render", "--stats", stats.string()});
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find(bad.problem), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(file.string()), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(stats)) << "a bad scene must not start a run";
  }
}

}  // namespace
