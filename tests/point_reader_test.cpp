#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "mink/geometry/types.hpp"
#include "point_reader.hpp"

namespace {

using mink::Vec2;

struct GoodLine {
  std::string text;
  double x;
  double y;
};

// Bitwise, so that -0 and +0 count as different values.
bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

TEST(PointReader, AcceptsEveryDocumentedFormat) {
  const std::vector<GoodLine> lines = {
      {"1 2", 1, 2},
      {"  1   2  ", 1, 2},
      {"1\t2", 1, 2},
      {"\t1 \t 2\t", 1, 2},
      {"1,2", 1, 2},
      {"1 , 2", 1, 2},
      {"1 ,2", 1, 2},
      {"1,\t2", 1, 2},
      {"1 2\r", 1, 2},
      {"1,2\r", 1, 2},
      {"+1 +2", 1, 2},
      {"-1.5 -2.25", -1.5, -2.25},
      {"1e3 2E-3", 1e3, 2e-3},
      {"1.e1 .5", 10, 0.5},
      {"-0 0", -0.0, 0.0},
      {"0.1 0.2", 0.1, 0.2},
      {"4.9406564584124654e-324 1.7976931348623157e308", std::numeric_limits<double>::denorm_min(),
       std::numeric_limits<double>::max()},
      {"0.30000000000000004 -123456789012345678", 0.30000000000000004, -123456789012345678.0},
  };
  for (const GoodLine& line : lines) {
    Vec2 point(-99, -99);
    ASSERT_TRUE(mink::cli::parse_point_line(line.text, 7, point)) << "'" << line.text << "'";
    EXPECT_TRUE(same_bits(point.x(), line.x) && same_bits(point.y(), line.y))
        << "'" << line.text << "' read as " << point.x() << " " << point.y();
  }
}

TEST(PointReader, SkipsBlankAndCommentLines) {
  for (const std::string line : {"", "   ", "\t", "\r", "# a comment", "   # indented", "#1 2"}) {
    Vec2 point(-99, -99);
    EXPECT_FALSE(mink::cli::parse_point_line(line, 1, point)) << "'" << line << "'";
  }
}

struct BadLine {
  std::string text;
  std::string problem;  // part of the expected message
};

TEST(PointReader, RejectsMalformedLinesNamingTheLineAndProblem) {
  const std::vector<BadLine> lines = {
      {"1", "missing y"},
      {"1 ", "missing y"},
      {"1,", "missing y"},
      {",1 2", "missing x"},
      {"1 2 3", "'3'"},
      {"1 2,", "','"},
      {"a b", "'a' is not a number"},
      {"1 b", "'b' is not a number"},
      {"1;2", "after x"},
      {"1,,2", "missing y"},
      {"1 2 # comment", "after the two coordinates"},
      {"nan 1", "not finite"},
      {"1 nan", "not finite"},
      {"inf 0", "not finite"},
      {"0 -inf", "not finite"},
      {"1e999 0", "out of range"},
      {"0 -1e400", "out of range"},
      {"0x10 1", "after x"},
      {"+-1 2", "not a number"},
      {"++1 2", "not a number"},
  };
  for (const BadLine& line : lines) {
    Vec2 point;
    try {
      mink::cli::parse_point_line(line.text, 12, point);
      ADD_FAILURE() << "accepted '" << line.text << "' as " << point.x() << " " << point.y();
    } catch (const mink::cli::ParseError& error) {
      EXPECT_EQ(error.line(), 12u);
      const std::string message = error.what();
      EXPECT_EQ(message.rfind("line 12: ", 0), 0u) << message;
      EXPECT_NE(message.find(line.problem), std::string::npos)
          << "'" << line.text << "': message '" << message << "' lacks '" << line.problem << "'";
    }
  }
}

TEST(PointReader, ReadsAStreamCountingEveryLine) {
  std::istringstream input("# header\r\n0 0\r\n\r\n4,0\n  \n4 , 4\n# done\n0\t4");
  const auto points = mink::cli::read_points(input);
  const std::vector<Vec2> expected = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  EXPECT_EQ(points, expected);
}

TEST(PointReader, ReportsTheLineNumberOfTheFirstBadLine) {
  // Comments and blank lines count: the bad line is the fifth.
  std::istringstream input("# header\n0 0\n\n1 1\n1 x\n2 2\nbad\n");
  try {
    mink::cli::read_points(input);
    ADD_FAILURE() << "no exception";
  } catch (const mink::cli::ParseError& error) {
    EXPECT_EQ(error.line(), 5u);
    EXPECT_EQ(std::string(error.what()).rfind("line 5: ", 0), 0u) << error.what();
  }
}

TEST(PointReader, EmptyInputHasNoPoints) {
  std::istringstream empty("");
  EXPECT_TRUE(mink::cli::read_points(empty).empty());
  std::istringstream comments("# only\n\n# comments\n");
  EXPECT_TRUE(mink::cli::read_points(comments).empty());
}

}  // namespace
