#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cli_test_support.hpp"
#include "contact_compare.hpp"
#include "mink/engine/scene_file.hpp"
#include "trajectory_compare.hpp"

namespace {

using namespace mink;
using namespace mink_test;

// trajectories.csv read back, each row checked for its own consistency.
std::vector<cli::TrajectoryRow> read_trajectories(const std::filesystem::path& file) {
  std::istringstream in(read_text(file));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "step,body,mink_x,mink_y,box2d_x,box2d_y,distance");
  std::vector<cli::TrajectoryRow> rows;
  while (std::getline(in, line)) {
    cli::TrajectoryRow r;
    double mx = 0, my = 0, bx = 0, by = 0;
    EXPECT_EQ(std::sscanf(line.c_str(), "%lld,%zu,%lf,%lf,%lf,%lf,%lf", &r.step, &r.body, &mx, &my,
                          &bx, &by, &r.distance),
              7)
        << line;
    r.mink = Vec2(mx, my);
    r.box2d = Vec2(bx, by);
    EXPECT_NEAR(r.distance, (r.mink - r.box2d).norm(), 1e-6 * (1 + r.distance)) << line;
    rows.push_back(r);
  }
  return rows;
}

// Per body: the largest difference over steps 0..last, and how far our body moved by then.
struct BodyAgreement {
  double worst = 0;
  double moved = 0;
};

std::map<std::size_t, BodyAgreement> agreement(const std::vector<cli::TrajectoryRow>& rows,
                                               long long last) {
  std::map<std::size_t, Vec2> start;
  std::map<std::size_t, BodyAgreement> out;
  for (const cli::TrajectoryRow& r : rows) {
    if (r.step > last) continue;
    if (r.step == 0) start[r.body] = r.mink;
    BodyAgreement& a = out[r.body];
    a.worst = std::max(a.worst, r.distance);
    a.moved = std::max(a.moved, (r.mink - start.at(r.body)).norm());
  }
  return out;
}

std::size_t dynamic_count(const SceneDef& scene) {
  return static_cast<std::size_t>(
      std::count_if(scene.bodies.begin(), scene.bodies.end(),
                    [](const SceneBody& b) { return b.body.type == BodyType::dynamic; }));
}

// `mink compare SCENE` for the first second (60 steps): every dynamic body of the scene in
// every row from step 0, the plot written, and each body's agreement.
std::map<std::size_t, BodyAgreement> compare_first_second(const std::string& scene,
                                                          const std::string& name) {
  const auto dir = fresh_dir(name);
  const CliResult r = run_cli({"compare", scene, "--steps", "60", "--out", dir.string()});
  EXPECT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(
      r.out.find("per step: 5 b2World::Step of 0.003333 s, 8 velocity and 3 position iterations"),
      std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("worst position difference"), std::string::npos) << r.out;
  const std::vector<cli::TrajectoryRow> rows = read_trajectories(dir / "trajectories.csv");
  const std::size_t bodies = dynamic_count(resolve_scene(scene));
  EXPECT_EQ(rows.size(), 61 * bodies);
  EXPECT_GT(std::filesystem::file_size(dir / "trajectories.png"), 1000u);
  const std::map<std::size_t, BodyAgreement> out = agreement(rows, 60);
  EXPECT_EQ(out.size(), bodies);
  return out;
}

TEST(CompareCommand, AShortPyramidRunPassesTheOracleAndWritesCsvAndPlot) {
  const auto dir = fresh_dir("compare");
  const CliResult r =
      run_cli({"compare", "pyramid", "--steps", "60", "--every", "10", "--out", dir.string()});
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("overlap oracle: 6 configurations"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("0 outside the 1e-06 band"), std::string::npos) << r.out;
  const std::string csv = read_text(dir / "contacts.csv");
  EXPECT_EQ(csv.rfind("step,mink_pairs,mink_contacts,box2d_pairs,box2d_touching\n", 0), 0u);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 61);
  EXPECT_GT(std::filesystem::file_size(dir / "contacts.png"), 1000u);
}

TEST(CompareCommand, TheOracleChecksOverlappingPairs) {
  const cli::ContactComparison c = cli::compare_contacts(builtin_scene("pyramid"), 20, 10, 1e-6);
  ASSERT_EQ(c.rows.size(), 20u);
  EXPECT_EQ(c.oracle_checks, 2u);
  // A resting pyramid of 210 boxes: every box touches its neighbours.
  EXPECT_GT(c.oracle_overlapping, 200u);
  EXPECT_EQ(c.outside_band, 0u);
  EXPECT_GT(c.rows.back().mink_contacts, 0u);
  EXPECT_GT(c.rows.back().box2d_touching, 0u);
}

TEST(CompareCommand, AHullTooBigForBox2dIsRefusedWithTheBodyNamed) {
  const auto dir = fresh_dir("compare_big");
  write_text(dir / "big.json", R"({"bodies": [
    {"type": "static", "shapes": [{"box": {"half_extents": [5, 0.5]}}]},
    {"type": "dynamic", "position": [0, 2], "shapes": [{"polygon": {"count": 12, "radius": 1}}]}
  ]})");
  const CliResult r = run_cli(
      {"compare", (dir / "big.json").string(), "--steps", "5", "--out", (dir / "out").string()});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("body 1 (dynamic"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("12 hull vertices"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "contacts.csv"));
}

// The pendulums (rigid ones on revolute joints, a double one, two on distance joints, one of
// them a spring) swing 1 rad out over 3 to 5 m. Integrated at the same rate (5 substeps) the
// engines agree within 1 cm over the first second, 0.25% of a 4 m pendulum: we measure at most
// 5.3 mm, on the chaotic double pendulum's lower bob. Both engines are 1.2 to 1.5 cm from a
// converged run (60 substeps) at that time, and agree within 0.5 mm run at that rate.
TEST(CompareTrajectories, ThePendulumsAgreeWithBox2dWithinACentimetreForTheFirstSecond) {
  const auto bodies = compare_first_second("pendulum", "compare_pendulum");
  for (const auto& [body, a] : bodies) {
    EXPECT_GT(a.moved, 1.0) << "body " << body;
    EXPECT_LT(a.worst, 0.01) << "body " << body;
  }
}

// The 30 links (15 m) falling from the horizontal with a weight of 100 links' mass: within
// 5 cm, a third of a percent of the chain's length, over the first second (we measure 3.6 cm, at
// the weight). Box2D's joints give under the weight (their gap reaches 3.3 cm by then) and ours
// are soft too: against a converged run, ours is 1.6 cm off and Box2D's 3.5 cm, so the engines
// may differ by their sum.
TEST(CompareTrajectories, TheHeavyChainAgreesWithBox2dWithinFiveCentimetresForTheFirstSecond) {
  const auto bodies = compare_first_second("chain", "compare_chain");
  ASSERT_EQ(bodies.size(), 31u);
  EXPECT_GT(bodies.rbegin()->second.moved, 3.0);  // the weight falls
  for (const auto& [body, a] : bodies) EXPECT_LT(a.worst, 0.05) << "body " << body;
}

// Run at a converged rate (60 substeps, joints 10 times stiffer), both engines give the same
// motion: what is left between them above is each one's step error, not a different model.
TEST(CompareTrajectories, AtAConvergedRateBothEnginesGiveTheSameChainAndPendulums) {
  for (const char* name : {"chain", "pendulum"}) {
    SceneDef scene = builtin_scene(name);
    scene.world.substeps = 60;
    scene.world.joint_hertz = 600;
    cli::TrajectoryRecorder recorder(scene);
    cli::compare_contacts(scene, 60, 60, 1e-6, {60, 8, 3},
                          [&](long long step, const World& ours, const interop::Box2dScene& rival) {
                            recorder.record(step, ours, rival);
                          });
    ASSERT_EQ(recorder.rows().size(), 61 * dynamic_count(scene));
    const cli::WorstDifference worst = cli::worst_difference(recorder.rows(), 60);
    EXPECT_LT(worst.distance, 0.002) << name << ": body " << worst.body << " step " << worst.step;
  }
}

// One joint of every kind, each on bodies that move in the first second (a box falling onto
// its revolute limit against a motor too weak to hold it; a prismatic motor; a rigid, a sprung
// and a rope distance joint; a soft weld on a swinging bar; a wheel's sprung, motorised
// suspension; a motor joint; a motorised revolute geared 2:1 to another; a pulley of ratio
// 1.5). Each translation agrees within 5 mm (we measure at most 2.2 mm), but for the box on
// the limit: our soft limit rebounds by about 0.015 rad where Box2D's stops dead, 1.7 cm at its
// end, so it gets 2.5 cm. The motor joint has force to spare: with its force bound, ours brakes
// before the target where Box2D's overshoots.
TEST(CompareTrajectories, EveryJointKindAgreesWithBox2d) {
  const auto dir = fresh_dir("compare_joints");
  write_text(dir / "joints.json", R"({
    "bodies": [
      {"type": "static", "position": [0, -1], "shapes": [{"box": {"half_extents": [30, 1]}}]},
      {"type": "dynamic", "position": [-12, 10], "shapes": [{"box": {"half_extents": [1, 0.2]}}]},
      {"type": "dynamic", "position": [-8, 10], "shapes": [{"box": {"half_extents": [0.3, 0.3]}}]},
      {"type": "dynamic", "position": [-4, 8], "shapes": [{"circle": {"radius": 0.3}}]},
      {"type": "dynamic", "position": [-1, 8], "shapes": [{"circle": {"radius": 0.3}}]},
      {"type": "dynamic", "position": [0, 8], "shapes": [{"circle": {"radius": 0.3}}]},
      {"type": "dynamic", "position": [5, 10], "shapes": [{"box": {"half_extents": [1, 0.2]}}]},
      {"type": "dynamic", "position": [6, 9], "shapes": [{"box": {"half_extents": [0.2, 1]}}]},
      {"type": "dynamic", "position": [9, 10], "shapes": [{"circle": {"radius": 0.5}}]},
      {"type": "dynamic", "position": [11, 9], "shapes": [{"box": {"half_extents": [0.4, 0.4]}}]},
      {"type": "dynamic", "position": [14, 10], "shapes": [{"box": {"half_extents": [1, 0.1]}}]},
      {"type": "dynamic", "position": [18, 10], "shapes": [{"box": {"half_extents": [1, 0.1]}}]},
      {"type": "dynamic", "position": [21, 8], "shapes": [{"box": {"half_extents": [0.5, 0.5]}}]},
      {"type": "dynamic", "position": [24, 8], "angle": 0.2,
       "shapes": [{"box": {"half_extents": [0.5, 0.5]}}]}
    ],
    "joints": [
      {"type": "revolute", "body_a": 0, "body_b": 1, "anchor": [-13, 10], "lower": -0.5,
       "upper": 0.5, "motor": {"speed": 1, "max_torque": 5}},
      {"type": "prismatic", "body_a": 0, "body_b": 2, "anchor": [-8, 10], "axis": [1, 1],
       "lower": -1, "upper": 1, "motor": {"speed": 0.5, "max_force": 3}},
      {"type": "distance", "body_a": 0, "body_b": 3, "anchor_a": [-5, 10], "anchor_b": [-4, 8]},
      {"type": "distance", "body_a": 0, "body_b": 4, "anchor_a": [-2, 10], "anchor_b": [-1, 8],
       "spring": {"hertz": 2, "damping_ratio": 0.3}},
      {"type": "distance", "body_a": 0, "body_b": 5, "anchor_a": [1, 10], "anchor_b": [0, 8],
       "max_length": 2.6},
      {"type": "revolute", "body_a": 0, "body_b": 6, "anchor": [4, 10]},
      {"type": "weld", "body_a": 6, "body_b": 7, "anchor": [6, 10], "angular_hertz": 3,
       "angular_damping_ratio": 0.4},
      {"type": "wheel", "body_a": 0, "body_b": 8, "anchor": [9, 10], "axis": [0, 1], "lower": -0.5,
       "upper": 0.5, "spring": {"hertz": 2, "damping_ratio": 0.5},
       "motor": {"speed": -5, "max_torque": 2}},
      {"type": "motor", "body_a": 0, "body_b": 9, "linear_offset": [11.5, 11.5],
       "angular_offset": 0.5, "max_force": 100000, "max_torque": 10000},
      {"type": "revolute", "body_a": 0, "body_b": 10, "anchor": [13, 10],
       "motor": {"speed": 2, "max_torque": 50}},
      {"type": "revolute", "body_a": 0, "body_b": 11, "anchor": [17, 10]},
      {"type": "gear", "joint1": 9, "joint2": 10, "ratio": 2},
      {"type": "pulley", "body_a": 12, "body_b": 13, "ground_a": [21, 11], "ground_b": [24, 11],
       "anchor_a": [21, 8.5], "anchor_b": [24, 8.5], "ratio": 1.5}
    ]
  })");
  const auto bodies = compare_first_second((dir / "joints.json").string(), "compare_joints_out");
  ASSERT_EQ(bodies.size(), 13u);
  for (const auto& [body, a] : bodies) {
    EXPECT_GT(a.moved, 0.05) << "body " << body;
    EXPECT_LT(a.worst, body == 1 ? 0.025 : 0.005) << "body " << body;
  }
}

// The mass-ratio figure, 10 s of each: the 30-link chain with its 100:1 weight (the `chain`
// built-in, 15 m) and 10 links holding 1000 times a link's mass (scenes/heavy_chain.json, 5 m).
// Ours stays within 1% and 5% of their lengths, the issue's bounds; Box2D 2.4.1, at the same
// rate, gives more than ours in both.
TEST(CompareTrajectories, TheMassRatioChainsStretchLessThanInBox2d) {
  struct Case {
    std::string scene;
    double length;
    double bound;
  };
  for (const Case& c :
       {Case{"chain", 15, 0.01}, Case{MINK_SCENES_DIR "/heavy_chain.json", 5, 0.05}}) {
    const auto dir = fresh_dir("compare_mass_ratio");
    const CliResult r = run_cli({"compare", c.scene, "--steps", "600", "--out", dir.string()});
    ASSERT_EQ(r.code, 0) << r.out << r.err;
    std::istringstream in(read_text(dir / "joint_gaps.csv"));
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "step,mink,box2d");
    double mink = 0, box2d = 0;
    long long rows = 0;
    while (std::getline(in, line)) {
      long long step = 0;
      double m = 0, b = 0;
      ASSERT_EQ(std::sscanf(line.c_str(), "%lld,%lf,%lf", &step, &m, &b), 3) << line;
      EXPECT_EQ(step, rows++);
      mink = std::max(mink, m);
      box2d = std::max(box2d, b);
    }
    EXPECT_EQ(rows, 601);
    EXPECT_LE(mink, c.bound * c.length) << c.scene;
    EXPECT_GT(box2d, mink) << c.scene;
    EXPECT_NE(r.out.find("joint gap"), std::string::npos) << r.out;
  }
}

// The scene file is the issue's 10-link chain: the weight is 1000 links' mass.
TEST(CompareTrajectories, TheHeavyChainFileHoldsAThousandTimesALinksMass) {
  const World world = build_world(load_scene_file(MINK_SCENES_DIR "/heavy_chain.json"));
  const std::vector<BodyId> bodies = world.bodies();
  ASSERT_EQ(bodies.size(), 12u);
  EXPECT_EQ(world.joint_count(), 11u);
  EXPECT_NEAR(world.mass(bodies[11]) / world.mass(bodies[1]), 1000, 1e-9);
}

// What 2.4.1 cannot hold is refused, naming the joint or the shape, before anything runs.
TEST(CompareTrajectories, JointsWithoutABox2dCounterpartAreRefusedWithTheJointNamed) {
  const auto dir = fresh_dir("compare_refused");
  struct Case {
    const char* joint;
    const char* says;
  };
  const Case cases[] = {
      {R"({"type": "revolute", "body_a": 0, "body_b": 1, "anchor": [0, 2],
           "spring": {"hertz": 2, "damping_ratio": 0.5}})",
       "joints[1] is a revolute joint that has a spring"},
      {R"({"type": "prismatic", "body_a": 0, "body_b": 1, "anchor": [0, 2], "axis": [1, 0],
           "spring": {"hertz": 2}})",
       "joints[1] is a prismatic joint that has a spring"},
      {R"({"type": "distance", "body_a": 0, "body_b": 1, "anchor_a": [0, 2], "anchor_b": [0, 1],
           "motor": {"speed": 1, "max_force": 5}})",
       "joints[1] is a distance joint that has a motor"},
      {R"({"type": "distance", "body_a": 0, "body_b": 1, "anchor_a": [0, 2], "anchor_b": [0, 1],
           "spring": {"hertz": 0, "damping_ratio": 1}})",
       "joints[1] is a distance joint that has a spring of 0 hertz"},
      {R"({"type": "weld", "body_a": 0, "body_b": 1, "anchor": [0, 2], "linear_hertz": 5})",
       "joints[1] is a weld joint that has a linear spring"},
      {R"({"type": "wheel", "body_a": 0, "body_b": 1, "anchor": [0, 2], "axis": [0, 1],
           "spring": {"hertz": 2, "target": 0.1}})",
       "joints[1] is a wheel joint that has a spring target of 0.1"},
  };
  for (const Case& c : cases) {
    write_text(dir / "scene.json", std::string(R"({"bodies": [
      {"type": "static", "shapes": [{"box": {"half_extents": [5, 0.5]}}]},
      {"type": "dynamic", "position": [0, 2], "shapes": [{"circle": {"radius": 0.5}}]}],
      "joints": [{"type": "revolute", "body_a": 0, "body_b": 1, "anchor": [0, 2]}, )") +
                                       c.joint + "]}");
    const CliResult r = run_cli({"compare", (dir / "scene.json").string(), "--steps", "5", "--out",
                                 (dir / "out").string()});
    EXPECT_EQ(r.code, 2) << c.says;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out" / "trajectories.csv"));
  }
  write_text(dir / "scene.json", R"({"bodies": [
    {"type": "dynamic", "shapes": [{"capsule": {"center1": [0, 0], "center2": [1, 0],
                                                "radius": 0.004}}]}]})");
  const CliResult thin = run_cli(
      {"compare", (dir / "scene.json").string(), "--steps", "5", "--out", (dir / "out").string()});
  EXPECT_EQ(thin.code, 2);
  EXPECT_NE(thin.err.find("body 0 (dynamic, at 0.000000, 0.000000) shape 0 is a capsule"),
            std::string::npos)
      << thin.err;
}

// A scene without joints gets trajectories only when asked.
TEST(CompareTrajectories, AJointlessSceneComparesTrajectoriesOnlyWhenAsked) {
  const auto dir = fresh_dir("compare_jointless");
  ASSERT_EQ(run_cli({"compare", "pyramid", "--steps", "3", "--out", dir.string()}).code, 0);
  EXPECT_FALSE(std::filesystem::exists(dir / "trajectories.csv"));
  const CliResult r = run_cli({"compare", "pyramid", "--steps", "3", "--trajectories",
                               "--box2d-substeps", "1", "--out", dir.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("per step: 1 b2World::Step of 0.01667 s"), std::string::npos) << r.out;
  const std::vector<cli::TrajectoryRow> rows = read_trajectories(dir / "trajectories.csv");
  EXPECT_EQ(rows.size(), 4 * dynamic_count(builtin_scene("pyramid")));
  EXPECT_FALSE(std::filesystem::exists(dir / "joint_gaps.csv"));  // no revolute or weld joints
}

// rain drops and destroys ragdolls as it runs: Box2D 2.4.1 could not follow our world.
TEST(CompareCommand, ASceneThatChangesAsItRunsIsRefused) {
  const auto dir = fresh_dir("compare_schedule");
  const CliResult r = run_cli({"compare", "rain", "--steps", "5", "--out", dir.string()});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("scene 'rain' changes as it runs"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "contacts.csv"));
}

}  // namespace
