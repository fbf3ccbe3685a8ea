#include "mink/broadphase/proxy_store.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "mink/error.hpp"

namespace mink {

namespace {

// The most a moved box reaches ahead, in margins.
constexpr Real kPredictionLimit = 4;

// The largest margin: with its reach ahead it stays far below what a double holds.
constexpr Real kMostMargin = 1e300;

std::string describe(const Vec2& point) {
  return "(" + std::to_string(point.x()) + ", " + std::to_string(point.y()) + ")";
}

std::string describe(const Aabb& box) {
  return "[" + describe(box.lower) + ", " + describe(box.upper) + "]";
}

// What create_proxy accepts, and so what a loaded store may hold.
bool known_kind(ProxyKind kind) {
  return kind == ProxyKind::static_body || kind == ProxyKind::moving ||
         kind == ProxyKind::kinematic;
}
bool valid_size(Real size) {
  return size == kSizeOfBox || (std::isfinite(size) && size >= 0);
}

bool valid_box(const Aabb& box) {
  return box.lower.allFinite() && box.upper.allFinite() && box.lower.x() <= box.upper.x() &&
         box.lower.y() <= box.upper.y();
}

// What is wrong with a fattening, or nothing. Its margin and its reach ahead (a few margins)
// are added to boxes within the world: a margin beyond kMostMargin would take them past what
// a box can hold.
std::string fattening_error(const Fattening& fattening) {
  if (!std::isfinite(fattening.margin) || fattening.margin < 0 || fattening.margin > kMostMargin) {
    return "broadphase margin " + std::to_string(fattening.margin) +
           " is not a finite non-negative number up to " + std::to_string(kMostMargin);
  }
  if (std::isnan(fattening.size_fraction) || fattening.size_fraction < 0) {
    return "broadphase margin size fraction " + std::to_string(fattening.size_fraction) +
           " is not non-negative";
  }
  if (!std::isfinite(fattening.prediction_steps) || fattening.prediction_steps < 0) {
    return "broadphase prediction steps " + std::to_string(fattening.prediction_steps) +
           " is not a finite non-negative number";
  }
  return {};
}

}  // namespace

void ProxyStore::check_box(const Aabb& box, std::string_view operation) {
  if (!box.lower.allFinite() || !box.upper.allFinite()) {
    throw InvalidArgumentError(std::string(operation) + ": box " + describe(box) +
                               " has a non-finite coordinate");
  }
  if (box.lower.x() > box.upper.x() || box.lower.y() > box.upper.y()) {
    throw InvalidArgumentError(std::string(operation) + ": box " + describe(box) +
                               " has its lower corner above its upper corner");
  }
}

void ProxyStore::check_point(const Vec2& point, std::string_view operation) {
  if (!point.allFinite()) {
    throw InvalidArgumentError(std::string(operation) + ": point (" + std::to_string(point.x()) +
                               ", " + std::to_string(point.y()) + ") has a non-finite coordinate");
  }
}

ProxyStore::ProxyStore(const Fattening& fattening) : fattening_(fattening) {
  if (const std::string wrong = fattening_error(fattening); !wrong.empty()) {
    throw InvalidArgumentError(wrong);
  }
}

ProxyId ProxyStore::create(const Aabb& tight, ProxyKind kind, std::uint64_t user_data, Real size) {
  check_box(tight, "create_proxy");
  if (!valid_size(size)) {
    throw InvalidArgumentError("create_proxy: size " + std::to_string(size) +
                               " is neither finite and non-negative nor kSizeOfBox");
  }
  if (!known_kind(kind)) {
    throw InvalidArgumentError("create_proxy: unknown proxy kind " +
                               std::to_string(static_cast<int>(kind)));
  }
  const Aabb fat = fattened(tight, Vec2::Zero(), size, "create_proxy");
  ProxyId id;
  if (!free_ids_.empty()) {
    id = free_ids_.back();
    free_ids_.pop_back();
  } else {
    if (alive_.size() >= null_proxy) throw InvalidArgumentError("create_proxy: too many proxies");
    id = static_cast<ProxyId>(alive_.size());
    fat_.emplace_back();
    last_lower_.emplace_back();
    kind_.push_back(kind);
    size_.push_back(kSizeOfBox);
    user_data_.push_back(0);
    alive_.push_back(0);
  }
  fat_[id] = fat;
  last_lower_[id] = tight.lower;
  kind_[id] = kind;
  size_[id] = size;
  user_data_[id] = user_data;
  alive_[id] = 1;
  ++count_;
  return id;
}

void ProxyStore::check_alive(ProxyId id, std::string_view operation) const {
  if (!alive(id)) {
    throw InvalidArgumentError(std::string(operation) + ": proxy " + std::to_string(id) +
                               " does not exist");
  }
}

void ProxyStore::destroy(ProxyId id) {
  check_alive(id, "destroy_proxy");
  alive_[id] = 0;
  destroyed_ids_.push_back(id);
  --count_;
}

bool ProxyStore::move(ProxyId id, const Aabb& tight) {
  check_alive(id, "move_proxy");
  check_box(tight, "move_proxy");
  const Vec2 step = tight.lower - last_lower_[id];
  last_lower_[id] = tight.lower;
  if (fat_[id].contains(tight)) return false;
  fat_[id] = fattened(tight, step, size_[id], "move_proxy");
  return true;
}

Aabb ProxyStore::fattened(const Aabb& tight, const Vec2& step, Real size,
                          std::string_view operation) const {
  Real margin = fattening_.margin;
  if (std::isfinite(fattening_.size_fraction)) {
    const Real measure = size != kSizeOfBox ? size : 0.5 * (tight.upper - tight.lower).norm();
    margin = std::min(margin, fattening_.size_fraction * measure);
  }
  Aabb fat = tight.fattened(margin);
  // Reach ahead along the last step, so a steadily moving body keeps its box for longer. A
  // few margins at most: a teleport is no motion to predict.
  const Real most = kPredictionLimit * fattening_.margin;
  for (int axis = 0; axis < 2; ++axis) {
    if (fattening_.prediction_steps == 0) break;
    const Real ahead = std::min(fattening_.prediction_steps * std::abs(step[axis]), most);
    if (step[axis] < 0) {
      fat.lower[axis] -= ahead;
    } else {
      fat.upper[axis] += ahead;
    }
  }
  if (!fat.lower.allFinite() || !fat.upper.allFinite()) {
    throw InvalidArgumentError(std::string(operation) + ": box " + describe(tight) +
                               " overflows when fattened by the margin");
  }
  return fat;
}

void ProxyStore::release_destroyed() {
  free_ids_.insert(free_ids_.end(), destroyed_ids_.begin(), destroyed_ids_.end());
  destroyed_ids_.clear();
}

}  // namespace mink

namespace mink {

template <typename Archive>
void ProxyStore::fields(Archive& archive) {
  archive(fattening_.margin);
  archive(fattening_.size_fraction);
  archive(fattening_.prediction_steps);
  archive(fat_);
  archive(last_lower_);
  archive(kind_);
  archive(size_);
  archive(user_data_);
  archive(alive_);
  archive(free_ids_);
  archive(destroyed_ids_);
  std::uint64_t count = count_;
  archive(count);
  count_ = static_cast<std::size_t>(count);
  if constexpr (Archive::loading) {
    const std::size_t n = alive_.size();
    if (fat_.size() != n || last_lower_.size() != n || kind_.size() != n || size_.size() != n ||
        user_data_.size() != n) {
      archive.in.fail("broadphase proxy arrays of different lengths");
    }
    for (const ProxyKind kind : kind_) {
      if (!known_kind(kind)) {
        archive.in.fail("a broadphase proxy of unknown kind " +
                        std::to_string(static_cast<int>(kind)));
      }
    }
    for (const Real size : size_) {
      if (!valid_size(size)) archive.in.fail("a broadphase proxy of size " + std::to_string(size));
    }
    if (const std::string wrong = fattening_error(fattening_); !wrong.empty()) {
      archive.in.fail(wrong);
    }
    for (std::size_t id = 0; id < n; ++id) {
      if (!last_lower_[id].allFinite()) {
        archive.in.fail("a broadphase proxy whose last box corner " + describe(last_lower_[id]) +
                        " is not finite");
      }
      if (alive_[id] != 0 && !valid_box(fat_[id])) {
        archive.in.fail("a broadphase proxy whose box " + describe(fat_[id]) +
                        " is not finite or has its lower corner above its upper corner");
      }
    }
    // create() hands out free ids and release_destroyed() frees destroyed ones, so each dead
    // id is in exactly one of the two lists and no live one is in either; the count sizes the
    // arrays a rebuild reserves.
    std::vector<std::uint8_t> listed(n, 0);
    const auto check_dead = [&](const std::vector<ProxyId>& ids, const char* which) {
      for (const ProxyId id : ids) {
        if (id >= n) archive.in.fail(std::string("a ") + which + " proxy id beyond the proxies");
        if (alive_[id] != 0) archive.in.fail(std::string("a ") + which + " proxy id still alive");
        if (listed[id]++ != 0) archive.in.fail("a dead proxy id listed twice");
      }
    };
    check_dead(free_ids_, "free");
    check_dead(destroyed_ids_, "destroyed");
    std::size_t live = 0;
    for (std::size_t id = 0; id < n; ++id) {
      if (alive_[id] != 0) {
        ++live;
      } else if (listed[id] == 0) {
        archive.in.fail("a dead proxy id neither free nor destroyed");
      }
    }
    if (count_ != live) archive.in.fail("a broadphase proxy count that is not its live proxies'");
  }
}

void ProxyStore::save(SaveArchive& archive) const {
  const_cast<ProxyStore*>(this)->fields(archive);
}
void ProxyStore::load(LoadArchive& archive) {
  fields(archive);
}

}  // namespace mink
