#include <gtest/gtest.h>

#include <string>

#include "cli_test_support.hpp"
#include "contact_compare.hpp"

namespace {

using namespace mink;
using namespace mink_test;

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

// rain drops and destroys ragdolls as it runs: Box2D 2.4.1 could not follow our world.
TEST(CompareCommand, ASceneThatChangesAsItRunsIsRefused) {
  const auto dir = fresh_dir("compare_schedule");
  const CliResult r = run_cli({"compare", "rain", "--steps", "5", "--out", dir.string()});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("scene 'rain' changes as it runs"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "contacts.csv"));
}

}  // namespace
