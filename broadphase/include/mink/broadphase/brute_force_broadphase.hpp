#pragma once

#include <vector>

#include "mink/broadphase/broadphase.hpp"
#include "mink/broadphase/proxy_store.hpp"

namespace mink {

/// The obviously-correct oracle: every update tests every pair of proxies and diffs the
/// result against the previous pair set. O(n^2) per update; for tests only.
class BruteForceBroadphase final : public Broadphase {
 public:
  explicit BruteForceBroadphase(Real margin = 0.1);
  explicit BruteForceBroadphase(const Fattening& fattening);

  ProxyId create_proxy(const Aabb& tight, ProxyKind kind, std::uint64_t user_data,
                       Real size = kSizeOfBox) override;
  void destroy_proxy(ProxyId id) override;
  bool move_proxy(ProxyId id, const Aabb& tight) override;
  void update_pairs(PairEvents& events) override;

  /// Sorted by (a, b).
  const std::vector<ProxyPair>& pairs() const override { return pairs_; }
  const Aabb& fat_aabb(ProxyId id) const override;
  std::uint64_t user_data(ProxyId id) const override;
  std::size_t proxy_count() const override { return store_.count(); }

  void query(const Aabb& box, std::vector<ProxyId>& out) const override;
  void query_point(const Vec2& point, std::vector<ProxyId>& out) const override;
  void query_fixed(const Aabb& box, std::vector<ProxyId>& out) const override;

 private:
  ProxyStore store_;
  std::vector<ProxyPair> pairs_;
  std::vector<ProxyPair> next_pairs_;
};

}  // namespace mink
