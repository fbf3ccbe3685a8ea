#include "mink/narrowphase/simplex.hpp"

namespace mink {

Simplex world_simplex(const SimplexCache& indices, const PreparedHull& a, const Pose& pose_a,
                      const PreparedHull& b, const Pose& pose_b) {
  Simplex s;
  for (int i = 0; i < indices.count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    SimplexVertex& v = s.vertices[k];
    v.index_a = indices.index_a[k];
    v.index_b = indices.index_b[k];
    v.a = pose_a.apply(a.vertices()[v.index_a]);
    v.b = pose_b.apply(b.vertices()[v.index_b]);
    v.point = v.a - v.b;
  }
  s.count = indices.count;
  return s;
}

}  // namespace mink
