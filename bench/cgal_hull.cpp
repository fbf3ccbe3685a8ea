#include "library_hulls.hpp"

#include <iterator>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/convex_hull_2.h>

namespace mink::bench {

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalPoint = Kernel::Point_2;
}  // namespace

struct CgalHullBuilder::State {
  std::vector<CgalPoint> points;
  std::vector<CgalPoint> hull;
};

CgalHullBuilder::CgalHullBuilder(std::span<const Vec2> points) : state_(std::make_unique<State>()) {
  state_->points.reserve(points.size());
  for (const Vec2& p : points) state_->points.emplace_back(p.x(), p.y());
  // Every point can be a hull vertex (points on a circle), so reserve for all of them.
  state_->hull.reserve(points.size());
}

CgalHullBuilder::~CgalHullBuilder() = default;
CgalHullBuilder::CgalHullBuilder(CgalHullBuilder&&) noexcept = default;
CgalHullBuilder& CgalHullBuilder::operator=(CgalHullBuilder&&) noexcept = default;

std::size_t CgalHullBuilder::build() {
  state_->hull.clear();  // keeps the capacity, so no allocation inside the timed region
  CGAL::convex_hull_2(state_->points.begin(), state_->points.end(),
                      std::back_inserter(state_->hull));
  return state_->hull.size();
}

std::vector<Vec2> CgalHullBuilder::vertices() const {
  std::vector<Vec2> result;
  result.reserve(state_->hull.size());
  for (const CgalPoint& p : state_->hull) result.emplace_back(p.x(), p.y());
  return result;
}

}  // namespace mink::bench
