#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "brute_force_support.hpp"
#include "cli_test_support.hpp"
#include "exact_overlap_oracle.hpp"

#ifndef MINK_BINARY
#error "MINK_BINARY must name the built mink executable"
#endif

namespace {

using namespace mink_test;
using nlohmann::json;

#ifdef MINK_SANITIZED_BUILD
constexpr int kPairs = 300;
#else
constexpr int kPairs = 3000;
#endif

struct Query {
  std::vector<Vec2> a;
  std::vector<Vec2> b;
};

std::string to_line(const Query& q) {
  auto list = [](const std::vector<Vec2>& points) {
    std::string text = "[";
    char number[80];
    for (std::size_t i = 0; i < points.size(); ++i) {
      std::snprintf(number, sizeof number, "%s[%.17g, %.17g]", i > 0 ? ", " : "", points[i].x(),
                    points[i].y());
      text += number;
    }
    return text + "]";
  };
  return "{\"a\": " + list(q.a) + ", \"b\": " + list(q.b) + "}";
}

std::vector<Vec2> random_cloud(std::mt19937_64& rng, Vec2 centre, Real size, int count) {
  std::normal_distribution<Real> gauss(0, size);
  std::vector<Vec2> points;
  for (int i = 0; i < count; ++i) points.push_back(centre + Vec2(gauss(rng), gauss(rng)));
  return points;
}

// Held-out pairs no other test uses: random clouds of 3..60 points at random offsets, and
// pairs pushed to within 1e-12 of touching (either side) along the oracle's own normal.
std::vector<Query> held_out_queries(std::uint64_t seed, int count) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> points(3, 60);
  std::uniform_real_distribution<Real> offset(-3, 3);
  std::uniform_real_distribution<Real> size(0.2, 1.5);
  std::vector<Query> queries;
  for (int k = 0; k < count; ++k) {
    Query q;
    q.a = random_cloud(rng, Vec2(0, 0), size(rng), points(rng));
    q.b = random_cloud(rng, Vec2(offset(rng), offset(rng)), size(rng), points(rng));
    if (k % 4 == 3) {
      // Slide b along the x axis until it nearly touches a, from outside or inside.
      const auto ha = cgal_hull(q.a);
      Real lo = -10;
      Real hi = 10;
      auto shifted = [&](Real dx) {
        std::vector<Vec2> moved = q.b;
        for (Vec2& v : moved) v.x() += dx;
        return moved;
      };
      // Bisection on the exact verdict: the shift where b leaves a, moving right.
      Real mid = 0;
      for (int i = 0; i < 200; ++i) {
        mid = 0.5 * (lo + hi);
        if (exact_overlap(ha, cgal_hull(shifted(mid)))) {
          lo = mid;
        } else {
          hi = mid;
        }
        if (hi - lo < 1e-13) break;
      }
      q.b = shifted(k % 8 == 3 ? lo : hi);
    }
    queries.push_back(std::move(q));
  }
  return queries;
}

struct Checked {
  int overlapping = 0;
  int apart = 0;
};

void check_answer(const Query& q, const json& out, std::size_t index, Checked& checked) {
  SCOPED_TRACE("query " + std::to_string(index) + ": " + to_line(q));
  ASSERT_TRUE(out.contains("overlap")) << out.dump();
  const auto ha = cgal_hull(q.a);
  const auto hb = cgal_hull(q.b);
  const bool overlap = exact_overlap(ha, hb);
  ASSERT_EQ(out["overlap"].get<bool>(), overlap);
  const Real distance = out["distance"].get<Real>();
  const Real depth = out["depth"].get<Real>();
  const Vec2 normal(out["normal"][0].get<Real>(), out["normal"][1].get<Real>());
  EXPECT_NEAR(normal.norm(), 1, 1e-12);
  EXPECT_GE(distance, 0);
  EXPECT_GE(depth, 0);
  // Relative 1e-6, measured against at least 1e-9 (the pairs are of unit size).
  auto tolerance = [](Real expected) { return 1e-6 * std::max<Real>(expected, 1e-9); };
  if (overlap) {
    ++checked.overlapping;
    EXPECT_EQ(distance, 0);
    const Real expected = brute_depth(ha, hb).depth;
    EXPECT_NEAR(depth, expected, tolerance(expected));
    // The normal undoes the penetration: b moved by the depth (and a hair) is apart.
    std::vector<Vec2> moved = hb;
    for (Vec2& v : moved) v += (depth + 1e-9) * normal;
    EXPECT_FALSE(exact_overlap(ha, moved));
  } else {
    ++checked.apart;
    EXPECT_EQ(depth, 0);
    const Real expected = scan_distance(ha, hb);
    EXPECT_NEAR(distance, expected, tolerance(expected));
    // Moving b back along the normal by the distance closes the gap (to rounding: corner to
    // corner, the hulls then touch at a single point).
    std::vector<Vec2> moved = hb;
    for (Vec2& v : moved) v -= distance * normal;
    EXPECT_TRUE(exact_overlap(ha, moved) || scan_distance(ha, moved) < 1e-9);
  }
}

std::vector<json> parse_lines(const std::string& text) {
  std::vector<json> lines;
  std::istringstream stream(text);
  std::string line;
  while (std::getline(stream, line)) lines.push_back(json::parse(line));
  return lines;
}

TEST(OverlapCommand, HeldOutPairsAgainstTheExactOracle) {
  const std::vector<Query> queries = held_out_queries(0x5eedc0de, kPairs);
  std::string input;
  for (const Query& q : queries) input += to_line(q) + "\n";
  const CliResult r = run_cli({"overlap", "-"}, input);
  const std::vector<json> out = parse_lines(r.out);
  EXPECT_EQ(r.code, 0);
  ASSERT_EQ(out.size(), queries.size());
  Checked checked;
  for (std::size_t i = 0; i < queries.size(); ++i) check_answer(queries[i], out[i], i, checked);
  EXPECT_GT(checked.overlapping, kPairs / 5);
  EXPECT_GT(checked.apart, kPairs / 5);
}

TEST(OverlapCommand, TouchingIsOverlapWithZeroDepth) {
  const CliResult r =
      run_cli({"overlap", "-"},
              "{\"a\": [[0,0],[1,0],[1,1],[0,1]], \"b\": [[1,1],[2,1],[2,2],[1,2]]}\n"
              "{\"a\": [[0,0],[1,0],[1,1],[0,1]], \"b\": [[1,0.5],[2,0.5],[2,2]]}\n"
              "{\"a\": [[0,0],[1,0],[1,1],[0,1]], \"b\": [[1.0000000000000002,0],[2,0],[2,1]]}\n");
  const auto out = parse_lines(r.out);
  EXPECT_EQ(r.code, 0);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_TRUE(out[0]["overlap"].get<bool>());
  EXPECT_EQ(out[0]["depth"].get<Real>(), 0);
  EXPECT_TRUE(out[1]["overlap"].get<bool>());
  EXPECT_EQ(out[1]["depth"].get<Real>(), 0);
  EXPECT_FALSE(out[2]["overlap"].get<bool>());
  EXPECT_NEAR(out[2]["distance"].get<Real>(), 2.220446049250313e-16, 1e-30);
}

// Found by the overlap_line fuzz harness: a number beyond a double made the JSON parser throw
// out_of_range, which nothing caught, and the command ended in std::terminate.
TEST(OverlapCommand, ANumberTooLargeForADoubleIsAnErrorLine) {
  const CliResult r = run_cli({"overlap", "-"},
                              "{\"a\": [[1e999,0],[1,0],[0,1]], \"b\": [[3,0],[4,0],[3,1]]}\n"
                              "{\"a\": [[0,0],[1,0],[0,1]], \"b\": [[3,0],[4,0],[3,1]]}\n");
  const auto out = parse_lines(r.out);
  EXPECT_EQ(r.code, 2);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0]["error"].get<std::string>(), "line 1: a number is too large for a double");
  EXPECT_FALSE(out[1]["overlap"].get<bool>());
  EXPECT_EQ(out[1]["distance"].get<Real>(), 2);
}

// Found by the overlap_line fuzz harness: hulls 1e302 m apart gave "distance": inf, which is no
// JSON. Far-out point sets are now scaled by a power of two before GJK, so such a distance is
// answered; only a distance beyond a double (hulls at opposite ends of its range) is an error.
TEST(OverlapCommand, ADistanceTooLargeForADoubleIsAnErrorLine) {
  const CliResult r =
      run_cli({"overlap", "-"},
              "{\"a\": [[0,0],[1,0],[0,1]], \"b\": [[1e302,0],[2e302,0],[1e302,1]]}\n"
              "{\"a\": [[-1.7e308,0],[-1e308,0],[-1.7e308,1]], "
              "\"b\": [[1.7e308,0],[1e308,0],[1.7e308,1]]}\n");
  const auto out = parse_lines(r.out);
  EXPECT_EQ(r.code, 2);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_FALSE(out[0]["overlap"].get<bool>());
  EXPECT_EQ(out[0]["distance"].get<Real>(), 1e302);
  EXPECT_EQ(out[0]["normal"][0].get<Real>(), 1);
  EXPECT_EQ(out[0]["normal"][1].get<Real>(), 0);
  EXPECT_EQ(out[1]["error"].get<std::string>(),
            "line 2: the hulls' distance is too large for a double");
}

// Found by the overlap_line fuzz harness: far out, GJK's fourth powers of the coordinates
// overflowed in one order of a and b only, so swapping them changed the verdict; and a gap
// of 1e-21 beside coordinates of 1e200 came back with a normal 1e-5 off unit length.
TEST(OverlapCommand, FarOutAndTinyGapsKeepTheirVerdictAndAUnitNormal) {
  const std::string a = "[[1e200,2e200],[0,1.7e308],[0,0]]";
  const std::string b = "[[1e200,2e200],[0,1.7e308],[3,-3.7731483778295826e148],[0,-1]]";
  const CliResult r = run_cli(
      {"overlap", "-"},
      "{\"a\": " + a + ", \"b\": " + b + "}\n{\"a\": " + b + ", \"b\": " + a +
          "}\n"
          "{\"a\": [[0,2],[3,0],[0,0],[3e-300,5e-324]], "
          "\"b\": [[-1e200,9.999999999999999e-19],[2,-1.4898344417001195e-21],[0.001,-1]]}\n");
  const auto out = parse_lines(r.out);
  EXPECT_EQ(r.code, 0);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_TRUE(out[0]["overlap"].get<bool>());
  EXPECT_TRUE(out[1]["overlap"].get<bool>());
  EXPECT_FALSE(out[2]["overlap"].get<bool>());
  EXPECT_EQ(out[2]["distance"].get<Real>(), 1.4898344417001195e-21);
  const Real nx = out[2]["normal"][0].get<Real>(), ny = out[2]["normal"][1].get<Real>();
  EXPECT_NEAR(std::hypot(nx, ny), 1, 1e-15);
  EXPECT_EQ(ny, -1);
}

TEST(OverlapCommand, BadLinesAreReportedAndTheRestAnswered) {
  const CliResult r = run_cli({"overlap", "-"},
                              "{\"a\": [[0,0],[1,0],[0,1]], \"b\": [[3,0],[4,0],[3,1]]}\n"
                              "not json\n"
                              "\n"
                              "{\"a\": [[0,0],[1,0],[2,0]], \"b\": [[3,0],[4,0],[3,1]]}\n"
                              "{\"a\": [[0,0],[1,0],[0,1]]}\n"
                              "{\"a\": [[0,0],[1,0],[0,\"x\"]], \"b\": [[3,0],[4,0],[3,1]]}\n"
                              "{\"a\": [[0,0],[1,0],[0,1]], \"b\": [[3,0],[4,0],[3,1]], \"c\": 1}\n"
                              "[1, 2]\n"
                              "{\"a\": [[0,0],[1,0],[0,1]], \"b\": [[0,0],[1,0],[0,1]]}\n");
  const auto out = parse_lines(r.out);
  EXPECT_EQ(r.code, 2);
  ASSERT_EQ(out.size(), 8u);
  EXPECT_FALSE(out[0]["overlap"].get<bool>());
  EXPECT_EQ(out[0]["distance"].get<Real>(), 2);
  const char* const expected_errors[] = {
      "line 2: not valid JSON",
      "line 4: a: all 3 points lie on one line",
      "line 5: needs both \"a\" and \"b\"",
      "line 6: a[2] is not a pair of numbers [x, y]",
      "line 7: unexpected key \"c\"",
      "line 8: expected an object {\"a\": [...], \"b\": [...]}",
  };
  for (std::size_t i = 0; i < std::size(expected_errors); ++i) {
    ASSERT_TRUE(out[i + 1].contains("error")) << out[i + 1].dump();
    EXPECT_EQ(out[i + 1]["error"].get<std::string>(), expected_errors[i]);
  }
  EXPECT_TRUE(out[7]["overlap"].get<bool>());
  EXPECT_NEAR(out[7]["depth"].get<Real>(), std::sqrt(0.5), 1e-15);
}

TEST(OverlapCommand, UnreadableFileIsBadInput) {
  const CliResult r = run_cli({"overlap", "/nonexistent/queries.jsonl"});
  EXPECT_EQ(r.code, 2);
}

// The real binary, reading a file: same answers, same exit code.
TEST(OverlapCommand, RealProcessReadsAFile) {
  const std::vector<Query> queries = held_out_queries(0xfeedbeef, 200);
  const auto dir = fresh_dir("overlap_" + std::to_string(std::random_device{}()));
  const auto input = dir / "queries.jsonl";
  const auto output = dir / "answers.jsonl";
  std::string lines;
  for (const Query& q : queries) lines += to_line(q) + "\n";
  write_text(input, lines);
  const std::string command =
      std::string(MINK_BINARY) + " overlap '" + input.string() + "' > '" + output.string() + "'";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  const std::vector<json> out = parse_lines(read_text(output));
  ASSERT_EQ(out.size(), queries.size());
  Checked checked;
  for (std::size_t i = 0; i < queries.size(); ++i) check_answer(queries[i], out[i], i, checked);
  std::filesystem::remove_all(dir);
}

}  // namespace
