#pragma once
// A scene at the origin and the same scene 10^7 m out, stepped side by side until both sleep,
// for any engine: how far apart (less the offset) their bodies end, and when each fell asleep.
// bench/run_large_world.sh runs it on Minkowski and on Box2D v3's float and double builds.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace mink::bench {

inline constexpr double kLargeWorldOffset = 1e7;
inline constexpr int kLargeWorldMaxSteps = 3000;

// What a world offers the comparison.
struct BodyPlace {
  double x, y, angle;
};
class SettlingWorld {
 public:
  virtual ~SettlingWorld() = default;
  virtual void step() = 0;
  virtual bool asleep() const = 0;  // every dynamic body
  virtual std::vector<BodyPlace> places() const = 0;
};

struct SettleResult {
  int origin_sleep_step = -1, far_sleep_step = -1;  // -1: awake after kLargeWorldMaxSteps
  double position_difference = 0, angle_difference = 0;
  bool finite = true;
};

inline SettleResult settle_side_by_side(SettlingWorld& origin, SettlingWorld& far) {
  SettleResult r;
  for (int step = 1; step <= kLargeWorldMaxSteps; ++step) {
    if (r.origin_sleep_step < 0) origin.step();
    if (r.far_sleep_step < 0) far.step();
    if (r.origin_sleep_step < 0 && origin.asleep()) r.origin_sleep_step = step;
    if (r.far_sleep_step < 0 && far.asleep()) r.far_sleep_step = step;
    if (r.origin_sleep_step >= 0 && r.far_sleep_step >= 0) break;
  }
  const std::vector<BodyPlace> near_places = origin.places(), far_places = far.places();
  for (std::size_t i = 0; i < near_places.size() && i < far_places.size(); ++i) {
    const BodyPlace& a = near_places[i];
    const BodyPlace& b = far_places[i];
    const double dx = (b.x - kLargeWorldOffset) - a.x, dy = (b.y - kLargeWorldOffset) - a.y;
    r.finite = r.finite && std::isfinite(dx) && std::isfinite(dy) && std::isfinite(b.angle);
    r.position_difference = std::max(r.position_difference, std::hypot(dx, dy));
    r.angle_difference = std::max(r.angle_difference, std::abs(b.angle - a.angle));
  }
  return r;
}

// One CSV row of bench/results/large_world.csv.
inline void print_settle_row(const std::string& scene, const std::string& implementation,
                             const SettleResult& r) {
  std::printf("%s,%s,%d,%d,%.6g,%.6g,%s\n", scene.c_str(), implementation.c_str(),
              r.origin_sleep_step, r.far_sleep_step, r.position_difference, r.angle_difference,
              r.finite ? "yes" : "no");
}

}  // namespace mink::bench
