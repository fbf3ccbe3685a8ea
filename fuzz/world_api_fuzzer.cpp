// Random sequences of World calls, read from the fuzzer's bytes: create and destroy bodies,
// shapes of every kind and joints of every kind; set filters, types, transforms, velocities,
// awake, enabled, bullet and the joints' settings; query (box, point, ray, shape cast); step
// and advance. Some arguments are bad on purpose (NaN, infinities, negative sizes, stale ids,
// ids of another world, degenerate shapes, joints on one body).
//
// A model of what is alive is kept beside the world. After every call:
//  - ids are valid exactly when alive (live ones, destroyed ones, another world's);
//  - body, shape and joint counts and lists agree with the model (shapes and joints on the
//    right bodies, joints gone with their bodies and gears with their joints);
//  - every body, shape box, joint reading and contact is finite; each body's contacts name
//    live shapes on it and on another body, and its partner lists the same contact;
//  - a call that throws throws a mink::Error (anything else is a finding) and leaves the
//    world as it was (its digest, below, unchanged).
// The whole sequence runs at 1 worker and at 2; the digests after every step must be bitwise
// equal (determinism at any worker count).
//
// The world's settings are one of eight variants picked by the input's length, not by its
// bytes, so every input keeps its call sequence under each: Box2D v3's fast-body handling
// (fast_body_margin and continuous_fast_pairs off), no sleeping with the scalar solver, and no
// manifold reuse with joint chains solved iteratively, each on or off.
//
// A snapshot operation takes a snapshot and makes a second world from it at the other worker
// count: its state hash and its own snapshot equal the first's. The first world then steps, is
// rolled back in place (digest and state hash as before the step), and both worlds step once
// more, ending in equal states.
#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "mink/engine/joint_def.hpp"
#include "mink/engine/stale_id_error.hpp"
#include "mink/engine/world.hpp"
#include "mink/error.hpp"

namespace {

using mink::BodyId;
using mink::JointId;
using mink::JointType;
using mink::Real;
using mink::ShapeId;
using mink::Vec2;

[[noreturn]] void fail(const std::string& what) {
  std::fprintf(stderr, "fuzz_world_api: %s\n", what.c_str());
  std::abort();
}

void require(bool condition, const char* what) {
  if (!condition) fail(what);
}

bool finite(Real value) {
  return std::isfinite(value);
}
bool finite(const Vec2& v) {
  return std::isfinite(v.x()) && std::isfinite(v.y());
}

// Bounds that keep one input fast: stepping is the costly call.
constexpr std::size_t max_bodies = 24;
constexpr std::size_t max_shapes = 48;
constexpr std::size_t max_joints = 24;
constexpr int max_steps = 48;
constexpr std::size_t max_dead_ids = 16;

// FNV-1a over the bits of every value fed to it.
class Digest {
 public:
  void add(std::uint64_t bits) {
    for (int i = 0; i < 8; ++i) {
      hash_ ^= (bits >> (8 * i)) & 0xff;
      hash_ *= 1099511628211ull;
    }
  }
  void add(Real value) { add(std::bit_cast<std::uint64_t>(value)); }
  void add(const Vec2& v) {
    add(v.x());
    add(v.y());
  }
  void add(bool value) { add(std::uint64_t{value}); }
  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 14695981039346656037ull;
};

struct ShapeRecord {
  ShapeId id;
  BodyId body;
};

struct JointRecord {
  JointId id;
  JointType type;
  BodyId body_a, body_b;   // gears: B of each of their joints
  JointId joint1, joint2;  // gears only
};

// One run of the byte program against one world.
class CallSequence {
 public:
  CallSequence(const std::uint8_t* data, std::size_t size, int workers)
      : input_(data, size), world_(make_world_def(workers, size)), other_(mink::WorldDef{}) {
    // Ids of another world are never valid here.
    foreign_body_ = other_.create_body({});
    foreign_shape_ = other_.create_shape(foreign_body_, mink::ShapeDef::circle(1));
    mink::BodyDef dynamic;
    dynamic.type = mink::BodyType::dynamic;
    const BodyId other_b = other_.create_body(dynamic);
    foreign_joint_ =
        other_.create_joint(mink::revolute_joint_at(other_, foreign_body_, other_b, Vec2(0, 0)));
  }

  // The digest after every step, for the comparison across worker counts.
  std::vector<std::uint64_t> run() {
    check();
    while (input_.remaining_bytes() > 0 && steps_ < max_steps) {
      const std::uint8_t op = input_.ConsumeIntegral<std::uint8_t>();
      operation(op);
      check();
    }
    return step_digests_;
  }

 private:
  static mink::WorldDef make_world_def(int workers, std::size_t size) {
    mink::WorldDef def;
    def.worker_count = workers;
    if (size & 1) {
      def.fast_body_margin = false;
      def.continuous_fast_pairs = false;
    }
    if (size & 2) {
      def.enable_sleep = false;
      def.simd_solver = false;
    }
    if (size & 4) {
      def.reuse_manifolds = false;
      def.direct_joint_chains = false;
    }
    return def;
  }

  // ---- Values -------------------------------------------------------------------------------

  bool coin() { return input_.ConsumeBool(); }
  std::uint8_t byte() { return input_.ConsumeIntegral<std::uint8_t>(); }

  // Mostly a number in [lo, hi]; now and then a value an API must refuse or survive.
  Real real(Real lo, Real hi) {
    const std::uint8_t mode = byte();
    if (mode < 232) {
      const Real t = input_.ConsumeIntegral<std::uint16_t>() / 65535.0;
      return lo + (hi - lo) * t;
    }
    static constexpr std::array<Real, 15> special = {
        std::numeric_limits<Real>::quiet_NaN(),
        std::numeric_limits<Real>::infinity(),
        -std::numeric_limits<Real>::infinity(),
        0.0,
        -1.0,
        1e-9,
        1e9,
        -1e9,
        1e4,
        -1e4,
        std::numeric_limits<Real>::denorm_min(),
        1.0,
        // The last three only with FUZZ_EXTREME=1 in the environment: each hour of them has
        // found a new class so far (weld springs of 1e300, an undamped spring of 5e-324 hertz,
        // frictions of 1e300), fixed (FuzzFindings), so the minute of CI runs without them.
        1e300,
        -1e300,
        std::numeric_limits<Real>::max(),
    };
    static const bool extreme = std::getenv("FUZZ_EXTREME") != nullptr;
    return special[(mode - 232) % (extreme ? special.size() : special.size() - 3)];
  }
  Vec2 vec(Real extent) { return {real(-extent, extent), real(-extent, extent)}; }
  Real size() { return real(0.05, 2.0); }

  template <class T>
  std::size_t pick(const std::vector<T>& items) {
    return input_.ConsumeIntegralInRange<std::size_t>(0, items.size() - 1);
  }

  // A live body, or (now and then, or when there is none) a stale or foreign one.
  BodyId any_body(bool& live) {
    const std::uint8_t mode = byte();
    live = false;
    if (!bodies_.empty() && mode < 240) {
      live = true;
      return bodies_[pick(bodies_)];
    }
    if (!dead_bodies_.empty() && mode < 250) return dead_bodies_[pick(dead_bodies_)];
    return mode % 2 == 0 ? foreign_body_ : BodyId{};
  }
  ShapeId any_shape(bool& live) {
    const std::uint8_t mode = byte();
    live = false;
    if (!shapes_.empty() && mode < 240) {
      live = true;
      return shapes_[pick(shapes_)].id;
    }
    if (!dead_shapes_.empty() && mode < 250) return dead_shapes_[pick(dead_shapes_)];
    return mode % 2 == 0 ? foreign_shape_ : ShapeId{};
  }
  JointId any_joint(bool& live) {
    const std::uint8_t mode = byte();
    live = false;
    if (!joints_.empty() && mode < 240) {
      live = true;
      return joints_[pick(joints_)].id;
    }
    if (!dead_joints_.empty() && mode < 250) return dead_joints_[pick(dead_joints_)];
    return mode % 2 == 0 ? foreign_joint_ : JointId{};
  }

  mink::ShapeDef shape_def() {
    mink::ShapeDef def;
    switch (byte() % 7) {
      case 0:
        def = mink::ShapeDef::circle(1);
        def.points = {vec(1)};
        def.radius = size();
        break;
      case 1:
        def = mink::ShapeDef::capsule({0, 0}, {1, 0}, 1);
        def.points = {vec(1), vec(1)};
        def.radius = size();
        break;
      case 2:
        def = mink::ShapeDef::segment({0, 0}, {1, 0});
        def.points = {vec(2), vec(2)};
        break;
      case 3: {
        // Boxes and regular polygons through their factories (which check their arguments).
        def = coin() ? mink::ShapeDef::box(size(), size(), vec(1), real(-4, 4))
                     : mink::ShapeDef::regular_polygon(3 + byte() % 6, size(), vec(1));
        def.radius = coin() ? 0 : real(0, 0.2);
        break;
      }
      case 4:
        // A chain through create_shape is refused (create_chain makes chains).
        def = mink::ShapeDef::chain({{0, 0}, {1, 0}, {2, 1}});
        break;
      default: {
        // Any points: duplicates, collinear and too few are the hull's to refuse.
        const std::size_t count = byte() % 9;
        for (std::size_t i = 0; i < count; ++i) def.points.push_back(vec(2));
        def.radius = coin() ? 0 : real(0, 0.2);
        if (coin()) {
          def.scale = mink::ShapeScale{vec(1), {real(0.1, 3), real(0.1, 3)}};
        }
        break;
      }
    }
    def.density = real(0, 5);
    def.friction = real(0, 1);
    def.restitution = coin() ? 0 : real(0, 1);
    def.is_sensor = byte() < 24;
    def.enable_hit_events = coin();
    def.filter = filter();
    def.user_data = byte();
    return def;
  }

  mink::Filter filter() {
    mink::Filter f;
    f.category = std::uint64_t{1} << (byte() % 4);
    f.mask = coin() ? ~std::uint64_t{0} : input_.ConsumeIntegral<std::uint8_t>();
    f.group = static_cast<std::int8_t>(byte()) % 3;
    return f;
  }

  mink::JointMotor motor() { return {coin(), real(-5, 5), real(0, 100)}; }
  mink::JointSpring spring() { return {coin(), real(0, 10), real(0, 2), real(-1, 1)}; }
  mink::JointLimit limit() {
    const Real a = real(-2, 2);
    const Real b = real(-2, 2);
    return {coin(), a, b};  // lower > upper half the time: refused
  }

  // ---- The model ----------------------------------------------------------------------------

  template <class Id>
  static void remember(std::vector<Id>& dead, Id id) {
    if (dead.size() == max_dead_ids) dead.erase(dead.begin());
    dead.push_back(id);
  }

  void forget_shape(ShapeId id) {
    std::erase_if(shapes_, [&](const ShapeRecord& s) { return s.id == id; });
    remember(dead_shapes_, id);
  }

  // Joints on `body` go (gears with them); the model follows World's rule.
  void forget_joints_where(const std::function<bool(const JointRecord&)>& doomed) {
    std::vector<JointId> gone;
    for (const JointRecord& j : joints_) {
      if (j.type != JointType::gear && doomed(j)) gone.push_back(j.id);
    }
    for (const JointRecord& j : joints_) {
      if (j.type == JointType::gear &&
          (doomed(j) || std::ranges::find(gone, j.joint1) != gone.end() ||
           std::ranges::find(gone, j.joint2) != gone.end())) {
        gone.push_back(j.id);
      }
    }
    for (const JointId id : gone) {
      std::erase_if(joints_, [&](const JointRecord& j) { return j.id == id; });
      remember(dead_joints_, id);
    }
  }

  // FUZZ_TRACE=1 in the environment prints each call and the bodies before it (to turn a
  // failing input into a test).
  void trace(const char* name) const {
    static const bool enabled = std::getenv("FUZZ_TRACE") != nullptr;
    if (!enabled) return;
    std::fprintf(stderr, "call %s\n", name);
    for (const BodyId b : world_.bodies()) {
      const Vec2 p = world_.position(b);
      const Vec2 v = world_.linear_velocity(b);
      std::fprintf(stderr,
                   "  body %u type %d p (%.17g, %.17g) a %.17g v (%.17g, %.17g) w %.17g m %.17g "
                   "I %.17g awake %d enabled %d bullet %d fixed %d shapes %zu joints %zu\n",
                   b.index, static_cast<int>(world_.body_type(b)), p.x(), p.y(), world_.angle(b),
                   v.x(), v.y(), world_.angular_velocity(b), world_.mass(b),
                   world_.rotational_inertia(b), world_.is_awake(b), world_.is_enabled(b),
                   world_.is_bullet(b), world_.fixed_rotation(b), world_.body_shapes(b).size(),
                   world_.body_joints(b).size());
    }
  }

  // ---- Calls --------------------------------------------------------------------------------

  // Runs `call`; a throw must be a mink::Error that leaves the world as it was. Returns
  // whether the call succeeded.
  template <class Call>
  bool attempt(const char* name, Call&& call) {
    trace(name);
    const std::uint64_t before = digest();
    try {
      call();
      return true;
    } catch (const mink::Error& error) {
      if (digest() != before) {
        fail(std::string(name) + " threw but changed the world: " + error.what());
      }
      return false;
    } catch (const std::exception& error) {
      fail(std::string(name) + " threw a non-mink exception: " + error.what());
    } catch (...) {
      fail(std::string(name) + " threw something that is not an exception");
    }
  }

  // A call on an id that is not alive must throw StaleIdError (and change nothing).
  template <class Call>
  void attempt_with(bool live, const char* name, Call&& call) {
    trace(name);
    const std::uint64_t before = digest();
    try {
      call();
      if (!live) fail(std::string(name) + " accepted a dead or foreign id");
    } catch (const mink::StaleIdError&) {
      if (live) fail(std::string(name) + " called a live id stale");
      if (digest() != before) fail(std::string(name) + " threw but changed the world");
    } catch (const mink::Error&) {
      // A dead id with a bad argument may be refused for either.
      if (digest() != before) fail(std::string(name) + " threw but changed the world");
    } catch (const std::exception& error) {
      fail(std::string(name) + " threw a non-mink exception: " + error.what());
    }
  }

  void create_body() {
    if (bodies_.size() >= max_bodies) return;
    mink::BodyDef def;
    const std::uint8_t type = byte() % 8;
    def.type = type < 5   ? mink::BodyType::dynamic
               : type < 7 ? mink::BodyType::static_body
                          : mink::BodyType::kinematic;
    def.position = vec(10);
    def.angle = real(-4, 4);
    def.linear_velocity = vec(5);
    def.angular_velocity = real(-5, 5);
    def.linear_damping = coin() ? 0 : real(0, 2);
    def.angular_damping = coin() ? 0 : real(0, 2);
    def.gravity_scale = coin() ? 1 : real(-1, 2);
    def.allow_sleep = byte() > 16;
    def.awake = byte() > 16;
    def.enabled = byte() > 16;
    def.fixed_rotation = byte() < 24;
    def.bullet = byte() < 24;
    def.continuous_threshold = coin() ? 0.5 : real(0, 2);
    BodyId id;
    if (attempt("create_body", [&] { id = world_.create_body(def); })) bodies_.push_back(id);
  }

  void destroy_body() {
    bool live = false;
    const BodyId id = any_body(live);
    attempt_with(live, "destroy_body", [&] { world_.destroy_body(id); });
    if (!live) return;
    std::erase(bodies_, id);
    remember(dead_bodies_, id);
    std::vector<ShapeId> gone;
    for (const ShapeRecord& s : shapes_) {
      if (s.body == id) gone.push_back(s.id);
    }
    for (const ShapeId s : gone) forget_shape(s);
    forget_joints_where([&](const JointRecord& j) { return j.body_a == id || j.body_b == id; });
  }

  void create_shape() {
    if (shapes_.size() >= max_shapes) return;
    bool live = false;
    const BodyId body = any_body(live);
    mink::ShapeDef def;
    // The factories refuse bad sizes: that is a typed error too, with no world involved.
    if (!attempt("ShapeDef factory", [&] { def = shape_def(); })) return;
    ShapeId id;
    const std::uint64_t before = digest();
    try {
      id = world_.create_shape(body, def);
    } catch (const mink::StaleIdError&) {
      if (live) fail("create_shape called a live body stale");
      if (digest() != before) fail("create_shape threw but changed the world");
      return;
    } catch (const mink::Error&) {
      if (digest() != before) fail("create_shape threw but changed the world");
      return;
    } catch (const std::exception& error) {
      fail(std::string("create_shape threw a non-mink exception: ") + error.what());
    }
    if (!live) fail("create_shape accepted a dead or foreign body");
    if (def.type == mink::ShapeType::chain) fail("create_shape accepted a chain");
    shapes_.push_back({id, body});
  }

  void create_chain() {
    if (shapes_.size() + 8 > max_shapes) return;
    bool live = false;
    const BodyId body = any_body(live);
    std::vector<Vec2> points;
    const std::size_t count = byte() % 7;
    for (std::size_t i = 0; i < count; ++i) points.push_back(vec(4));
    mink::ShapeDef def = mink::ShapeDef::chain(points, coin());
    def.friction = real(0, 1);
    def.filter = filter();
    std::vector<ShapeId> ids;
    const std::uint64_t before = digest();
    try {
      ids = world_.create_chain(body, def);
    } catch (const mink::StaleIdError&) {
      if (live) fail("create_chain called a live body stale");
      if (digest() != before) fail("create_chain threw but changed the world");
      return;
    } catch (const mink::Error&) {
      if (digest() != before) fail("create_chain threw but changed the world");
      return;
    } catch (const std::exception& error) {
      fail(std::string("create_chain threw a non-mink exception: ") + error.what());
    }
    if (!live) fail("create_chain accepted a dead or foreign body");
    const std::size_t edges = def.loop ? points.size() : points.size() - 1;
    if (ids.size() != edges) fail("create_chain made the wrong number of segments");
    for (const ShapeId id : ids) shapes_.push_back({id, body});
  }

  void destroy_shape() {
    bool live = false;
    const ShapeId id = any_shape(live);
    attempt_with(live, "destroy_shape", [&] { world_.destroy_shape(id); });
    if (live) forget_shape(id);
  }

  // Two bodies for a joint: usually two live ones, sometimes the same one twice.
  std::pair<BodyId, BodyId> joint_bodies(bool& live) {
    bool live_a = false, live_b = false;
    const BodyId a = any_body(live_a);
    BodyId b = any_body(live_b);
    if (live_a && live_b && a == b && bodies_.size() > 1 && byte() > 32) {
      b = bodies_[(std::ranges::find(bodies_, a) - bodies_.begin() + 1) % bodies_.size()];
    }
    live = live_a && live_b;
    return {a, b};
  }

  void create_joint() {
    if (joints_.size() >= max_joints) return;
    bool live = false;
    const std::pair<BodyId, BodyId> pair = joint_bodies(live);
    const BodyId a = pair.first;
    const BodyId b = pair.second;
    mink::JointDef def;
    const Vec2 anchor = vec(10);
    const Vec2 axis = coin() ? Vec2{1, 0} : vec(1);
    const JointType type = static_cast<JointType>(byte() % 8);
    // The *_joint_at helpers read the bodies' poses, so they too throw StaleIdError.
    const bool made = attempt("joint definition", [&] {
      switch (type) {
        case JointType::revolute: {
          mink::RevoluteJointDef d = mink::revolute_joint_at(world_, a, b, anchor);
          d.limit = limit();
          d.motor = motor();
          d.spring = spring();
          def = d;
          break;
        }
        case JointType::prismatic: {
          mink::PrismaticJointDef d = mink::prismatic_joint_at(world_, a, b, anchor, axis);
          d.limit = limit();
          d.motor = motor();
          d.spring = spring();
          def = d;
          break;
        }
        case JointType::distance: {
          mink::DistanceJointDef d = mink::distance_joint_at(world_, a, b, anchor, vec(10));
          if (coin()) d.limit = limit();
          d.motor = motor();
          d.spring = spring();
          def = d;
          break;
        }
        case JointType::weld: {
          mink::WeldJointDef d = mink::weld_joint_at(world_, a, b, anchor);
          d.linear_hertz = coin() ? 0 : real(0, 10);
          d.angular_hertz = coin() ? 0 : real(0, 10);
          d.linear_damping_ratio = real(0, 2);
          d.angular_damping_ratio = real(0, 2);
          def = d;
          break;
        }
        case JointType::wheel: {
          mink::WheelJointDef d = mink::wheel_joint_at(world_, a, b, anchor, axis);
          d.limit = limit();
          d.motor = motor();
          d.spring = spring();
          def = d;
          break;
        }
        case JointType::motor: {
          mink::MotorJointDef d = mink::motor_joint_at(world_, a, b);
          d.max_force = real(0, 100);
          d.max_torque = real(0, 100);
          d.correction_factor = real(0, 1);
          def = d;
          break;
        }
        case JointType::gear: {
          mink::GearJointDef d;
          bool live1 = false, live2 = false;
          d.joint1 = any_joint(live1);
          d.joint2 = any_joint(live2);
          d.ratio = real(-3, 3);
          def = d;
          break;
        }
        case JointType::pulley:
          def =
              mink::pulley_joint_at(world_, a, b, vec(10), vec(10), vec(10), vec(10), real(0.1, 3));
          break;
      }
    });
    if (!made) return;
    mink::JointBase& base = mink::joint_base(def);
    base.collide_connected = coin();
    if (byte() < 32) base.break_force = real(0, 1000);
    if (byte() < 32) base.break_torque = real(0, 1000);
    JointId id;
    if (!attempt("create_joint", [&] { id = world_.create_joint(def); })) return;
    JointRecord record{id, type, world_.joint_body_a(id), world_.joint_body_b(id), {}, {}};
    if (type == JointType::gear) {
      const auto& gear = std::get<mink::GearJointDef>(def);
      record.joint1 = gear.joint1;
      record.joint2 = gear.joint2;
      const auto joint_of = [&](JointId j) {
        const auto it = std::ranges::find(joints_, j, &JointRecord::id);
        if (it == joints_.end()) fail("create_joint made a gear on a joint that is not alive");
        return *it;
      };
      const JointRecord j1 = joint_of(gear.joint1);
      const JointRecord j2 = joint_of(gear.joint2);
      if (j1.type != JointType::revolute && j1.type != JointType::prismatic) {
        fail("create_joint made a gear on a joint that is neither revolute nor prismatic");
      }
      if (j2.type != JointType::revolute && j2.type != JointType::prismatic) {
        fail("create_joint made a gear on a joint that is neither revolute nor prismatic");
      }
    } else {
      if (!live) fail("create_joint accepted a dead or foreign body");
      if (record.body_a != a || record.body_b != b) fail("joint bodies differ from its definition");
      if (a == b) fail("create_joint joined a body to itself");
    }
    joints_.push_back(record);
  }

  void destroy_joint() {
    bool live = false;
    const JointId id = any_joint(live);
    attempt_with(live, "destroy_joint", [&] { world_.destroy_joint(id); });
    if (live) {
      forget_joints_where([&](const JointRecord& j) { return j.id == id; });
    }
  }

  void set_joint_setting() {
    bool live = false;
    const JointId id = any_joint(live);
    switch (byte() % 9) {
      case 0: {
        const mink::JointMotor m = motor();
        attempt_with(live, "set_joint_motor", [&] { world_.set_joint_motor(id, m); });
        break;
      }
      case 1: {
        const mink::JointSpring s = spring();
        attempt_with(live, "set_joint_spring", [&] { world_.set_joint_spring(id, s); });
        break;
      }
      case 2: {
        const mink::JointLimit l = limit();
        attempt_with(live, "set_joint_limit", [&] { world_.set_joint_limit(id, l); });
        break;
      }
      case 3: {
        const Real length = real(0, 10);
        attempt_with(live, "set_distance_length", [&] { world_.set_distance_length(id, length); });
        break;
      }
      case 4: {
        const Vec2 offset = vec(3);
        const Real angle = real(-3, 3);
        attempt_with(live, "set_motor_target", [&] { world_.set_motor_target(id, offset, angle); });
        break;
      }
      case 5: {
        const Real force = real(0, 100);
        const Real torque = real(0, 100);
        attempt_with(live, "set_motor_limits", [&] { world_.set_motor_limits(id, force, torque); });
        break;
      }
      case 6: {
        const Real lh = real(0, 10), ld = real(0, 2), ah = real(0, 10), ad = real(0, 2);
        attempt_with(live, "set_weld_springs",
                     [&] { world_.set_weld_springs(id, lh, ld, ah, ad); });
        break;
      }
      case 7: {
        const Real force = real(0, 1000), torque = real(0, 1000);
        attempt_with(live, "set_joint_break", [&] { world_.set_joint_break(id, force, torque); });
        break;
      }
      default:
        // Readers: a dead id throws; kinds without a motor, spring or limit throw typed errors.
        attempt_with(live, "joint_def", [&] { (void)world_.joint_def(id); });
        attempt_with(live, "joint_motor", [&] { (void)world_.joint_motor(id); });
        attempt_with(live, "joint_limit", [&] { (void)world_.joint_limit(id); });
        break;
    }
  }

  void set_body_state() {
    bool live = false;
    const BodyId id = any_body(live);
    switch (byte() % 14) {
      case 0: {
        const Vec2 p = vec(20);
        const Real a = real(-10, 10);
        attempt_with(live, "set_transform", [&] { world_.set_transform(id, p, a); });
        break;
      }
      case 1: {
        const Vec2 v = vec(20);
        attempt_with(live, "set_linear_velocity", [&] { world_.set_linear_velocity(id, v); });
        break;
      }
      case 2: {
        const Real w = real(-20, 20);
        attempt_with(live, "set_angular_velocity", [&] { world_.set_angular_velocity(id, w); });
        break;
      }
      case 3: {
        const Vec2 f = vec(500), at = vec(10);
        attempt_with(live, "apply_force", [&] { world_.apply_force(id, f, at); });
        break;
      }
      case 4: {
        const Real t = real(-500, 500);
        attempt_with(live, "apply_torque", [&] { world_.apply_torque(id, t); });
        break;
      }
      case 5: {
        const Vec2 j = vec(50), at = vec(10);
        attempt_with(live, "apply_linear_impulse", [&] { world_.apply_linear_impulse(id, j, at); });
        break;
      }
      case 6: {
        const bool awake = coin();
        attempt_with(live, "set_awake", [&] { world_.set_awake(id, awake); });
        break;
      }
      case 7: {
        const auto type = static_cast<mink::BodyType>(byte() % 3);
        attempt_with(live, "set_body_type", [&] { world_.set_body_type(id, type); });
        break;
      }
      case 8: {
        const bool enabled = byte() > 64;
        attempt_with(live, "set_enabled", [&] { world_.set_enabled(id, enabled); });
        break;
      }
      case 9: {
        const bool bullet = coin();
        attempt_with(live, "set_bullet", [&] { world_.set_bullet(id, bullet); });
        break;
      }
      case 10: {
        const bool fixed = coin();
        attempt_with(live, "set_fixed_rotation", [&] { world_.set_fixed_rotation(id, fixed); });
        break;
      }
      case 11: {
        const Real threshold = real(0, 2);
        attempt_with(live, "set_continuous_threshold",
                     [&] { world_.set_continuous_threshold(id, threshold); });
        break;
      }
      case 12: {
        const Vec2 p = vec(20);
        const Real a = real(-3, 3);
        const Real dt = real(0.001, 0.1);
        attempt_with(live, "set_target_transform",
                     [&] { world_.set_target_transform(id, p, a, dt); });
        break;
      }
      default: {
        mink::MassData mass{real(0.1, 10), vec(1), real(0.01, 10)};
        attempt_with(live, "set_mass_data", [&] { world_.set_mass_data(id, mass); });
        break;
      }
    }
  }

  void set_shape_setting() {
    bool live = false;
    const ShapeId id = any_shape(live);
    switch (byte() % 4) {
      case 0: {
        const mink::Filter f = filter();
        attempt_with(live, "set_shape_filter", [&] { world_.set_shape_filter(id, f); });
        break;
      }
      case 1: {
        const Real density = real(0, 5);
        attempt_with(live, "set_shape_density", [&] { world_.set_shape_density(id, density); });
        break;
      }
      case 2: {
        const Real friction = real(0, 1);
        attempt_with(live, "set_shape_friction", [&] { world_.set_shape_friction(id, friction); });
        break;
      }
      default: {
        const Real restitution = real(0, 1);
        attempt_with(live, "set_shape_restitution",
                     [&] { world_.set_shape_restitution(id, restitution); });
        break;
      }
    }
  }

  void set_world_setting() {
    if (coin()) {
      const Vec2 g = vec(20);
      attempt("set_gravity", [&] { world_.set_gravity(g); });
    } else {
      const bool sleep = coin();
      attempt("enable_sleep", [&] { world_.enable_sleep(sleep); });
    }
  }

  void query() {
    switch (byte() % 4) {
      case 0: {
        const Vec2 c = vec(20), h = {real(0, 10), real(0, 10)};
        const mink::Aabb box{c - h, c + h};
        std::vector<ShapeId> found;
        if (!attempt("query_aabb", [&] { found = world_.query_aabb(box); })) return;
        for (const ShapeId s : found) {
          require(world_.is_valid(s), "query_aabb found a dead shape");
          require(world_.shape_aabb(s).overlaps(box), "query_aabb found a shape off the box");
        }
        break;
      }
      case 1: {
        const Vec2 p = vec(20);
        std::vector<ShapeId> found;
        if (!attempt("query_point", [&] { found = world_.query_point(p); })) return;
        for (const ShapeId s : found) {
          require(world_.is_valid(s), "query_point found a dead shape");
          const mink::Aabb box = world_.shape_aabb(s);
          const mink::Aabb grown{box.lower - Vec2{1e-9, 1e-9}, box.upper + Vec2{1e-9, 1e-9}};
          require(grown.contains(p), "query_point found a shape whose box misses the point");
        }
        break;
      }
      case 2: {
        const Vec2 origin = vec(20), translation = vec(40);
        std::optional<mink::ShapeRayHit> hit;
        if (!attempt("ray_cast", [&] { hit = world_.ray_cast(origin, translation); })) return;
        if (hit) {
          require(world_.is_valid(hit->shape), "ray_cast hit a dead shape");
          require(hit->hit.fraction >= 0 && hit->hit.fraction <= 1, "ray_cast fraction off [0, 1]");
          require(finite(hit->hit.point) && finite(hit->hit.normal), "ray_cast hit not finite");
          require(std::abs(hit->hit.normal.norm() - 1) < 1e-6, "ray_cast normal not unit");
        }
        break;
      }
      default: {
        mink::ShapeDef def;
        if (!attempt("ShapeDef factory", [&] { def = shape_def(); })) return;
        const mink::Pose pose{vec(20), mink::Rotation::from_angle(real(-4, 4))};
        const Vec2 translation = vec(40);
        const mink::Filter f = filter();
        std::optional<mink::ShapeCastHit> hit;
        if (!attempt("cast_shape", [&] { hit = world_.cast_shape(def, pose, translation, f); })) {
          return;
        }
        if (hit) {
          require(world_.is_valid(hit->shape), "cast_shape hit a dead shape");
          require(hit->fraction >= 0 && hit->fraction <= 1, "cast_shape fraction off [0, 1]");
          require(finite(hit->point) && finite(hit->normal), "cast_shape hit not finite");
          // Zero only for a start overlapping the cores, where no direction separates them.
          const bool overlapped_at_start = hit->fraction == 0 && hit->normal == Vec2(0, 0);
          if (!overlapped_at_start && std::abs(hit->normal.norm() - 1) >= 1e-6) {
            char text[400];
            std::snprintf(text, sizeof text,
                          "cast_shape normal not unit: (%.17g, %.17g) at fraction %.17g, shape "
                          "kind %d with %zu points, radius %.17g, from (%.17g, %.17g) by "
                          "(%.17g, %.17g)",
                          hit->normal.x(), hit->normal.y(), hit->fraction,
                          static_cast<int>(def.type), def.points.size(), def.radius,
                          pose.position.x(), pose.position.y(), translation.x(), translation.y());
            fail(text);
          }
        }
        break;
      }
    }
  }

  void step() {
    ++steps_;
    // Events describe the last step run; a refused call or an advance too short for a step
    // runs none, and the events of an earlier step may name what was destroyed since.
    bool stepped = false;
    switch (byte() % 4) {
      case 0: {
        const Real dt = real(0.001, 0.05);
        const int substeps = static_cast<int>(byte() % 10) - 1;
        stepped = attempt("step(time_step, substeps)", [&] { world_.step(dt, substeps); });
        break;
      }
      case 1: {
        const Real frame = real(0, 0.1);
        mink::AdvanceResult result;
        stepped = attempt("advance", [&] { result = world_.advance(frame); }) && result.steps > 0;
        break;
      }
      default:
        stepped = attempt("step", [&] { world_.step(); });
        break;
    }
    if (stepped) check_events();
    step_digests_.push_back(digest());
  }

  void snapshot_round_trip() {
    trace("snapshot");
    const std::vector<std::uint8_t> bytes = world_.snapshot();
    const std::uint64_t hash = world_.state_hash(), before = digest();
    const int workers = world_.def().worker_count;
    mink::World copy = mink::World::from_snapshot(bytes, workers == 1 ? 2 : 1);
    require(copy.state_hash() == hash, "a world made from a snapshot hashes differently");
    require(copy.snapshot() == bytes, "a world made from a snapshot snapshots differently");
    attempt("step before a rollback", [&] { world_.step(); });
    world_.restore(bytes);
    require(world_.state_hash() == hash, "a rollback did not restore the state hash");
    require(digest() == before, "a rollback did not restore what the world reports");
    const bool stepped = attempt("step after a rollback", [&] { world_.step(); });
    bool copy_stepped = true;
    try {
      copy.step();
    } catch (const mink::Error&) {
      copy_stepped = false;
    }
    require(stepped == copy_stepped, "a world and its snapshot's copy step differently");
    require(copy.state_hash() == world_.state_hash(),
            "a world and its snapshot's copy differ after a step");
    ++steps_;
    if (stepped) check_events();
    step_digests_.push_back(digest());
  }

  void operation(std::uint8_t op) {
    switch (op % 16) {
      case 0:
      case 1:
        create_body();
        break;
      case 2:
        destroy_body();
        break;
      case 3:
      case 4:
        create_shape();
        break;
      case 5:
        create_chain();
        break;
      case 6:
        destroy_shape();
        break;
      case 7:
        create_joint();
        break;
      case 8:
        destroy_joint();
        break;
      case 9:
        set_joint_setting();
        break;
      case 10:
      case 11:
        set_body_state();
        break;
      case 12:
        set_shape_setting();
        break;
      case 13:
        op % 32 < 16 ? query() : set_world_setting();
        break;
      case 14:
        step();
        break;
      default:
        op % 32 < 16 ? step() : snapshot_round_trip();
        break;
    }
  }

  // ---- Invariants ---------------------------------------------------------------------------

  void check_events() {
    for (const mink::BodyMoveEvent& e : world_.body_move_events()) {
      require(world_.is_valid(e.body), "a move event names a dead body");
      require(finite(e.pose.position) && finite(e.pose.rotation.cos) && finite(e.pose.rotation.sin),
              "a move event pose is not finite");
    }
    for (const mink::ContactBeginEvent& e : world_.contact_begin_events()) {
      require(world_.is_valid(e.shape_a) && world_.is_valid(e.shape_b),
              "a contact begin event names a dead shape");
    }
    for (const mink::JointBreakEvent& e : world_.joint_break_events()) {
      require(world_.is_valid(e.joint), "a joint break event names a dead joint");
    }
  }

  // Everything observable that a call could change: what a failing call must leave alone and
  // what two worker counts must agree on.
  std::uint64_t digest() const {
    Digest d;
    d.add(std::uint64_t{world_.body_count()});
    d.add(std::uint64_t{world_.shape_count()});
    d.add(std::uint64_t{world_.joint_count()});
    d.add(world_.step_count());
    d.add(world_.def().gravity);
    d.add(world_.def().enable_sleep);
    for (const BodyId b : world_.bodies()) {
      d.add(std::uint64_t{b.index});
      d.add(std::uint64_t{static_cast<std::uint8_t>(world_.body_type(b))});
      d.add(world_.position(b));
      d.add(world_.angle(b));
      d.add(world_.linear_velocity(b));
      d.add(world_.angular_velocity(b));
      d.add(world_.mass(b));
      d.add(world_.rotational_inertia(b));
      d.add(world_.local_center(b));
      d.add(world_.is_awake(b));
      d.add(world_.is_enabled(b));
      d.add(world_.is_bullet(b));
      d.add(world_.fixed_rotation(b));
      d.add(world_.continuous_threshold(b));
      for (const ShapeId s : world_.body_shapes(b)) {
        d.add(std::uint64_t{s.index});
        const mink::Filter& f = world_.shape_filter(s);
        d.add(f.category);
        d.add(f.mask);
        d.add(std::uint64_t(static_cast<std::uint32_t>(f.group)));
        d.add(world_.shape_density(s));
        d.add(world_.shape_friction(s));
        d.add(world_.shape_restitution(s));
      }
    }
    for (const JointId j : world_.joints()) {
      d.add(std::uint64_t{j.index});
      d.add(std::uint64_t{static_cast<std::uint8_t>(world_.joint_type(j))});
      d.add(world_.joint_anchor_a(j));
      d.add(world_.joint_anchor_b(j));
      std::visit(
          [&](const auto& def) {
            d.add(def.break_force);
            d.add(def.break_torque);
            if constexpr (requires { def.motor; }) {
              d.add(def.motor.enabled);
              d.add(def.motor.speed);
              d.add(def.motor.max_force);
            }
            if constexpr (requires { def.spring; }) {
              d.add(def.spring.enabled);
              d.add(def.spring.hertz);
              d.add(def.spring.damping_ratio);
              d.add(def.spring.target);
            }
            if constexpr (requires { def.limit; }) {
              d.add(def.limit.enabled);
              d.add(def.limit.lower);
              d.add(def.limit.upper);
            }
            if constexpr (requires { def.length; }) d.add(def.length);
            if constexpr (requires { def.max_torque; }) {
              d.add(def.linear_offset);
              d.add(def.angular_offset);
              d.add(def.max_force);
              d.add(def.max_torque);
            }
            if constexpr (requires { def.linear_hertz; }) {
              d.add(def.linear_hertz);
              d.add(def.linear_damping_ratio);
              d.add(def.angular_hertz);
              d.add(def.angular_damping_ratio);
            }
          },
          world_.joint_def(j));
    }
    return d.value();
  }

  // A joint acts on its two bodies; a gear on the four bodies of its two joints.
  bool joins(JointId j, BodyId b) const {
    if (world_.joint_body_a(j) == b || world_.joint_body_b(j) == b) return true;
    const auto it = std::ranges::find(joints_, j, &JointRecord::id);
    if (it == joints_.end() || it->type != JointType::gear) return false;
    for (const JointId geared : {it->joint1, it->joint2}) {
      if (world_.joint_body_a(geared) == b || world_.joint_body_b(geared) == b) return true;
    }
    return false;
  }

  template <class Id>
  static bool by_slot(const Id& a, const Id& b) {
    return a.index < b.index;
  }

  void check() {
    require(world_.body_count() == bodies_.size(), "body_count differs from the live bodies");
    require(world_.shape_count() == shapes_.size(), "shape_count differs from the live shapes");
    require(world_.joint_count() == joints_.size(), "joint_count differs from the live joints");

    std::vector<BodyId> expected_bodies = bodies_;
    std::ranges::sort(expected_bodies, by_slot<BodyId>);
    require(world_.bodies() == expected_bodies, "bodies() differs from the live bodies");
    std::vector<JointId> expected_joints;
    for (const JointRecord& j : joints_) expected_joints.push_back(j.id);
    std::ranges::sort(expected_joints, by_slot<JointId>);
    require(world_.joints() == expected_joints, "joints() differs from the live joints");

    for (const BodyId id : dead_bodies_) require(!world_.is_valid(id), "a dead body is valid");
    for (const ShapeId id : dead_shapes_) require(!world_.is_valid(id), "a dead shape is valid");
    for (const JointId id : dead_joints_) require(!world_.is_valid(id), "a dead joint is valid");
    require(!world_.is_valid(foreign_body_) && !world_.is_valid(foreign_shape_) &&
                !world_.is_valid(foreign_joint_),
            "another world's id is valid here");
    require(
        !world_.is_valid(BodyId{}) && !world_.is_valid(ShapeId{}) && !world_.is_valid(JointId{}),
        "a null id is valid");

    for (const BodyId b : bodies_) {
      require(world_.is_valid(b), "a live body is not valid");
      require(finite(world_.position(b)) && finite(world_.angle(b)) &&
                  finite(world_.world_center(b)) && finite(world_.local_center(b)) &&
                  finite(world_.linear_velocity(b)) && finite(world_.angular_velocity(b)) &&
                  finite(world_.mass(b)) && finite(world_.rotational_inertia(b)),
              "a body state is not finite");
      const mink::Pose pose = world_.pose(b);
      require(std::abs(pose.rotation.cos * pose.rotation.cos +
                       pose.rotation.sin * pose.rotation.sin - 1) < 1e-6,
              "a body rotation is not a rotation");
      std::vector<ShapeId> expected;
      for (const ShapeRecord& s : shapes_) {
        if (s.body == b) expected.push_back(s.id);
      }
      std::vector<ShapeId> actual = world_.body_shapes(b);
      std::ranges::sort(expected, by_slot<ShapeId>);
      std::ranges::sort(actual, by_slot<ShapeId>);
      require(actual == expected, "body_shapes differs from the body's live shapes");
      for (const JointId j : world_.body_joints(b)) {
        require(world_.is_valid(j), "body_joints lists a dead joint");
        require(joins(j, b), "body_joints lists a joint of other bodies");
      }
    }
    for (const ShapeRecord& s : shapes_) {
      require(world_.is_valid(s.id), "a live shape is not valid");
      require(world_.shape_body(s.id) == s.body, "a shape moved to another body");
      const mink::Aabb box = world_.shape_aabb(s.id);
      require(finite(box.lower) && finite(box.upper), "a shape box is not finite");
      require(box.lower.x() <= box.upper.x() && box.lower.y() <= box.upper.y(),
              "a shape box is inside out");
    }
    for (const JointRecord& j : joints_) {
      require(world_.is_valid(j.id), "a live joint is not valid");
      require(world_.joint_type(j.id) == j.type, "a joint changed kind");
      require(world_.joint_body_a(j.id) == j.body_a && world_.joint_body_b(j.id) == j.body_b,
              "a joint changed bodies");
      for (const BodyId b : {j.body_a, j.body_b}) {
        const std::vector<JointId> listed = world_.body_joints(b);
        require(std::ranges::find(listed, j.id) != listed.end(),
                "a joint is missing from its body's joints");
      }
      require(finite(world_.joint_anchor_a(j.id)) && finite(world_.joint_anchor_b(j.id)) &&
                  finite(world_.joint_force(j.id)) && finite(world_.joint_torque(j.id)) &&
                  finite(world_.joint_coordinate(j.id)) && finite(world_.joint_speed(j.id)),
              "a joint reading is not finite");
    }
    check_contacts();
  }

  void check_contacts() {
    // Each body's contacts, as (lower shape slot, higher shape slot) pairs.
    using Pair = std::pair<std::uint32_t, std::uint32_t>;
    std::vector<std::pair<BodyId, std::vector<Pair>>> lists;
    for (const BodyId b : bodies_) {
      std::vector<Pair> pairs;
      for (const mink::ContactData& c : world_.body_contacts(b)) {
        require(world_.is_valid(c.shape_a) && world_.is_valid(c.shape_b),
                "a contact names a dead shape");
        const BodyId body_a = world_.shape_body(c.shape_a);
        const BodyId body_b = world_.shape_body(c.shape_b);
        require(body_a == b || body_b == b, "a body lists a contact of other bodies");
        require(body_a != body_b, "a contact joins a body to itself");
        const mink::Manifold& m = c.manifold;
        require(m.point_count >= 1 && m.point_count <= 2, "a contact has no manifold points");
        require(finite(m.normal) && std::abs(m.normal.norm() - 1) < 1e-6,
                "a contact normal is not a unit vector");
        for (int i = 0; i < m.point_count; ++i) {
          require(finite(m.points[i].point) && finite(m.points[i].separation),
                  "a contact point is not finite");
        }
        pairs.emplace_back(std::min(c.shape_a.index, c.shape_b.index),
                           std::max(c.shape_a.index, c.shape_b.index));
      }
      std::ranges::sort(pairs);
      require(std::ranges::adjacent_find(pairs) == pairs.end(), "a body lists a contact twice");
      lists.emplace_back(b, std::move(pairs));
    }
    // Symmetry: a contact between bodies A and B is in both lists.
    const auto list_of = [&](BodyId b) -> const std::vector<Pair>& {
      return std::ranges::find(lists, b, &std::pair<BodyId, std::vector<Pair>>::first)->second;
    };
    for (const auto& [b, pairs] : lists) {
      for (const Pair& p : pairs) {
        const ShapeRecord* sa = nullptr;
        const ShapeRecord* sb = nullptr;
        for (const ShapeRecord& s : shapes_) {
          if (s.id.index == p.first) sa = &s;
          if (s.id.index == p.second) sb = &s;
        }
        require(sa != nullptr && sb != nullptr, "a contact names a shape the model lacks");
        const BodyId other = sa->body == b ? sb->body : sa->body;
        const std::vector<Pair>& theirs = list_of(other);
        require(std::ranges::binary_search(theirs, p), "a contact is listed by one body only");
      }
    }
  }

  FuzzedDataProvider input_;
  mink::World world_;
  mink::World other_;
  BodyId foreign_body_;
  ShapeId foreign_shape_;
  JointId foreign_joint_;
  std::vector<BodyId> bodies_;
  std::vector<ShapeRecord> shapes_;
  std::vector<JointRecord> joints_;
  std::vector<BodyId> dead_bodies_;
  std::vector<ShapeId> dead_shapes_;
  std::vector<JointId> dead_joints_;
  std::vector<std::uint64_t> step_digests_;
  int steps_ = 0;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 2048) return 0;
  const std::vector<std::uint64_t> one_worker = CallSequence(data, size, 1).run();
  const std::vector<std::uint64_t> two_workers = CallSequence(data, size, 2).run();
  if (one_worker != two_workers) fail("1 and 2 workers give different states");
  return 0;
}
