#include <gtest/gtest.h>

#include <string>

#include "cli_test_support.hpp"
#include "mink/engine/scene_file.hpp"

// The scene format itself is tested with the engine (tests/engine/scene_file_test.cpp); here,
// what the `mink` command does with scene files.

namespace {

using namespace mink;
using namespace mink_test;

TEST(SceneFile, ExportSceneWritesAFileThatLoads) {
  const auto dir = fresh_dir("export");
  for (const std::string name : {"pyramid", "shapes"}) {
    const auto file = dir / (name + ".json");
    const CliResult r = run_cli({"export-scene", name, "--out", file.string()});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(scene_to_json(load_scene_file(file)), scene_to_json(builtin_scene(name))) << name;
  }
  const CliResult listed = run_cli({"scenes"});
  ASSERT_EQ(listed.code, 0);
  for (std::string_view name : builtin_scene_names()) {
    EXPECT_NE(listed.out.find(std::string(name) + " ("), std::string::npos) << name;
  }
  EXPECT_EQ(run_cli({"export-scene", "no_such_scene"}).code, 2);
}

struct BadScene {
  const char* name;
  const char* json;
  const char* problem;  // expected in the message
};

const BadScene kBadScenes[] = {
    {"missing_bodies", R"({"world": {}})", "bodies: missing field"},
    {"unknown_key", R"({"bodies": [{"type": "dynamic", "shapes": [], "velocity": [1, 0]}]})",
     "bodies[0].velocity: unknown key"},
    {"bad_world_value", R"({"world": {"time_step": -1}, "bodies": []})",
     "world.time_step: must be > 0"},
    {"bad_filter", R"({"bodies": [{"type": "dynamic", "shapes": [{"circle": {"radius": 1},
        "filter": {"mask": "0xG"}}]}]})",
     "bodies[0].shapes[0].filter.mask: expected a hex string"},
    {"not_json", R"({"bodies": [)", "not valid JSON"},
};

TEST(SceneFile, EveryBadFileGetsItsPathProblemAndExitCode2WithNoOutput) {
  const auto dir = fresh_dir("bad");
  for (const BadScene& bad : kBadScenes) {
    SCOPED_TRACE(bad.name);
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
