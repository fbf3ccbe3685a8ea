#include "mink/geometry/point_sets.hpp"

#include <array>
#include <cmath>
#include <numbers>

#include "mink/error.hpp"

namespace mink {

namespace {

// xoshiro256** seeded by splitmix64: small, fast, and fully specified, so a seed means the
// same points everywhere.
class Random {
 public:
  explicit Random(std::uint64_t seed) {
    for (auto& word : state_) {
      seed += 0x9e3779b97f4a7c15ULL;
      std::uint64_t z = seed;
      z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
      z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
      word = z ^ (z >> 31);
    }
  }
  std::uint64_t next() {
    const std::uint64_t result = rotl(state_[1] * 5, 7) * 9;
    const std::uint64_t t = state_[1] << 17;
    state_[2] ^= state_[0];
    state_[3] ^= state_[1];
    state_[1] ^= state_[2];
    state_[0] ^= state_[3];
    state_[2] ^= t;
    state_[3] = rotl(state_[3], 45);
    return result;
  }
  Real unit() { return static_cast<Real>(next() >> 11) * 0x1p-53; }  // [0, 1)
  Real symmetric() { return 2 * unit() - 1; }                        // [-1, 1)
  Real normal() {  // Box-Muller; 1 - unit() is in (0, 1], so the log is finite
    const Real radius = std::sqrt(-2 * std::log(1 - unit()));
    return radius * std::cos(2 * std::numbers::pi * unit());
  }
  std::uint64_t below(std::uint64_t bound) { return next() % bound; }

 private:
  static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  std::array<std::uint64_t, 4> state_{};
};

Vec2 in_unit_disk(Random& random) {
  for (;;) {
    const Vec2 p(random.symmetric(), random.symmetric());
    if (p.squaredNorm() <= 1) return p;
  }
}

constexpr std::array<PointDistribution, 9> kDistributions = {PointDistribution::uniform_disk,
                                                             PointDistribution::uniform_square,
                                                             PointDistribution::gaussian,
                                                             PointDistribution::on_circle,
                                                             PointDistribution::lattice,
                                                             PointDistribution::clusters,
                                                             PointDistribution::near_collinear,
                                                             PointDistribution::far_from_origin,
                                                             PointDistribution::tiny};

}  // namespace

std::string_view to_string(PointDistribution distribution) noexcept {
  switch (distribution) {
    case PointDistribution::uniform_disk:
      return "uniform-disk";
    case PointDistribution::uniform_square:
      return "uniform-square";
    case PointDistribution::gaussian:
      return "gaussian";
    case PointDistribution::on_circle:
      return "on-circle";
    case PointDistribution::lattice:
      return "lattice";
    case PointDistribution::clusters:
      return "clusters";
    case PointDistribution::near_collinear:
      return "near-collinear";
    case PointDistribution::far_from_origin:
      return "far-from-origin";
    case PointDistribution::tiny:
      return "tiny";
  }
  return "unknown";
}

std::span<const PointDistribution> all_point_distributions() noexcept {
  return kDistributions;
}

std::vector<Vec2> generate_points(PointDistribution distribution, std::size_t count,
                                  std::uint64_t seed) {
  Random random(seed);
  std::vector<Vec2> points;
  points.reserve(count);
  switch (distribution) {
    case PointDistribution::uniform_disk:
      for (std::size_t i = 0; i < count; ++i) points.push_back(in_unit_disk(random));
      break;
    case PointDistribution::uniform_square:
      for (std::size_t i = 0; i < count; ++i) {
        points.emplace_back(random.symmetric(), random.symmetric());
      }
      break;
    case PointDistribution::gaussian:
      for (std::size_t i = 0; i < count; ++i) points.emplace_back(random.normal(), random.normal());
      break;
    case PointDistribution::on_circle:
      for (std::size_t i = 0; i < count; ++i) {
        const Real angle = 2 * std::numbers::pi * random.unit();
        points.emplace_back(std::cos(angle), std::sin(angle));
      }
      break;
    case PointDistribution::lattice: {
      // About two points per grid cell, so duplicates and long collinear runs are common.
      const auto side = static_cast<std::uint64_t>(std::ceil(std::sqrt(count / 2.0))) + 2;
      for (std::size_t i = 0; i < count; ++i) {
        points.emplace_back(static_cast<Real>(random.below(side)),
                            static_cast<Real>(random.below(side)));
      }
      break;
    }
    case PointDistribution::clusters: {
      std::array<Vec2, 5> centres;
      for (Vec2& c : centres) c = Vec2(random.symmetric(), random.symmetric());
      for (std::size_t i = 0; i < count; ++i) {
        const Vec2& c = centres[random.below(centres.size())];
        points.emplace_back(c.x() + 1e-3 * random.normal(), c.y() + 1e-3 * random.normal());
      }
      break;
    }
    case PointDistribution::near_collinear:
      // On y = 0.3 x + 0.1 up to rounding, then nudged by up to 3 ulps: naive orientation
      // signs are noise here.
      for (std::size_t i = 0; i < count; ++i) {
        const Real x = random.symmetric();
        Real y = 0.3 * x + 0.1;
        const int nudges = static_cast<int>(random.below(7)) - 3;
        for (int k = 0; k < std::abs(nudges); ++k) {
          y = std::nextafter(y, nudges > 0 ? INFINITY : -INFINITY);
        }
        points.emplace_back(x, y);
      }
      break;
    case PointDistribution::far_from_origin:
      for (std::size_t i = 0; i < count; ++i) {
        points.push_back(Vec2(1e9, -3e9) + in_unit_disk(random));
      }
      break;
    case PointDistribution::tiny:
      for (std::size_t i = 0; i < count; ++i) points.push_back(1e-300 * in_unit_disk(random));
      break;
  }
  return points;
}

std::pair<std::vector<Vec2>, std::vector<Vec2>> paper_point_sets(std::uint64_t seed,
                                                                 std::size_t count) {
  if (count < 3) throw InvalidArgumentError("paper point sets need at least 3 points each");
  Random random(seed);
  std::vector<Vec2> first;
  std::vector<Vec2> second;
  for (std::size_t i = 0; i < count; ++i)
    first.emplace_back(400 * random.unit(), 400 * random.unit());
  for (std::size_t i = 0; i < count; ++i)
    second.emplace_back(400 * random.unit(), 400 * random.unit());
  return {std::move(first), std::move(second)};
}

}  // namespace mink
