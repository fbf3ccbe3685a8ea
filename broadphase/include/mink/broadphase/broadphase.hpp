#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "mink/broadphase/aabb.hpp"

namespace mink {

/// Stays valid from create_proxy until destroy_proxy, whatever happens to other proxies.
using ProxyId = std::uint32_t;
inline constexpr ProxyId null_proxy = std::numeric_limits<ProxyId>::max();

/// Static proxies never pair with each other. Kinematic proxies pair as moving ones do; with
/// the static ones they are the fixed obstacles query_fixed() finds.
enum class ProxyKind : std::uint8_t { static_body, moving, kinematic };

/// The size a proxy's margin follows when its creator gives none: half the diagonal of each
/// box it is given (see Fattening).
inline constexpr Real kSizeOfBox = -1;

/// A candidate pair, always with a < b.
struct ProxyPair {
  ProxyId a = null_proxy;
  ProxyId b = null_proxy;
  bool operator==(const ProxyPair&) const = default;
};

/// What changed in the pair set since the previous update_pairs().
struct PairEvents {
  std::vector<ProxyPair> begun;
  std::vector<ProxyPair> ended;
};

/// The interface both the sweep-and-prune and its brute-force oracle implement. Boxes are
/// stored fattened by a margin; move_proxy only changes the stored box when the tight box
/// leaves it, so slow bodies keep their pairs.
class Broadphase {
 public:
  virtual ~Broadphase() = default;

  /// @brief Adds a box; its id stays valid until destroy_proxy.
  /// @param tight the object's exact box (stored fattened by the margin)
  /// @param kind static proxies never pair with each other
  /// @param user_data carried along for the caller (user_data())
  /// @param size the object's radius about its centre, which its margin follows (Fattening),
  /// or kSizeOfBox
  /// @throws InvalidArgumentError for a box with a non-finite coordinate or lower above upper,
  /// or a size that is neither kSizeOfBox nor finite and non-negative
  virtual ProxyId create_proxy(const Aabb& tight, ProxyKind kind, std::uint64_t user_data,
                               Real size = kSizeOfBox) = 0;
  /// @throws InvalidArgumentError for an id that is not a live proxy
  virtual void destroy_proxy(ProxyId id) = 0;
  /// @return true when the stored (fat) box changed.
  /// @throws InvalidArgumentError for a dead id or a bad box, as create_proxy
  virtual bool move_proxy(ProxyId id, const Aabb& tight) = 0;
  /// Brings the pair set up to date: every pair of overlapping fat boxes, except static-static.
  virtual void update_pairs(PairEvents& events) = 0;

  /// The current pair set, in no particular order.
  virtual const std::vector<ProxyPair>& pairs() const = 0;
  /// @throws InvalidArgumentError for an id that is not a live proxy
  virtual const Aabb& fat_aabb(ProxyId id) const = 0;
  /// @throws InvalidArgumentError for an id that is not a live proxy
  virtual std::uint64_t user_data(ProxyId id) const = 0;
  virtual std::size_t proxy_count() const = 0;

  /// @brief Appends every proxy whose fat box overlaps `box` / contains `point`.
  /// @throws InvalidArgumentError for a bad box or a non-finite point
  virtual void query(const Aabb& box, std::vector<ProxyId>& out) const = 0;
  virtual void query_point(const Vec2& point, std::vector<ProxyId>& out) const = 0;
  /// @brief As query(), but only the proxies created as ProxyKind::static_body or kinematic:
  /// what a fast body sweeps against, without visiting its moving neighbours.
  virtual void query_fixed(const Aabb& box, std::vector<ProxyId>& out) const = 0;
};

}  // namespace mink
