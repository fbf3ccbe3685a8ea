#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "mink/broadphase/aabb.hpp"
#include "mink/broadphase/broadphase.hpp"

namespace mink {

// The per-proxy bookkeeping both broadphases share: ids, fat boxes, kinds, user data and the
// validation of everything that crosses the API. Ids freed by destroy() are handed out again
// only after release_destroyed(), so within one step an id names one proxy only.
class ProxyStore {
 public:
  explicit ProxyStore(Real margin);

  ProxyId create(const Aabb& tight, ProxyKind kind, std::uint64_t user_data);
  void destroy(ProxyId id);
  // Refattens and returns true when `tight` leaves the stored box. The new box also reaches
  // ahead along the last step's motion, as far as a few steps or a few margins.
  bool move(ProxyId id, const Aabb& tight);
  void release_destroyed();

  // Throw InvalidArgumentError naming `operation` for a box with a non-finite coordinate or
  // lower above upper, a non-finite point, or an id that is not a live proxy.
  static void check_box(const Aabb& box, std::string_view operation);
  static void check_point(const Vec2& point, std::string_view operation);
  void check_alive(ProxyId id, std::string_view operation) const;

  bool alive(ProxyId id) const { return id < alive_.size() && alive_[id] != 0; }
  const Aabb& fat(ProxyId id) const { return fat_[id]; }
  bool is_static(ProxyId id) const { return kind_[id] == ProxyKind::static_body; }
  std::uint64_t user_data(ProxyId id) const { return user_data_[id]; }
  std::size_t count() const { return count_; }
  // One past the largest id ever handed out.
  std::size_t id_bound() const { return alive_.size(); }
  Real margin() const { return margin_; }

 private:
  // `tight` grown by the margin and stretched along `step`, the motion since the last move.
  Aabb fattened(const Aabb& tight, const Vec2& step, std::string_view operation) const;

  Real margin_;
  std::vector<Aabb> fat_;
  std::vector<Vec2> last_lower_;  // lower corner of the last tight box, for the step
  std::vector<ProxyKind> kind_;
  std::vector<std::uint64_t> user_data_;
  std::vector<std::uint8_t> alive_;
  std::vector<ProxyId> free_ids_;
  std::vector<ProxyId> destroyed_ids_;
  std::size_t count_ = 0;
};

}  // namespace mink
