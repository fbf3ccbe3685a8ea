#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "cli_test_support.hpp"
#include "mink/engine/scene_file.hpp"
#include "mink/engine/world.hpp"

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
  EXPECT_EQ(lines[0], "step,time,bodies,awake,pairs,contacts,kinetic_energy,step_ms");
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

TEST(RunCommand, SecondsAndStepsAreExclusiveAndBadOptionsExit2) {
  EXPECT_EQ(run_cli({"run", "pyramid", "--steps", "3", "--seconds", "1", "--no-render"}).code, 2);
  EXPECT_EQ(run_cli({"run", "no_such_scene", "--no-render"}).code, 2);
  EXPECT_EQ(run_cli({"run", "pyramid", "--no-render", "--frames"}).code, 2);
  EXPECT_EQ(run_cli({"run", "pyramid", "--size", "101x100", "--frames"}).code, 2);
}

// Resuming from --save: the pose and velocities of every body are kept exactly, but the
// contact impulses the solver warm-starts from are not part of a scene, so the resumed run
// starts its contacts cold and drifts from the uninterrupted one. On a resting pyramid that is
// under a millimetre in 30 steps (the stack settles a little while the impulses build up
// again); in chaotic scenes (rain, tumbler) the same tiny difference grows to decimetres, as
// any perturbation would, so only the saved state itself is compared exactly there.
TEST(RunCommand, SaveThenResumeFollowsTheUninterruptedRun) {
  const auto dir = fresh_dir("resume");
  const auto saved = (dir / "half.json").string();
  ASSERT_EQ(run_cli({"run", "pyramid", "--steps", "60", "--no-render", "--save", saved}).code, 0);
  // The saved file is the world as it stood: same state as 60 steps in-process.
  World direct = build_world(builtin_scene("pyramid"));
  for (int i = 0; i < 60; ++i) direct.step();
  const SceneDef at_half = load_scene_file(saved);
  const SceneDef expected = capture_scene(direct);
  const auto ids = direct.bodies();
  ASSERT_EQ(at_half.bodies.size(), expected.bodies.size());
  for (std::size_t i = 0; i < expected.bodies.size(); ++i) {
    const BodyDef& got = at_half.bodies[i].body;
    const BodyDef& want = expected.bodies[i].body;
    ASSERT_EQ(got.position, want.position) << i;
    ASSERT_EQ(got.angle, want.angle) << i;
    ASSERT_EQ(got.linear_velocity, want.linear_velocity) << i;
    ASSERT_EQ(got.angular_velocity, want.angular_velocity) << i;
    ASSERT_EQ(got.awake, want.awake) << i;
  }
  const auto end = (dir / "end.json").string();
  ASSERT_EQ(run_cli({"run", saved, "--steps", "30", "--no-render", "--save", end}).code, 0);
  for (int i = 0; i < 30; ++i) direct.step();
  const SceneDef resumed = load_scene_file(end);
  double worst = 0;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    worst = std::max(worst, (resumed.bodies[i].body.position - direct.position(ids[i])).norm());
  }
  EXPECT_LT(worst, 0.002);
  std::printf("resume vs uninterrupted after 60 + 30 steps of pyramid: worst position gap %.3g m\n",
              worst);
}

bool have_program(const char* name) {
  return std::system((std::string("command -v ") + name + " > /dev/null 2>&1").c_str()) == 0;
}

TEST(RunCommand, FramesAndVideoOfAShortRun) {
  if (!have_program("ffmpeg") || !have_program("ffprobe")) GTEST_SKIP() << "no ffmpeg/ffprobe";
  const auto dir = fresh_dir("video");
  const auto video = (dir / "run.mp4").string();
  // 30 steps at 60 Hz, 30 fps: the first frame plus one every second step.
  const CliResult r = run_cli({"run", "tumbler", "--steps", "30", "--frames", "--out", dir.string(),
                               "--video", video, "--fps", "30", "--size", "320x240"});
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
