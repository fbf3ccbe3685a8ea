#include "box2d_distance.hpp"

#include <box2d/b2_distance.h>

#include <vector>

namespace mink::interop {

std::vector<b2Vec2> to_float(std::span<const Vec2> points) {
  std::vector<b2Vec2> out;
  out.reserve(points.size());
  for (const Vec2& p : points) out.push_back(to_float(p));
  return out;
}

Box2dDistance box2d_distance(std::span<const Vec2> a, std::span<const Vec2> b) {
  const std::vector<b2Vec2> va = to_float(a);
  const std::vector<b2Vec2> vb = to_float(b);
  b2DistanceInput input;
  input.proxyA.Set(va.data(), static_cast<int32>(va.size()), 0.0f);
  input.proxyB.Set(vb.data(), static_cast<int32>(vb.size()), 0.0f);
  input.transformA.SetIdentity();
  input.transformB.SetIdentity();
  input.useRadii = false;
  b2SimplexCache cache;
  cache.count = 0;
  b2DistanceOutput output;
  b2Distance(&output, &cache, &input);
  return {output.distance == 0.0f, output.distance, output.iterations};
}

}  // namespace mink::interop
