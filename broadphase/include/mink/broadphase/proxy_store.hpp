#pragma once

#include <cstdint>
#include <limits>
#include <string_view>
#include <vector>

#include "mink/broadphase/aabb.hpp"
#include "mink/broadphase/broadphase.hpp"
#include "mink/byte_stream.hpp"

namespace mink {

/// How a tight box is fattened when it is stored: grown by a margin on every side, at most
/// `margin` and at most `size_fraction` of the object's size (so a small shape gets a small
/// margin, and its pairs stay few), and stretched ahead along the last step's motion. The size
/// is the one given at create_proxy, else the box's half-diagonal.
struct Fattening {
  Real margin = 0.1;  ///< the most a box grows on each side
  Real size_fraction = std::numeric_limits<Real>::infinity();
  /// Reach ahead along the last step's motion, this many steps' worth (at most four margins):
  /// a steadily moving box is refattened less often, at the price of more pairs. 0: none.
  Real prediction_steps = 4;
};

/// The per-proxy bookkeeping both broadphases share: ids, fat boxes, kinds, user data and the
/// validation of everything that crosses the API. Ids freed by destroy() are handed out again
/// only after release_destroyed(), so within one step an id names one proxy only.
class ProxyStore {
 public:
  explicit ProxyStore(const Fattening& fattening);

  ProxyId create(const Aabb& tight, ProxyKind kind, std::uint64_t user_data, Real size);
  void destroy(ProxyId id);
  /// Refattens and returns true when `tight` leaves the stored box (see Fattening).
  bool move(ProxyId id, const Aabb& tight);
  void release_destroyed();

  /// @brief Argument checks shared by the broadphases.
  /// @throws InvalidArgumentError naming `operation` for a box with a non-finite coordinate or
  /// lower above upper, a non-finite point, or an id that is not a live proxy.
  static void check_box(const Aabb& box, std::string_view operation);
  static void check_point(const Vec2& point, std::string_view operation);
  void check_alive(ProxyId id, std::string_view operation) const;

  bool alive(ProxyId id) const { return id < alive_.size() && alive_[id] != 0; }
  const Aabb& fat(ProxyId id) const { return fat_[id]; }
  bool is_static(ProxyId id) const { return kind_[id] == ProxyKind::static_body; }
  /// Static or kinematic: an obstacle that query_fixed() finds.
  bool is_fixed(ProxyId id) const { return kind_[id] != ProxyKind::moving; }
  std::uint64_t user_data(ProxyId id) const { return user_data_[id]; }
  std::size_t count() const { return count_; }
  /// One past the largest id ever handed out.
  std::size_t id_bound() const { return alive_.size(); }
  const Fattening& fattening() const { return fattening_; }

  /// Everything above, free and destroyed ids included, as snapshot bytes and back.
  void save(SaveArchive& archive) const;
  void load(LoadArchive& archive);

 private:
  template <typename Archive>
  void fields(Archive& archive);

  /// `tight` grown by its margin and stretched along `step`, the motion since the last move.
  Aabb fattened(const Aabb& tight, const Vec2& step, Real size, std::string_view operation) const;

  Fattening fattening_;
  std::vector<Aabb> fat_;
  std::vector<Vec2> last_lower_;  ///< lower corner of the last tight box, for the step
  std::vector<ProxyKind> kind_;
  std::vector<Real> size_;  ///< per id: the size given at creation, or kSizeOfBox
  std::vector<std::uint64_t> user_data_;
  std::vector<std::uint8_t> alive_;
  std::vector<ProxyId> free_ids_;
  std::vector<ProxyId> destroyed_ids_;
  std::size_t count_ = 0;
};

}  // namespace mink
