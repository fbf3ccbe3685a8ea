#include <gtest/gtest.h>
#include <sys/wait.h>

#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "mink/geometry/point_sets.hpp"
#include "test_support.hpp"

#ifndef MINK_BINARY
#error "MINK_BINARY must name the built mink executable"
#endif

namespace {

namespace fs = std::filesystem;
using mink::Vec2;
using mink_test::same_bits;

struct ProcessResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

std::string shell_quote(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) {
    if (c == '\'') {
      quoted += "'\\''";
    } else {
      quoted += c;
    }
  }
  return quoted + "'";
}

std::string read_whole_file(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

// Writes points in every accepted style, chosen at random per line (separators, signs, CRLF,
// comments, blank lines), with 17 significant digits so the doubles read back exactly.
std::string format_points_file(const std::vector<Vec2>& points, std::mt19937_64& random) {
  static const char* const kSeparators[] = {" ", "\t", ",", " , ", "\t,  ", "   "};
  std::string text = "# generated points\n";
  char number[40];
  for (const Vec2& p : points) {
    const std::uint64_t style = random();
    if (style % 17 == 0) text += "# comment\n";
    if (style % 19 == 0) text += "\n";
    std::snprintf(number, sizeof number, "%.17g", p.x());
    if (style % 5 == 0 && p.x() >= 0) text += "+";
    text += number;
    text += kSeparators[(style >> 8) % std::size(kSeparators)];
    std::snprintf(number, sizeof number, "%.17g", p.y());
    text += number;
    text += (style >> 16) % 3 == 0 ? "\r\n" : "\n";
  }
  return text;
}

std::vector<Vec2> parse_hull_output(const std::string& text) {
  std::vector<Vec2> points;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    char* end_x = nullptr;
    char* end_y = nullptr;
    const double x = std::strtod(line.c_str(), &end_x);
    const double y = std::strtod(end_x, &end_y);
    EXPECT_TRUE(end_x != line.c_str() && end_y != end_x && *end_y == '\0')
        << "output line '" << line << "'";
    points.push_back({x, y});
  }
  return points;
}

// Runs the real binary on files it has never seen: a fresh directory and a fresh seed per
// test, both printed so a failure can be reproduced.
class CliProcess : public testing::Test {
 protected:
  void SetUp() override {
    std::random_device device;
    const auto now = std::chrono::steady_clock::now().time_since_epoch().count();
    seed_ = ((std::uint64_t{device()} << 32) | device()) ^ static_cast<std::uint64_t>(now);
    random_.seed(seed_);
    directory_ = fs::temp_directory_path() / ("mink_cli_process_" + std::to_string(seed_));
    fs::create_directories(directory_);
    std::cout << "point seed " << seed_ << ", files in " << directory_ << std::endl;
  }

  void TearDown() override {
    // Keep the files of a failed test for inspection.
    if (!HasFailure()) fs::remove_all(directory_);
  }

  std::string seed_note() const { return "point seed " + std::to_string(seed_); }

  fs::path write_file(const std::string& name, const std::string& text) {
    const fs::path path = directory_ / name;
    std::ofstream file(path, std::ios::binary);
    file << text;
    return path;
  }

  // `mink <arguments>` with standard input from `input` (or empty).
  ProcessResult run(const std::string& arguments, const fs::path& input = "/dev/null") {
    const fs::path out = directory_ / "stdout.txt";
    const fs::path err = directory_ / "stderr.txt";
    const std::string command = shell_quote(MINK_BINARY) + " " + arguments + " < " +
                                shell_quote(input.string()) + " > " + shell_quote(out.string()) +
                                " 2> " + shell_quote(err.string());
    const int status = std::system(command.c_str());
    ProcessResult result;
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.out = read_whole_file(out);
    result.err = read_whole_file(err);
    return result;
  }

  std::uint64_t seed_ = 0;
  std::mt19937_64 random_;
  fs::path directory_;
};

// Points at a random scale from 2^-60 to 2^60 each: hulls over mixed magnitudes.
std::vector<Vec2> mixed_scale_points(std::size_t count, std::mt19937_64& random) {
  std::vector<Vec2> points;
  for (std::size_t i = 0; i < count; ++i) {
    const int exponent = static_cast<int>(random() % 121) - 60;
    const double x = 2 * mink_test::unit_double(random()) - 1;
    const double y = 2 * mink_test::unit_double(random()) - 1;
    points.push_back({std::ldexp(x, exponent), std::ldexp(y, exponent)});
  }
  return points;
}

TEST_F(CliProcess, RandomPointFilesMatchCgalForEveryAlgorithm) {
  SCOPED_TRACE(seed_note());
  std::vector<std::pair<std::string, std::vector<Vec2>>> sets;
  for (mink::PointDistribution distribution : mink::all_point_distributions()) {
    sets.emplace_back(mink::to_string(distribution),
                      mink::generate_points(distribution, 500 + random_() % 3'000, random_()));
  }
  sets.emplace_back("mixed-scales", mixed_scale_points(2'000, random_));

  for (const auto& [name, points] : sets) {
    SCOPED_TRACE(name + ", " + std::to_string(points.size()) + " points");
    const fs::path file = write_file(name + ".txt", format_points_file(points, random_));
    const auto expected = mink_test::reference_hull(points);
    for (const char* algorithm : {"chan", "divide-conquer", "graham", "jarvis", "monotone-chain"}) {
      for (const char* prefilter : {"", " --prefilter"}) {
        SCOPED_TRACE(std::string(algorithm) + prefilter);
        const ProcessResult result = run("hull --algorithm " + std::string(algorithm) + prefilter +
                                         " " + shell_quote(file.string()));
        if (expected.size() < 3) {
          EXPECT_EQ(result.exit_code, 3) << result.err;
          continue;
        }
        ASSERT_EQ(result.exit_code, 0) << result.err;
        EXPECT_EQ(result.err, "");
        EXPECT_TRUE(same_bits(expected, parse_hull_output(result.out)));
      }
    }
  }
}

TEST_F(CliProcess, StandardInputAndFileArgumentAgree) {
  SCOPED_TRACE(seed_note());
  const auto points = mink::generate_points(mink::PointDistribution::gaussian, 1'000, random_());
  const fs::path file = write_file("points.txt", format_points_file(points, random_));
  const ProcessResult by_name = run("hull " + shell_quote(file.string()));
  const ProcessResult by_dash = run("hull -", file);
  const ProcessResult by_default = run("hull", file);
  ASSERT_EQ(by_name.exit_code, 0) << by_name.err;
  EXPECT_TRUE(same_bits(mink_test::reference_hull(points), parse_hull_output(by_name.out)));
  EXPECT_EQ(by_dash.exit_code, 0) << by_dash.err;
  EXPECT_EQ(by_dash.out, by_name.out);
  EXPECT_EQ(by_default.exit_code, 0) << by_default.err;
  EXPECT_EQ(by_default.out, by_name.out);
}

TEST_F(CliProcess, DegenerateFilesExitThree) {
  SCOPED_TRACE(seed_note());
  // Random integer points on y = 3x - 7 (exact), and a file of one repeated point.
  std::string collinear;
  for (int i = 0; i < 200; ++i) {
    const long x = static_cast<long>(random_() % 2'000'001) - 1'000'000;
    collinear += std::to_string(x) + " " + std::to_string(3 * x - 7) + "\n";
  }
  const ProcessResult on_a_line = run("hull " + shell_quote(write_file("line.txt", collinear)));
  EXPECT_EQ(on_a_line.exit_code, 3);
  EXPECT_NE(on_a_line.err.find("one line"), std::string::npos) << on_a_line.err;
  EXPECT_EQ(on_a_line.out, "");

  const ProcessResult same = run("hull", write_file("same.txt", "2.5 -1\n2.5 -1\n2.5,-1\n"));
  EXPECT_EQ(same.exit_code, 3);
  EXPECT_NE(same.err.find("same point"), std::string::npos) << same.err;

  const ProcessResult too_few = run("hull", write_file("two.txt", "0 0\n1 1\n"));
  EXPECT_EQ(too_few.exit_code, 3);
}

TEST_F(CliProcess, MalformedFilesExitTwoNamingTheLine) {
  SCOPED_TRACE(seed_note());
  const std::vector<std::string> bad_lines = {"1",    "1 2 3", "a b",   "1;2",
                                              "1,,2", "nan 1", "1 inf", "1e999 2"};
  for (int trial = 0; trial < 4; ++trial) {
    const std::string bad = bad_lines[random_() % bad_lines.size()];
    const std::size_t bad_line = 1 + random_() % 40;
    std::string text;
    for (std::size_t line = 1; line < bad_line; ++line) {
      text += std::to_string(random_() % 100) + " " + std::to_string(random_() % 100) + "\n";
    }
    text += bad + "\n0 0\n1 0\n0 1\n";
    SCOPED_TRACE("'" + bad + "' on line " + std::to_string(bad_line));
    const ProcessResult result = run("hull", write_file("bad.txt", text));
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_NE(result.err.find("line " + std::to_string(bad_line) + ":"), std::string::npos)
        << result.err;
    EXPECT_EQ(result.out, "");
  }
}

TEST_F(CliProcess, UsageErrorsAndHelp) {
  const ProcessResult missing = run("hull " + shell_quote((directory_ / "absent.txt").string()));
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("cannot open"), std::string::npos) << missing.err;

  EXPECT_EQ(run("frobnicate").exit_code, 2);
  EXPECT_EQ(run("hull --frobnicate").exit_code, 2);
  EXPECT_EQ(run("hull --algorithm quickhull").exit_code, 2);
  EXPECT_EQ(run("").exit_code, 2);

  const ProcessResult help = run("--help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("Exit codes"), std::string::npos) << help.out;
  const ProcessResult hull_help = run("hull --help");
  EXPECT_EQ(hull_help.exit_code, 0);
  EXPECT_NE(hull_help.out.find("one point per line"), std::string::npos) << hull_help.out;
}

TEST_F(CliProcess, TimeGoesToStandardErrorOnly) {
  SCOPED_TRACE(seed_note());
  const auto points =
      mink::generate_points(mink::PointDistribution::uniform_disk, 5'000, random_());
  const fs::path file = write_file("points.txt", format_points_file(points, random_));
  const ProcessResult plain = run("hull " + shell_quote(file.string()));
  const ProcessResult timed = run("hull --time " + shell_quote(file.string()));
  ASSERT_EQ(timed.exit_code, 0) << timed.err;
  EXPECT_EQ(timed.out, plain.out);
  EXPECT_NE(timed.err.find("hull: 5000 points -> "), std::string::npos) << timed.err;
  EXPECT_NE(timed.err.find(" ms (chan)"), std::string::npos) << timed.err;
  EXPECT_EQ(plain.err, "");
}

}  // namespace
