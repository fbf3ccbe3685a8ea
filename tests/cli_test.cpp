#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "mink/geometry/convex_hull.hpp"
#include "mink/geometry/point_sets.hpp"
#include "test_support.hpp"

namespace {

using mink::Vec2;
using mink_test::same_bits;

struct CliRun {
  int exit_code = -1;
  std::string out;
  std::string err;        // what the command wrote to the error stream it was given
  std::string std_error;  // anything written to std::cerr instead
  std::string diagnostics() const { return err + std_error; }
};

// Runs `mink <arguments>` in-process on `input`. std::cerr is captured too, so a message is
// found even if it bypasses the given stream, and a test can tell where it went.
CliRun run_mink(const std::vector<std::string>& arguments, const std::string& input = "") {
  std::istringstream in(input);
  std::ostringstream out;
  std::ostringstream err;
  std::ostringstream captured;
  std::vector<const char*> argv = {"mink"};
  for (const std::string& argument : arguments) argv.push_back(argument.c_str());
  std::streambuf* const original = std::cerr.rdbuf(captured.rdbuf());
  CliRun run;
  run.exit_code =
      mink::cli::run(static_cast<int>(argv.size()), argv.data(), mink::cli::Streams{in, out, err});
  std::cerr.rdbuf(original);
  run.out = out.str();
  run.err = err.str();
  run.std_error = captured.str();
  return run;
}

std::string format_input(const std::vector<Vec2>& points) {
  std::string text;
  char line[96];
  for (const Vec2& p : points) {
    std::snprintf(line, sizeof line, "%.17g %.17g\n", p.x(), p.y());
    text += line;
  }
  return text;
}

// Parses `mink hull` output back into points; any malformed line is a test failure.
std::vector<Vec2> parse_output(const std::string& text) {
  std::vector<Vec2> points;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    char* end = nullptr;
    const double x = std::strtod(line.c_str(), &end);
    char* after_y = nullptr;
    const double y = std::strtod(end, &after_y);
    EXPECT_TRUE(end != line.c_str() && after_y != end && *after_y == '\0')
        << "output line '" << line << "'";
    points.push_back({x, y});
  }
  return points;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

const char* const kSquareInput = "0 0\n4 0\n4 4\n0 4\n2 2\n";
const char* const kSquareOutput = "0 0\n4 0\n4 4\n0 4\n";

TEST(Cli, HullOfASquare) {
  const CliRun run = run_mink({"hull"}, kSquareInput);
  EXPECT_EQ(run.exit_code, mink::cli::kSuccess) << run.diagnostics();
  EXPECT_EQ(run.out, kSquareOutput);
  EXPECT_EQ(run.diagnostics(), "");
}

TEST(Cli, AcceptsEveryDocumentedInputFormat) {
  const std::string input =
      "# a comment\n"
      "\n"
      "0 0\n"
      "4\t0\r\n"
      "   \n"
      "4,4\n"
      "0 , 4\r\n"
      "  # indented comment\n"
      "+2 +1e0\n"
      "1e0\t, 2E0\n"
      "\t3.0   1.5  \n";
  const CliRun run = run_mink({"hull"}, input);
  EXPECT_EQ(run.exit_code, mink::cli::kSuccess) << run.diagnostics();
  EXPECT_EQ(run.out, kSquareOutput);
}

TEST(Cli, OutputRoundTripsEveryDoubleExactly) {
  // Full-precision coordinates of every magnitude, including subnormals and signed zeros.
  std::vector<Vec2> points;
  for (mink::PointDistribution distribution :
       {mink::PointDistribution::gaussian, mink::PointDistribution::far_from_origin,
        mink::PointDistribution::tiny, mink::PointDistribution::near_collinear}) {
    const auto more = mink::generate_points(distribution, 300, 21);
    points.insert(points.end(), more.begin(), more.end());
  }
  const double subnormal = std::numeric_limits<double>::denorm_min();
  points.insert(points.end(),
                {{-0.0, -1e300}, {5e-324, 1e300}, {1e300, -0.0}, {-1e300, 3 * subnormal}});
  for (const auto& input : {points, mink::generate_points(mink::PointDistribution::tiny, 500, 2),
                            mink::generate_points(mink::PointDistribution::on_circle, 500, 3)}) {
    const CliRun run = run_mink({"hull"}, format_input(input));
    ASSERT_EQ(run.exit_code, mink::cli::kSuccess) << run.diagnostics();
    EXPECT_TRUE(same_bits(mink_test::reference_hull(input), parse_output(run.out)));
  }
}

TEST(Cli, EveryAlgorithmGivesCgalsHull) {
  const auto points = mink::generate_points(mink::PointDistribution::clusters, 2'000, 22);
  const auto expected = mink_test::reference_hull(points);
  const std::string input = format_input(points);
  for (const char* algorithm : {"chan", "divide-conquer", "graham", "jarvis", "monotone-chain"}) {
    for (bool prefilter : {false, true}) {
      SCOPED_TRACE(testing::Message() << algorithm << (prefilter ? " --prefilter" : ""));
      std::vector<std::string> arguments = {"hull", "--algorithm", algorithm};
      if (prefilter) arguments.push_back("--prefilter");
      const CliRun run = run_mink(arguments, input);
      ASSERT_EQ(run.exit_code, mink::cli::kSuccess) << run.diagnostics();
      EXPECT_TRUE(same_bits(expected, parse_output(run.out)));
    }
  }
  const CliRun short_flag = run_mink({"hull", "-a", "jarvis"}, input);
  EXPECT_EQ(short_flag.exit_code, mink::cli::kSuccess);
  EXPECT_TRUE(same_bits(expected, parse_output(short_flag.out)));
}

TEST(Cli, ReadsAFileOrStandardInput) {
  // A random name, so parallel test processes never share the file.
  const auto path = std::filesystem::temp_directory_path() /
                    ("mink_cli_test_" + std::to_string(std::random_device{}()) + ".txt");
  {
    std::ofstream file(path);
    file << kSquareInput;
  }
  const CliRun from_file = run_mink({"hull", path.string()});
  const CliRun from_dash = run_mink({"hull", "-"}, kSquareInput);
  std::filesystem::remove(path);
  EXPECT_EQ(from_file.exit_code, mink::cli::kSuccess) << from_file.diagnostics();
  EXPECT_EQ(from_file.out, kSquareOutput);
  EXPECT_EQ(from_dash.exit_code, mink::cli::kSuccess) << from_dash.diagnostics();
  EXPECT_EQ(from_dash.out, kSquareOutput);
}

TEST(Cli, MalformedLinesExitTwoNamingTheLine) {
  for (const std::string bad : {"1", "1 2 3", "a b", "1;2", "1,,2", "1 2,", ",1 2", "x"}) {
    SCOPED_TRACE("'" + bad + "'");
    // The bad line is line 3 of the input.
    const CliRun run = run_mink({"hull"}, "0 0\n1 0\n" + bad + "\n0 1\n");
    EXPECT_EQ(run.exit_code, mink::cli::kBadInput);
    EXPECT_TRUE(contains(run.diagnostics(), "line 3:")) << run.diagnostics();
    EXPECT_EQ(run.out, "");
  }
}

TEST(Cli, NonFiniteValuesExitTwoNamingTheLine) {
  for (const std::string bad : {"nan 0", "0 NaN", "inf 1", "1 -inf", "-Infinity 2", "1e400 0"}) {
    SCOPED_TRACE("'" + bad + "'");
    const CliRun run = run_mink({"hull"}, "# points\n0 0\n1 0\n0 1\n" + bad + "\n");
    EXPECT_EQ(run.exit_code, mink::cli::kBadInput);
    EXPECT_TRUE(contains(run.diagnostics(), "line 5:")) << run.diagnostics();
    EXPECT_EQ(run.out, "");
  }
}

TEST(Cli, MissingFileExitsTwo) {
  const std::string path = "/nonexistent-mink-directory/points.txt";
  const CliRun run = run_mink({"hull", path});
  EXPECT_EQ(run.exit_code, mink::cli::kBadInput);
  EXPECT_TRUE(contains(run.diagnostics(), "cannot open")) << run.diagnostics();
  EXPECT_TRUE(contains(run.diagnostics(), path)) << run.diagnostics();
  EXPECT_EQ(run.out, "");
}

TEST(Cli, DegenerateSetsExitThreeWithAClearMessage) {
  struct Case {
    std::string input;
    std::string phrase;
  };
  for (const Case& c : std::vector<Case>{{"", "at least 3 points, got 0"},
                                         {"# nothing here\n\n", "at least 3 points, got 0"},
                                         {"1 1\n2 2\n", "at least 3 points, got 2"},
                                         {"1 1\n1 1\n1 1\n", "same point"},
                                         {"0 0\n1 1\n2 2\n3 3\n1 1\n", "one line"},
                                         {"5 0\n5 1\n5 -7\n", "one line"}}) {
    SCOPED_TRACE("input '" + c.input + "'");
    const CliRun run = run_mink({"hull"}, c.input);
    EXPECT_EQ(run.exit_code, mink::cli::kDegenerate);
    EXPECT_TRUE(contains(run.diagnostics(), c.phrase)) << run.diagnostics();
    EXPECT_EQ(run.out, "");
  }
}

TEST(Cli, ErrorMessagesGoToTheGivenErrorStream) {
  // run() takes its streams so a caller (or a test) sees every message; none may bypass them.
  for (const auto& [input, message] : std::vector<std::pair<std::string, std::string>>{
           {"0 0\nbad\n", "line 2:"}, {"0 0\n1 1\n", "at least 3 points"}}) {
    const CliRun run = run_mink({"hull"}, input);
    EXPECT_NE(run.exit_code, mink::cli::kSuccess);
    EXPECT_TRUE(contains(run.err, message))
        << "error stream: '" << run.err << "', std::cerr: '" << run.std_error << "'";
    EXPECT_EQ(run.std_error, "");
  }
}

TEST(Cli, TimeFlagPrintsOneTimingLineToTheErrorStreamOnly) {
  const CliRun plain = run_mink({"hull", "--algorithm", "graham"}, kSquareInput);
  const CliRun timed = run_mink({"hull", "--algorithm", "graham", "--time"}, kSquareInput);
  ASSERT_EQ(timed.exit_code, mink::cli::kSuccess) << timed.diagnostics();
  EXPECT_EQ(timed.out, plain.out);
  EXPECT_TRUE(contains(timed.err, "hull: 5 points -> 4 vertices in ")) << timed.err;
  EXPECT_TRUE(contains(timed.err, " ms (graham)")) << timed.err;
  EXPECT_EQ(std::count(timed.err.begin(), timed.err.end(), '\n'), 1) << timed.err;
  EXPECT_EQ(plain.err, "");

  const CliRun prefiltered = run_mink({"hull", "--time", "--prefilter"}, kSquareInput);
  EXPECT_TRUE(contains(prefiltered.err, "(chan, prefilter)")) << prefiltered.err;
  EXPECT_EQ(prefiltered.out, kSquareOutput);
}

TEST(Cli, MainHelpDescribesCommandsAndExitCodes) {
  for (const char* flag : {"--help", "-h"}) {
    const CliRun run = run_mink({flag});
    EXPECT_EQ(run.exit_code, mink::cli::kSuccess) << flag;
    EXPECT_TRUE(contains(run.out, "hull")) << run.out;
    EXPECT_TRUE(contains(run.out, "demo")) << run.out;
    EXPECT_TRUE(contains(run.out, "Exit codes")) << run.out;
    EXPECT_TRUE(contains(run.out, "one point per line")) << "input format missing:\n" << run.out;
  }
}

TEST(Cli, HullHelpDescribesInputOutputAndExitCodes) {
  const CliRun run = run_mink({"hull", "--help"});
  EXPECT_EQ(run.exit_code, mink::cli::kSuccess);
  for (const char* phrase : {"one point per line", "comma", "'#'", "17 significant digits",
                             "Exit codes", "--algorithm", "--prefilter", "--time"}) {
    EXPECT_TRUE(contains(run.out, phrase)) << "'" << phrase << "' missing:\n" << run.out;
  }
}

TEST(Cli, UsageErrorsExitTwo) {
  const std::vector<std::vector<std::string>> usages = {
      {},
      {"frobnicate"},
      {"--frobnicate"},
      {"hull", "--frobnicate"},
      {"hull", "--algorithm", "quickhull"},
      {"hull", "--algorithm"},
      {"hull", "a.txt", "b.txt"},
      {"demo", "--points", "2"},
  };
  for (const auto& arguments : usages) {
    std::string joined;
    for (const auto& argument : arguments) joined += " " + argument;
    const CliRun run = run_mink(arguments, kSquareInput);
    EXPECT_EQ(run.exit_code, mink::cli::kBadInput) << "mink" << joined;
    EXPECT_FALSE(run.diagnostics().empty()) << "mink" << joined;
    EXPECT_EQ(run.out, "") << "mink" << joined;
  }
}

TEST(Cli, DemoPrintsThePaperHulls) {
  const CliRun run = run_mink({"demo", "--seed", "7", "--points", "60", "--repeats", "1"});
  ASSERT_EQ(run.exit_code, mink::cli::kSuccess) << run.diagnostics();
  // Vertex lines are indented under "Hull A" and "Hull B".
  std::vector<std::vector<Vec2>> hulls;
  std::istringstream lines(run.out);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.rfind("Hull ", 0) == 0) {
      hulls.emplace_back();
    } else if (line.rfind("  ", 0) == 0 && !hulls.empty()) {
      const auto parsed = parse_output(line.substr(2));
      hulls.back().insert(hulls.back().end(), parsed.begin(), parsed.end());
    }
  }
  ASSERT_EQ(hulls.size(), 2u) << run.out;
  const auto [set_a, set_b] = mink::paper_point_sets(7, 60);
  EXPECT_TRUE(same_bits(mink_test::reference_hull(set_a), hulls[0]));
  EXPECT_TRUE(same_bits(mink_test::reference_hull(set_b), hulls[1]));
}

}  // namespace
