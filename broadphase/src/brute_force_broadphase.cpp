#include "mink/broadphase/brute_force_broadphase.hpp"

#include <algorithm>
#include <iterator>

namespace mink {

namespace {
bool pair_less(const ProxyPair& x, const ProxyPair& y) {
  return x.a != y.a ? x.a < y.a : x.b < y.b;
}
}  // namespace

BruteForceBroadphase::BruteForceBroadphase(Real margin) : store_(Fattening{margin}) {}

BruteForceBroadphase::BruteForceBroadphase(const Fattening& fattening) : store_(fattening) {}

ProxyId BruteForceBroadphase::create_proxy(const Aabb& tight, ProxyKind kind,
                                           std::uint64_t user_data, Real size) {
  return store_.create(tight, kind, user_data, size);
}

void BruteForceBroadphase::destroy_proxy(ProxyId id) {
  store_.destroy(id);
}

bool BruteForceBroadphase::move_proxy(ProxyId id, const Aabb& tight) {
  return store_.move(id, tight);
}

void BruteForceBroadphase::update_pairs(PairEvents& events) {
  events.begun.clear();
  events.ended.clear();
  next_pairs_.clear();
  const auto bound = static_cast<ProxyId>(store_.id_bound());
  for (ProxyId a = 0; a < bound; ++a) {
    if (!store_.alive(a)) continue;
    for (ProxyId b = a + 1; b < bound; ++b) {
      if (!store_.alive(b) || (store_.is_static(a) && store_.is_static(b))) continue;
      if (store_.fat(a).overlaps(store_.fat(b))) next_pairs_.push_back({a, b});
    }
  }
  // Both lists are sorted, so the events are plain set differences.
  std::set_difference(next_pairs_.begin(), next_pairs_.end(), pairs_.begin(), pairs_.end(),
                      std::back_inserter(events.begun), pair_less);
  std::set_difference(pairs_.begin(), pairs_.end(), next_pairs_.begin(), next_pairs_.end(),
                      std::back_inserter(events.ended), pair_less);
  pairs_.swap(next_pairs_);
  store_.release_destroyed();
}

const Aabb& BruteForceBroadphase::fat_aabb(ProxyId id) const {
  store_.check_alive(id, "fat_aabb");
  return store_.fat(id);
}

std::uint64_t BruteForceBroadphase::user_data(ProxyId id) const {
  store_.check_alive(id, "user_data");
  return store_.user_data(id);
}

void BruteForceBroadphase::query(const Aabb& box, std::vector<ProxyId>& out) const {
  ProxyStore::check_box(box, "query");
  for (ProxyId id = 0; id < store_.id_bound(); ++id) {
    if (store_.alive(id) && store_.fat(id).overlaps(box)) out.push_back(id);
  }
}

void BruteForceBroadphase::query_fixed(const Aabb& box, std::vector<ProxyId>& out) const {
  ProxyStore::check_box(box, "query_fixed");
  for (ProxyId id = 0; id < store_.id_bound(); ++id) {
    if (store_.alive(id) && store_.is_fixed(id) && store_.fat(id).overlaps(box)) out.push_back(id);
  }
}

void BruteForceBroadphase::query_point(const Vec2& point, std::vector<ProxyId>& out) const {
  ProxyStore::check_point(point, "query_point");
  for (ProxyId id = 0; id < store_.id_bound(); ++id) {
    if (store_.alive(id) && store_.fat(id).contains(point)) out.push_back(id);
  }
}

}  // namespace mink
