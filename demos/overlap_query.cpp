#include "overlap_query.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <vector>

#include "mink/error.hpp"
#include "mink/geometry/convex_hull.hpp"
#include "mink/narrowphase/gjk_distance.hpp"
#include "mink/narrowphase/gjk_overlap.hpp"
#include "mink/narrowphase/penetration.hpp"

namespace mink::cli {

namespace {

PreparedHull hull_named(std::span<const Vec2> points, const char* name) {
  try {
    return PreparedHull(build_hull(points, HullAlgorithm::monotone_chain));
  } catch (const DegenerateInputError& error) {
    throw DegenerateInputError(std::string(name) + ": " + error.what());
  } catch (const Error& error) {
    // Non-finite points, or a hull wider than a double.
    throw InvalidArgumentError(std::string(name) + ": " + error.what());
  }
}

std::vector<Vec2> read_point_list(const nlohmann::json& value, const char* name) {
  if (!value.is_array()) throw InvalidArgumentError(std::string(name) + " is not an array");
  std::vector<Vec2> points;
  for (std::size_t i = 0; i < value.size(); ++i) {
    const nlohmann::json& p = value[i];
    if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number()) {
      throw InvalidArgumentError(std::string(name) + "[" + std::to_string(i) +
                                 "] is not a pair of numbers [x, y]");
    }
    const Vec2 v(p[0].get<Real>(), p[1].get<Real>());
    if (!std::isfinite(v.x()) || !std::isfinite(v.y())) {
      throw InvalidArgumentError(std::string(name) + "[" + std::to_string(i) +
                                 "] has a non-finite coordinate");
    }
    points.push_back(v);
  }
  return points;
}

std::string format_number(Real value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

}  // namespace

namespace {

// GJK's answer, and the exact verdict where the gap is within rounding of zero.
OverlapAnswer measure_overlap(const PreparedHull& a, const PreparedHull& b) {
  const Pose identity{};
  const DistanceResult d = gjk_distance(a, identity, b, identity);
  OverlapAnswer answer;
  answer.iterations = d.iterations;
  if (d.overlap) {
    const PenetrationResult p = penetration(a, identity, b, identity, d.simplex);
    answer.overlap = true;
    answer.depth = p.depth;
    answer.normal = p.normal;
    answer.iterations += p.iterations;
  } else {
    answer.distance = d.distance;
    answer.normal = d.normal;
  }
  Real magnitude = 0;
  for (const auto* hull : {&a, &b}) {
    for (const Vec2& v : hull->vertices()) {
      magnitude = std::max({magnitude, std::abs(v.x()), std::abs(v.y())});
    }
  }
  const Real gap = answer.overlap ? answer.depth : answer.distance;
  if (gap > 1e-9 * magnitude) return answer;
  const bool exact = hulls_overlap_exact(a.vertices(), b.vertices());
  if (exact == answer.overlap) return answer;
  if (exact) {
    const PenetrationResult p = penetration_by_faces(a, identity, b, identity);
    answer = {true, 0, p.depth, p.normal, answer.iterations};
  } else {
    // Rare: GJK's rounding saw touching where the exact test sees a gap.
    const BruteDistance scanned = hull_distance_brute(a.vertices(), b.vertices());
    answer = {false, scanned.distance, 0, scanned.normal, answer.iterations};
  }
  return answer;
}

}  // namespace

OverlapAnswer answer_overlap(std::span<const Vec2> a_points, std::span<const Vec2> b_points) {
  // GJK's simplex solve multiplies two cross products of differences, a fourth power of the
  // coordinates: from about 1e76 on it overflows, in one order of a and b and not the other.
  // Sets reaching beyond 2^200 are scaled by a power of two down to that magnitude, which
  // changes no digit of any coordinate (scaling them to unit size instead would have small
  // gaps' squares underflow); the lengths found are scaled back.
  Real magnitude = 0;
  for (const auto points : {a_points, b_points}) {
    for (const Vec2& p : points) {
      magnitude = std::max({magnitude, std::abs(p.x()), std::abs(p.y())});
    }
  }
  constexpr int kLargestUnscaledExponent = 200;
  const int scale = magnitude > std::ldexp(Real(1), kLargestUnscaledExponent + 1)
                        ? std::ilogb(magnitude) - kLargestUnscaledExponent
                        : 0;
  // Scaling by 2^0 changes nothing, so every query takes the same path.
  const auto prepared = [scale](std::span<const Vec2> points, const char* name) {
    std::vector<Vec2> scaled;
    scaled.reserve(points.size());
    for (const Vec2& p : points) {
      scaled.emplace_back(std::ldexp(p.x(), -scale), std::ldexp(p.y(), -scale));
    }
    return hull_named(scaled, name);
  };
  OverlapAnswer answer = measure_overlap(prepared(a_points, "a"), prepared(b_points, "b"));
  answer.distance = std::ldexp(answer.distance, scale);
  answer.depth = std::ldexp(answer.depth, scale);
  // Hulls at opposite ends of the doubles' range have a distance (or a depth) beyond a double:
  // say so rather than print an infinity, which is no JSON number.
  if (!std::isfinite(answer.distance) || !std::isfinite(answer.depth) ||
      !answer.normal.allFinite()) {
    throw InvalidArgumentError(std::string("the hulls' ") +
                               (answer.overlap ? "penetration depth" : "distance") +
                               " is too large for a double");
  }
  return answer;
}

std::string overlap_line(std::string_view line, std::size_t line_number, bool& ok) {
  ok = false;
  const std::string where = "line " + std::to_string(line_number) + ": ";
  auto error_line = [&](const std::string& problem) {
    return "{\"error\": " + nlohmann::json(where + problem).dump() + "}";
  };
  nlohmann::json query;
  try {
    query = nlohmann::json::parse(line);
  } catch (const nlohmann::json::parse_error&) {
    return error_line("not valid JSON");
  } catch (const nlohmann::json::out_of_range&) {
    // The parser throws this, not parse_error, for a number beyond a double (1e999).
    return error_line("a number is too large for a double");
  }
  if (!query.is_object()) return error_line("expected an object {\"a\": [...], \"b\": [...]}");
  for (const auto& item : query.items()) {
    if (item.key() != "a" && item.key() != "b") {
      return error_line("unexpected key \"" + item.key() + "\"");
    }
  }
  if (!query.contains("a") || !query.contains("b")) return error_line("needs both \"a\" and \"b\"");
  try {
    const std::vector<Vec2> a = read_point_list(query["a"], "a");
    const std::vector<Vec2> b = read_point_list(query["b"], "b");
    const OverlapAnswer r = answer_overlap(a, b);
    ok = true;
    return std::string("{\"overlap\": ") + (r.overlap ? "true" : "false") +
           ", \"distance\": " + format_number(r.distance) +
           ", \"depth\": " + format_number(r.depth) + ", \"normal\": [" +
           format_number(r.normal.x()) + ", " + format_number(r.normal.y()) +
           "], \"iterations\": " + std::to_string(r.iterations) + "}";
  } catch (const Error& error) {
    return error_line(error.what());
  }
}

}  // namespace mink::cli
