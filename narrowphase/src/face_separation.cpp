#include "face_separation.hpp"

#include <array>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "mink/narrowphase/support.hpp"

namespace mink::detail {

namespace {
constexpr std::size_t kTransformedLimit = 16;

#if defined(__SSE2__)
// Small hulls (boxes, octagons): Q's first 2 * kPairs padded vertices mapped into P's frame two
// at a time, then per face of P the smallest offset over them. The faces are independent, so
// their work overlaps.
template <std::size_t kPairs>
FaceSeparation small_face_separation(const PreparedHull& p, const PreparedHull& q,
                                     const Pose& q_to_p) {
  const std::span<const Vec2> pn = p.normals();
  const PoseLanes map(q_to_p);
  __m128d mx[kPairs];
  __m128d my[kPairs];
  for (std::size_t k = 0; k < kPairs; ++k) map.apply(q.xs() + 2 * k, q.ys() + 2 * k, mx[k], my[k]);
  const std::span<const Real> offsets = p.face_offsets();
  FaceSeparation best{-std::numeric_limits<Real>::infinity(), 0};
  for (std::size_t i = 0; i < pn.size(); ++i) {
    const __m128d nx = _mm_set1_pd(pn[i].x());
    const __m128d ny = _mm_set1_pd(pn[i].y());
    __m128d low = _mm_add_pd(_mm_mul_pd(nx, mx[0]), _mm_mul_pd(ny, my[0]));
    for (std::size_t k = 1; k < kPairs; ++k) {
      low = _mm_min_pd(low, _mm_add_pd(_mm_mul_pd(nx, mx[k]), _mm_mul_pd(ny, my[k])));
    }
    low = _mm_min_pd(low, _mm_shuffle_pd(low, low, 1));
    const Real separation = _mm_cvtsd_f64(low) - offsets[i];
    if (separation > best.separation) best = {separation, static_cast<std::uint32_t>(i)};
  }
  return best;
}
#endif
}  // namespace

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
#if defined(__SSE2__)
  if (q.padded_size() == kSupportBlock && pv.size() <= kSupportBlock) {
    // Q's first four padded entries hold all of a hull of up to four vertices (boxes): half
    // the block.
    return q.size() <= 4 ? small_face_separation<2>(p, q, q_to_p)
                         : small_face_separation<4>(p, q, q_to_p);
  }
#endif
  if (qv.size() <= kTransformedLimit && pv.size() <= kTransformedLimit) {
    // Map Q once, then a plain double loop.
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
