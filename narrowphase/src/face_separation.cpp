#include "face_separation.hpp"

#include <array>
#include <limits>

#include "mink/narrowphase/support.hpp"

namespace mink::detail {

namespace {
constexpr std::size_t kTransformedLimit = 16;
}

FaceSeparation max_face_separation_brute(const PreparedHull& p, const PreparedHull& q,
                                         const Pose& q_to_p) {
  FaceSeparation best{-std::numeric_limits<Real>::infinity(), 0};
  const std::span<const Vec2> pv = p.vertices();
  const std::span<const Vec2> pn = p.normals();
  for (std::size_t i = 0; i < pv.size(); ++i) {
    Real deepest = std::numeric_limits<Real>::infinity();
    for (const Vec2& w : q.vertices())
      deepest = std::min(deepest, pn[i].dot(q_to_p.apply(w) - pv[i]));
    if (deepest > best.separation) best = {deepest, static_cast<std::uint32_t>(i)};
  }
  return best;
}

FaceSeparation max_face_separation(const PreparedHull& p, const PreparedHull& q,
                                   const Pose& q_to_p) {
  const std::span<const Vec2> pv = p.vertices();
  const std::span<const Vec2> pn = p.normals();
  const std::span<const Vec2> qv = q.vertices();
  FaceSeparation best{-std::numeric_limits<Real>::infinity(), 0};
  if (qv.size() <= kTransformedLimit && pv.size() <= kTransformedLimit) {
    // Map Q once, then a plain double loop: for boxes this is the whole cost.
    std::array<Vec2, kTransformedLimit> mapped;
    for (std::size_t j = 0; j < qv.size(); ++j) mapped[j] = q_to_p.apply(qv[j]);
    for (std::size_t i = 0; i < pv.size(); ++i) {
      Real deepest = std::numeric_limits<Real>::infinity();
      for (std::size_t j = 0; j < qv.size(); ++j) {
        deepest = std::min(deepest, pn[i].dot(mapped[j] - pv[i]));
      }
      if (deepest > best.separation) best = {deepest, static_cast<std::uint32_t>(i)};
    }
    return best;
  }
  std::size_t deepest_index = support_index(q, q_to_p.rotation.apply_inverse(-pn[0]));
  for (std::size_t i = 0; i < pv.size(); ++i) {
    deepest_index = support_index_climb(q, q_to_p.rotation.apply_inverse(-pn[i]), deepest_index);
    const Real separation = pn[i].dot(q_to_p.apply(qv[deepest_index]) - pv[i]);
    if (separation > best.separation) best = {separation, static_cast<std::uint32_t>(i)};
  }
  return best;
}

}  // namespace mink::detail
