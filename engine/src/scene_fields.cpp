#include "mink/engine/scene_fields.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace mink {

bool FieldRange::contains(Real value) const noexcept {
  return (min_exclusive ? value > min : value >= min) && value <= max;
}

std::string FieldRange::describe() const {
  const auto text = [](Real x) {
    // Whole bounds as integers ("1000000", not "1e+06"): they are mostly integer ranges.
    if (x == std::trunc(x) && std::abs(x) < 1e15) return std::to_string(static_cast<long long>(x));
    std::array<char, 32> buffer{};
    const auto end = std::to_chars(buffer.data(), buffer.data() + buffer.size(), x).ptr;
    return std::string(buffer.data(), end);
  };
  const bool has_min = std::isfinite(min), has_max = std::isfinite(max);
  if (has_min && has_max && !min_exclusive) return text(min) + ".." + text(max);
  std::string out;
  if (has_min) out = (min_exclusive ? "> " : ">= ") + text(min);
  if (has_max) out += (out.empty() ? "<= " : " and <= ") + text(max);
  return out;
}

namespace {

constexpr Real kInfinity = std::numeric_limits<Real>::infinity();
constexpr FieldRange kPositive{0, kInfinity, true};
constexpr FieldRange kNonNegative{0, kInfinity, false};

// Member pointers give each table row its getter and setter, so a row names its member once.
template <class>
struct MemberOf;
template <class Object, class Value>
struct MemberOf<Value Object::*> {
  using object = Object;
};

FieldValue to_value(Real v) {
  return v;
}
FieldValue to_value(int v) {
  return std::int64_t{v};
}
FieldValue to_value(std::int64_t v) {
  return v;
}
FieldValue to_value(bool v) {
  return v;
}
FieldValue to_value(const Vec2& v) {
  return v;
}
FieldValue to_value(const std::vector<Vec2>& v) {
  return v;
}
FieldValue to_value(std::uint64_t v) {
  return v;
}

// The reader hands setters values it has already checked against the row's kind and range.
void from_value(const FieldValue& v, Real& out) {
  out = std::get<Real>(v);
}
void from_value(const FieldValue& v, int& out) {
  out = static_cast<int>(std::get<std::int64_t>(v));
}
void from_value(const FieldValue& v, std::int64_t& out) {
  out = std::get<std::int64_t>(v);
}
void from_value(const FieldValue& v, bool& out) {
  out = std::get<bool>(v);
}
void from_value(const FieldValue& v, Vec2& out) {
  out = std::get<Vec2>(v);
}
void from_value(const FieldValue& v, std::vector<Vec2>& out) {
  out = std::get<std::vector<Vec2>>(v);
}
void from_value(const FieldValue& v, std::uint64_t& out) {
  out = std::get<std::uint64_t>(v);
}

template <auto Member>
FieldValue get_member(const typename MemberOf<decltype(Member)>::object& object) {
  return to_value(object.*Member);
}
template <auto Member>
void set_member(typename MemberOf<decltype(Member)>::object& object, const FieldValue& value) {
  from_value(value, object.*Member);
}

template <class Object>
constexpr SceneField<Object> row(std::string_view key, FieldKind kind,
                                 FieldValue (*get)(const Object&),
                                 void (*set)(Object&, const FieldValue&), std::string_view doc,
                                 FieldRange range = {}) {
  SceneField<Object> out;
  out.key = key;
  out.kind = kind;
  out.get = get;
  out.set = set;
  out.doc = doc;
  out.range = range;
  return out;
}

template <auto Member>
constexpr SceneField<typename MemberOf<decltype(Member)>::object> field(std::string_view key,
                                                                        FieldKind kind,
                                                                        std::string_view doc,
                                                                        FieldRange range = {}) {
  return row(key, kind, &get_member<Member>, &set_member<Member>, doc, range);
}

template <class Object>
constexpr SceneField<Object> name_field(std::string_view key, FieldValue (*get)(const Object&),
                                        void (*set)(Object&, const FieldValue&),
                                        std::string_view doc,
                                        std::span<const std::string_view> (*names)()) {
  SceneField<Object> out = row(key, FieldKind::name, get, set, doc);
  out.names = names;
  return out;
}

template <class Object>
constexpr SceneField<Object> required(SceneField<Object> row) {
  row.required = true;
  return row;
}

bool is_polygon(const ShapeDef& shape) {
  return shape.type == ShapeType::polygon;
}

constexpr SceneField<ShapeDef> polygon_only(SceneField<ShapeDef> row) {
  row.applies = &is_polygon;
  row.applies_to = "polygon shapes";
  return row;
}

// The geometry forms keep their points in ShapeDef::points: point I of the core.
template <std::size_t I>
FieldValue get_point(const ShapeDef& shape) {
  return I < shape.points.size() ? shape.points[I] : Vec2(0, 0);
}
template <std::size_t I>
void set_point(ShapeDef& shape, const FieldValue& value) {
  if (shape.points.size() <= I) shape.points.resize(I + 1, Vec2(0, 0));
  shape.points[I] = std::get<Vec2>(value);
}
template <std::size_t I>
constexpr SceneField<ShapeDef> point_field(std::string_view key, std::string_view doc) {
  return row<ShapeDef>(key, FieldKind::vec2, &get_point<I>, &set_point<I>, doc);
}

std::span<const std::string_view> body_type_names() {
  static const std::array<std::string_view, 3> names = {to_string(BodyType::static_body),
                                                        to_string(BodyType::kinematic),
                                                        to_string(BodyType::dynamic)};
  return names;
}
FieldValue get_body_type(const BodyDef& body) {
  return std::string(to_string(body.type));
}
void set_body_type(BodyDef& body, const FieldValue& value) {
  for (const BodyType type : {BodyType::static_body, BodyType::kinematic, BodyType::dynamic}) {
    if (to_string(type) == std::get<std::string>(value)) body.type = type;
  }
}

std::span<const std::string_view> algorithm_names() {
  static const std::vector<std::string_view> names = [] {
    std::vector<std::string_view> out;
    for (const HullAlgorithm algorithm : all_hull_algorithms()) out.push_back(to_string(algorithm));
    return out;
  }();
  return names;
}
FieldValue get_algorithm(const ShapeDef& shape) {
  return std::string(to_string(shape.algorithm));
}
void set_algorithm(ShapeDef& shape, const FieldValue& value) {
  shape.algorithm = parse_hull_algorithm(std::get<std::string>(value));
}

// ---- Joints ----
// A joint key lives in some kinds' definitions: `Kinds<...>` lists them (and says so in the
// docs), a `Part` lambda points at the key's member in a definition of one of them.

template <class... Defs>
struct Kinds {
  template <class D>
  static constexpr bool has = (std::is_same_v<std::remove_cvref_t<D>, Defs> || ...);
  static bool applies(const SceneJointRecord& r) {
    return std::visit([](const auto& d) { return has<decltype(d)>; }, r.joint.def);
  }
  // "revolute, prismatic and wheel joints", from the kinds' own names.
  static std::string_view text() {
    static const std::string out = [] {
      const std::vector<std::string_view> names = {to_string(joint_type(JointDef(Defs{})))...};
      std::string list;
      for (std::size_t i = 0; i < names.size(); ++i) {
        if (i > 0) list += i + 1 == names.size() ? " and " : ", ";
        list += names[i];
      }
      return list + " joints";
    }();
    return out;
  }
};

using AnyJoint = Kinds<RevoluteJointDef, PrismaticJointDef, DistanceJointDef, WeldJointDef,
                       WheelJointDef, MotorJointDef, GearJointDef, PulleyJointDef>;
using TwoBodies = Kinds<RevoluteJointDef, PrismaticJointDef, DistanceJointDef, WeldJointDef,
                        WheelJointDef, MotorJointDef, PulleyJointDef>;
using Anchored = Kinds<RevoluteJointDef, PrismaticJointDef, DistanceJointDef, WeldJointDef,
                       WheelJointDef, PulleyJointDef>;
using OneAnchor = Kinds<RevoluteJointDef, PrismaticJointDef, WeldJointDef, WheelJointDef>;
using TwoAnchors = Kinds<DistanceJointDef, PulleyJointDef>;
using Axial = Kinds<PrismaticJointDef, WheelJointDef>;
using Angled = Kinds<RevoluteJointDef, PrismaticJointDef, WeldJointDef>;
using Bounded = Kinds<RevoluteJointDef, PrismaticJointDef, WheelJointDef>;
using Driven = Kinds<RevoluteJointDef, PrismaticJointDef, DistanceJointDef, WheelJointDef>;
using Turning = Kinds<RevoluteJointDef, WheelJointDef>;
using Pushing = Kinds<PrismaticJointDef, DistanceJointDef>;
using Targeted = Kinds<RevoluteJointDef, PrismaticJointDef, WheelJointDef>;
using Distance = Kinds<DistanceJointDef>;
using Weld = Kinds<WeldJointDef>;
using Motor = Kinds<MotorJointDef>;
using Gear = Kinds<GearJointDef>;
using Pulley = Kinds<PulleyJointDef>;
using Ratio = Kinds<GearJointDef, PulleyJointDef>;

using JointRow = SceneField<SceneJointRecord>;

template <class K, auto Part>
FieldValue get_def(const SceneJointRecord& r) {
  return std::visit(
      [](const auto& d) -> FieldValue {
        if constexpr (K::template has<decltype(d)>) {
          return to_value(*Part(d));
        } else {
          return FieldValue{};  // never asked: the row does not apply
        }
      },
      r.joint.def);
}
// `Enable` turns on what the key belongs to (a limit), or is null.
template <class K, auto Part, auto Enable = nullptr>
void set_def(SceneJointRecord& r, const FieldValue& value) {
  std::visit(
      [&](auto& d) {
        if constexpr (K::template has<decltype(d)>) {
          from_value(value, *Part(d));
          if constexpr (!std::is_null_pointer_v<decltype(Enable)>) Enable(d);
        }
      },
      r.joint.def);
}
template <class K, auto Flag>
bool def_flag(const SceneJointRecord& r) {
  return std::visit(
      [](const auto& d) {
        if constexpr (K::template has<decltype(d)>) {
          return Flag(d);
        } else {
          return false;
        }
      },
      r.joint.def);
}

// A key of the definitions of kinds K.
template <class K, auto Part, auto Enable = nullptr>
JointRow def_field(std::string_view key, FieldKind kind, std::string_view doc,
                   FieldRange range = {}) {
  JointRow out =
      row<SceneJointRecord>(key, kind, &get_def<K, Part>, &set_def<K, Part, Enable>, doc, range);
  if constexpr (!std::is_same_v<K, AnyJoint>) {
    out.applies = &K::applies;
    out.applies_to = K::text();
  }
  return out;
}
// A key of a nested part's object: the part already says which kinds have it.
template <class K, auto Part>
JointRow part_field(std::string_view key, FieldKind kind, std::string_view doc,
                    FieldRange range = {}) {
  JointRow out = def_field<K, Part>(key, kind, doc, range);
  out.applies = nullptr;
  out.applies_to = {};
  return out;
}
// An optional key, absent unless `Present` (e.g. a limit's bound: only while it is on).
template <class K, auto Part, auto Enable, auto Present>
JointRow optional_field(std::string_view key, std::string_view doc, FieldRange range = {}) {
  JointRow out = def_field<K, Part, Enable>(key, FieldKind::real, doc, range);
  out.present = &def_flag<K, Present>;
  return out;
}

// Scene indices (of bodies, of joints) kept in the record's SceneJoint.
template <auto Member>
FieldValue get_index(const SceneJointRecord& r) {
  return static_cast<std::int64_t>(r.joint.*Member);
}
template <auto Member>
void set_index(SceneJointRecord& r, const FieldValue& value) {
  r.joint.*Member = static_cast<std::size_t>(std::get<std::int64_t>(value));
}
template <class K, auto Member>
JointRow index_field(std::string_view key, std::string_view doc) {
  JointRow out = required(row<SceneJointRecord>(key, FieldKind::integer, &get_index<Member>,
                                                &set_index<Member>, doc, {0, 2147483647.0}));
  out.applies = &K::applies;
  out.applies_to = K::text();
  return out;
}

// World-frame keys: read only, the reader converts them once the bodies are known.
bool never(const SceneJointRecord&) {
  return false;
}
template <auto Member>
FieldValue get_world(const SceneJointRecord& r) {
  return (r.*Member).value_or(Vec2(0, 0));
}
template <auto Member>
void set_world(SceneJointRecord& r, const FieldValue& value) {
  r.*Member = std::get<Vec2>(value);
}
template <class K, auto Member>
JointRow world_field(std::string_view key, std::string_view doc) {
  JointRow out =
      row<SceneJointRecord>(key, FieldKind::vec2, &get_world<Member>, &set_world<Member>, doc);
  out.applies = &K::applies;
  out.applies_to = K::text();
  out.present = &never;
  return out;
}

std::span<const std::string_view> joint_type_names() {
  static const std::vector<std::string_view> names = [] {
    std::vector<std::string_view> out;
    for (std::size_t i = 0; i < std::variant_size_v<JointDef>; ++i) {
      out.push_back(to_string(static_cast<JointType>(i)));
    }
    return out;
  }();
  return names;
}
FieldValue get_joint_type(const SceneJointRecord& r) {
  return std::string(to_string(joint_type(r.joint.def)));
}
template <std::size_t... I>
JointDef default_def(std::size_t index, std::index_sequence<I...>) {
  JointDef out;
  ((index == I ? (out = std::variant_alternative_t<I, JointDef>{}, 0) : 0), ...);
  return out;
}
// The type comes first in the table: it makes the kind's default definition, which the other
// keys then fill in.
void set_joint_type(SceneJointRecord& r, const FieldValue& value) {
  const auto names = joint_type_names();
  const auto at = std::find(names.begin(), names.end(), std::get<std::string>(value));
  r.joint.def = default_def(static_cast<std::size_t>(at - names.begin()),
                            std::make_index_sequence<std::variant_size_v<JointDef>>());
}

bool finite_force(const SceneJointRecord& r) {
  return std::isfinite(joint_base(r.joint.def).break_force);
}
bool finite_torque(const SceneJointRecord& r) {
  return std::isfinite(joint_base(r.joint.def).break_torque);
}

constexpr auto kLimitOn = [](auto& d) { d.limit.enabled = true; };
constexpr auto kLimitOnNow = [](const auto& d) { return d.limit.enabled; };

const std::vector<JointRow>& joint_rows() {
  static const std::vector<JointRow> rows = [] {
    JointRow type = required(name_field<SceneJointRecord>("type", &get_joint_type, &set_joint_type,
                                                          "the kind of joint", &joint_type_names));
    JointRow force = def_field<AnyJoint, [](auto& d) { return &d.break_force; }>(
        "break_force", FieldKind::real,
        "N: a joint_break event each step the joint's force exceeds it", kNonNegative);
    force.present = &finite_force;
    JointRow torque = def_field<AnyJoint, [](auto& d) { return &d.break_torque; }>(
        "break_torque", FieldKind::real,
        "N m: a joint_break event each step the joint's torque exceeds it", kNonNegative);
    torque.present = &finite_torque;
    return std::vector<JointRow>{
        type,
        index_field<TwoBodies, &SceneJoint::body_a>(
            "body_a", "index into bodies: body A, whose frame holds axes and angles"),
        index_field<TwoBodies, &SceneJoint::body_b>("body_b", "index into bodies: body B"),
        index_field<Gear, &SceneJoint::joint1>(
            "joint1", "index into joints: an earlier revolute or prismatic joint"),
        index_field<Gear, &SceneJoint::joint2>(
            "joint2", "index into joints: another earlier revolute or prismatic joint"),
        world_field<OneAnchor, &SceneJointRecord::anchor>(
            "anchor", "world point joining the bodies (read only: written as local anchors)"),
        world_field<TwoAnchors, &SceneJointRecord::anchor_a>(
            "anchor_a", "world point on body A (read only: written as local_anchor_a)"),
        world_field<TwoAnchors, &SceneJointRecord::anchor_b>(
            "anchor_b", "world point on body B (read only: written as local_anchor_b)"),
        def_field<Anchored, [](auto& d) { return &d.local_anchor_a; }>(
            "local_anchor_a", FieldKind::vec2, "the anchor on body A, in A's frame"),
        def_field<Anchored, [](auto& d) { return &d.local_anchor_b; }>(
            "local_anchor_b", FieldKind::vec2, "the anchor on body B, in B's frame"),
        world_field<Axial, &SceneJointRecord::axis>(
            "axis", "world direction, any length (read only: written as local_axis_a)"),
        def_field<Axial, [](auto& d) { return &d.local_axis_a; }>(
            "local_axis_a", FieldKind::vec2, "unit axis in A's frame: slide or suspension"),
        def_field<Angled, [](auto& d) { return &d.reference_angle; }>(
            "reference_angle", FieldKind::real,
            "B's angle minus A's where the joint angle is 0 (with anchor: as the bodies are)"),
        optional_field<Bounded, [](auto& d) { return &d.limit.lower; }, kLimitOn, kLimitOnNow>(
            "lower", "limit's lower bound, rad or m; lower and upper turn the limit on"),
        optional_field<Bounded, [](auto& d) { return &d.limit.upper; }, kLimitOn, kLimitOnNow>(
            "upper", "limit's upper bound, >= lower"),
        def_field<Distance, [](auto& d) { return &d.length; }>(
            "length", FieldKind::real, "rest length, m (with anchor_a, anchor_b: their distance)",
            kPositive),
        optional_field<Distance, [](auto& d) { return &d.limit.lower; }, kLimitOn, kLimitOnNow>(
            "min_length", "shortest length, m (0 when only max_length is given)", kNonNegative),
        optional_field<Distance, [](auto& d) { return &d.limit.upper; }, kLimitOn, kLimitOnNow>(
            "max_length", "longest length, m (a rope: min_length 0)", kNonNegative),
        def_field<Weld, [](auto& d) { return &d.linear_hertz; }>(
            "linear_hertz", FieldKind::real, "0: rigid; else a spring's frequency", kNonNegative),
        def_field<Weld, [](auto& d) { return &d.linear_damping_ratio; }>(
            "linear_damping_ratio", FieldKind::real, "1: critical", kNonNegative),
        def_field<Weld, [](auto& d) { return &d.angular_hertz; }>(
            "angular_hertz", FieldKind::real, "0: rigid; else a spring's frequency", kNonNegative),
        def_field<Weld, [](auto& d) { return &d.angular_damping_ratio; }>(
            "angular_damping_ratio", FieldKind::real, "1: critical", kNonNegative),
        def_field<Motor, [](auto& d) { return &d.linear_offset; }>(
            "linear_offset", FieldKind::vec2, "target: B's origin in A's frame"),
        def_field<Motor, [](auto& d) { return &d.angular_offset; }>(
            "angular_offset", FieldKind::real, "target: B's angle minus A's"),
        def_field<Motor, [](auto& d) { return &d.max_force; }>(
            "max_force", FieldKind::real, "N, most force to reach the target", kNonNegative),
        def_field<Motor, [](auto& d) { return &d.max_torque; }>(
            "max_torque", FieldKind::real, "N m, most torque to reach the target", kNonNegative),
        def_field<Motor, [](auto& d) { return &d.correction_factor; }>(
            "correction_factor", FieldKind::real, "share of the error removed per step",
            FieldRange{0, 1}),
        def_field<Ratio, [](auto& d) { return &d.ratio; }>(
            "ratio", FieldKind::real,
            "gear: non-zero; pulley: > 0, B's rope counts this many times"),
        def_field<Pulley, [](auto& d) { return &d.ground_anchor_a; }>(
            "ground_a", FieldKind::vec2, "world point A's rope runs over"),
        def_field<Pulley, [](auto& d) { return &d.ground_anchor_b; }>(
            "ground_b", FieldKind::vec2, "world point B's rope runs over"),
        def_field<Pulley, [](auto& d) { return &d.length_a; }>(
            "length_a", FieldKind::real, "A's rope, m (with anchor_a: from it to ground_a)",
            kPositive),
        def_field<Pulley, [](auto& d) { return &d.length_b; }>(
            "length_b", FieldKind::real, "B's rope, m (with anchor_b: from it to ground_b)",
            kPositive),
        def_field<AnyJoint, [](auto& d) { return &d.collide_connected; }>(
            "collide_connected", FieldKind::boolean, "let the two bodies collide"),
        force,
        torque,
        def_field<AnyJoint, [](auto& d) { return &d.user_data; }>(
            "user_data", FieldKind::user_data, "kept for the caller (JointBase::user_data)"),
    };
  }();
  return rows;
}

const std::vector<JointRow>& motor_rows() {
  static const std::vector<JointRow> rows = {
      part_field<Driven, [](auto& d) { return &d.motor.enabled; }>(
          "enabled", FieldKind::boolean, "false keeps the motor's settings but turns it off"),
      part_field<Driven, [](auto& d) { return &d.motor.speed; }>(
          "speed", FieldKind::real, "target speed of the joint's coordinate, rad/s or m/s"),
      def_field<Turning, [](auto& d) { return &d.motor.max_force; }>(
          "max_torque", FieldKind::real, "N m, the most the motor applies", kNonNegative),
      def_field<Pushing, [](auto& d) { return &d.motor.max_force; }>(
          "max_force", FieldKind::real, "N, the most the motor applies", kNonNegative),
  };
  return rows;
}

const std::vector<JointRow>& spring_rows() {
  static const std::vector<JointRow> rows = {
      part_field<Driven, [](auto& d) { return &d.spring.enabled; }>(
          "enabled", FieldKind::boolean, "false keeps the spring's settings but turns it off"),
      part_field<Driven, [](auto& d) { return &d.spring.hertz; }>(
          "hertz", FieldKind::real, "natural frequency (0: holds the coordinate's speed)",
          kNonNegative),
      part_field<Driven, [](auto& d) { return &d.spring.damping_ratio; }>(
          "damping_ratio", FieldKind::real, "1: critical", kNonNegative),
      def_field<Targeted, [](auto& d) { return &d.spring.target; }>(
          "target", FieldKind::real, "rest angle or translation (a distance joint's is length)"),
  };
  return rows;
}

const std::vector<SceneJointPart>& part_list() {
  static const std::vector<SceneJointPart> parts = {
      {"motor", &Driven::applies, Driven::text(),
       [](SceneJointRecord& r) {
         set_def<Driven, [](auto& d) { return &d.motor.enabled; }>(
             r, FieldValue(std::in_place_type<bool>, true));
       },
       motor_rows()},
      {"spring", &Driven::applies, Driven::text(),
       [](SceneJointRecord& r) {
         set_def<Driven, [](auto& d) { return &d.spring.enabled; }>(
             r, FieldValue(std::in_place_type<bool>, true));
       },
       spring_rows()},
  };
  return parts;
}

constexpr SceneField<WorldDef> kWorldFields[] = {
    field<&WorldDef::gravity>("gravity", FieldKind::vec2, "m/s^2, world frame"),
    field<&WorldDef::time_step>("time_step", FieldKind::real, "seconds per fixed step", kPositive),
    field<&WorldDef::substeps>("substeps", FieldKind::integer, "soft-step substeps per step",
                               {1, max_substeps}),
    field<&WorldDef::contact_hertz>("contact_hertz", FieldKind::real,
                                    "contact spring stiffness, cycles per second", kNonNegative),
    field<&WorldDef::contact_damping_ratio>("contact_damping_ratio", FieldKind::real,
                                            "contact spring damping ratio (1: critical)",
                                            kNonNegative),
    field<&WorldDef::joint_hertz>(
        "joint_hertz", FieldKind::real,
        "how stiffly rigid joints push out their error, cycles per second", kNonNegative),
    field<&WorldDef::joint_damping_ratio>("joint_damping_ratio", FieldKind::real,
                                          "damping of that push-out (1: critical)", kNonNegative),
    field<&WorldDef::joint_iterations>("joint_iterations", FieldKind::integer,
                                       "joint passes per substep in the biased solve",
                                       {1, max_joint_iterations}),
    field<&WorldDef::direct_joint_chains>("direct_joint_chains", FieldKind::boolean,
                                          "solve chains of revolute joints exactly as one system"),
    field<&WorldDef::enable_continuous>(
        "enable_continuous", FieldKind::boolean,
        "sweep fast bodies and stop them at their first touch (continuous collision)"),
    field<&WorldDef::continuous_fast_pairs>(
        "continuous_fast_pairs", FieldKind::boolean,
        "sweep fast bodies against each other too, not only bullets (false: as Box2D v3)"),
    field<&WorldDef::fast_body_margin>(
        "fast_body_margin", FieldKind::boolean,
        "keep the speculative margin on fast bodies' broadphase boxes (false: as Box2D v3)"),
    field<&WorldDef::contact_push_max_velocity>(
        "contact_push_max_velocity", FieldKind::real,
        "fastest speed (m/s) at which overlap is pushed apart", kNonNegative),
    field<&WorldDef::restitution_threshold>("restitution_threshold", FieldKind::real,
                                            "approach speeds (m/s) below this do not bounce",
                                            kNonNegative),
    field<&WorldDef::hit_event_threshold>(
        "hit_event_threshold", FieldKind::real,
        "contacts closing faster (m/s) report a hit event, for shapes with hit_events",
        kNonNegative),
    field<&WorldDef::linear_slop>("linear_slop", FieldKind::real, "allowed overlap, m", kPositive),
    field<&WorldDef::max_linear_speed>("max_linear_speed", FieldKind::real,
                                       "m/s; faster bodies are clamped to it", kPositive),
    field<&WorldDef::enable_sleep>("enable_sleep", FieldKind::boolean, "let resting bodies sleep"),
    field<&WorldDef::time_to_sleep>("time_to_sleep", FieldKind::real,
                                    "seconds a body must rest before it may sleep", kNonNegative),
    field<&WorldDef::linear_sleep_tolerance>("linear_sleep_tolerance", FieldKind::real,
                                             "m/s below which a body rests", kNonNegative),
    field<&WorldDef::angular_sleep_tolerance>("angular_sleep_tolerance", FieldKind::real,
                                              "rad/s below which a body rests", kNonNegative),
    field<&WorldDef::max_steps_per_advance>("max_steps_per_advance", FieldKind::integer,
                                            "most steps one World::advance call runs",
                                            {1, 1'000'000}),
    field<&WorldDef::simd_solver>("simd_solver", FieldKind::boolean,
                                  "solve eight contacts at a time (same results)"),
    field<&WorldDef::reuse_manifolds>("reuse_manifolds", FieldKind::boolean,
                                      "keep manifolds while a pair barely moves"),
    field<&WorldDef::manifold_reuse_distance>(
        "manifold_reuse_distance", FieldKind::real,
        "m a touching pair may move before its manifold is computed anew", kNonNegative),
};

constexpr SceneField<BodyDef> kBodyFields[] = {
    required(name_field<BodyDef>("type", &get_body_type, &set_body_type, "how the body moves",
                                 &body_type_names)),
    field<&BodyDef::position>("position", FieldKind::vec2, "world position of the body origin"),
    field<&BodyDef::angle>("angle", FieldKind::real, "radians, counter-clockwise"),
    field<&BodyDef::linear_velocity>("linear_velocity", FieldKind::vec2, "of the body origin, m/s"),
    field<&BodyDef::angular_velocity>("angular_velocity", FieldKind::real, "rad/s"),
    field<&BodyDef::linear_damping>("linear_damping", FieldKind::real,
                                    "slows linear velocity over time", kNonNegative),
    field<&BodyDef::angular_damping>("angular_damping", FieldKind::real,
                                     "slows angular velocity over time", kNonNegative),
    field<&BodyDef::gravity_scale>("gravity_scale", FieldKind::real,
                                   "multiplies the world's gravity"),
    field<&BodyDef::allow_sleep>("allow_sleep", FieldKind::boolean, "false keeps the body awake"),
    field<&BodyDef::awake>("awake", FieldKind::boolean, "false creates it asleep"),
    field<&BodyDef::enabled>("enabled", FieldKind::boolean,
                             "false keeps it in the world but neither simulated nor collided"),
    field<&BodyDef::fixed_rotation>("fixed_rotation", FieldKind::boolean, "true: never rotates"),
    field<&BodyDef::bullet>("bullet", FieldKind::boolean,
                            "continuous collision against dynamic bodies too"),
    field<&BodyDef::continuous_threshold>(
        "continuous_threshold", FieldKind::real,
        "a step moving it farther than this fraction of its thinnest half-width is swept",
        kNonNegative),
    field<&BodyDef::user_data>("user_data", FieldKind::user_data,
                               "handed back by World::user_data"),
};

constexpr SceneField<ShapeDef> kShapeFields[] = {
    polygon_only(field<&ShapeDef::points>(
        "points", FieldKind::points, "any point set, body frame: its convex hull is the core")),
    polygon_only(field<&ShapeDef::radius>(
        "radius", FieldKind::real, "rounding: the shape is every point this close to the core",
        kNonNegative)),
    polygon_only(name_field<ShapeDef>("algorithm", &get_algorithm, &set_algorithm,
                                      "the hull algorithm", &algorithm_names)),
    field<&ShapeDef::density>("density", FieldKind::real, "kg/m^2", kNonNegative),
    field<&ShapeDef::friction>("friction", FieldKind::real, "Coulomb coefficient", kNonNegative),
    field<&ShapeDef::restitution>("restitution", FieldKind::real, "bounciness (0: none)",
                                  kNonNegative),
    field<&ShapeDef::is_sensor>("sensor", FieldKind::boolean,
                                "detects overlap (sensor events), never pushes"),
    field<&ShapeDef::enable_contact_events>("contact_events", FieldKind::boolean,
                                            "begin and end contact events for its pairs"),
    field<&ShapeDef::enable_sensor_events>("sensor_events", FieldKind::boolean,
                                           "sensors see this shape (and a sensor reports at all)"),
    field<&ShapeDef::enable_hit_events>("hit_events", FieldKind::boolean,
                                        "hit events for its pairs"),
    field<&ShapeDef::user_data>("user_data", FieldKind::user_data,
                                "handed back by World::shape_user_data"),
};

constexpr SceneField<Filter> kFilterFields[] = {
    field<&Filter::category>("category", FieldKind::bits, "the bits this shape is"),
    field<&Filter::mask>("mask", FieldKind::bits, "the bits this shape collides with"),
    field<&Filter::group>("group", FieldKind::integer,
                          "0: none; same positive: always collide; same negative: never",
                          {-2147483648.0, 2147483647.0}),
};

constexpr SceneField<ShapeScale> kScaleFields[] = {
    field<&ShapeScale::fixed_point>("fixed_point", FieldKind::vec2,
                                    "body-local point that stays put"),
    field<&ShapeScale::factor>("factor", FieldKind::vec2, "per-axis factors"),
};

constexpr SceneField<ShapeDef> kCircleFields[] = {
    point_field<0>("center", "body-local centre"),
    required(field<&ShapeDef::radius>("radius", FieldKind::real, "m", kPositive)),
};

constexpr SceneField<ShapeDef> kCapsuleFields[] = {
    required(point_field<0>("center1", "centre of one end, body-local")),
    required(point_field<1>("center2", "centre of the other end, distinct from center1")),
    required(field<&ShapeDef::radius>("radius", FieldKind::real, "m", kPositive)),
};

constexpr SceneField<ShapeDef> kSegmentFields[] = {
    required(point_field<0>("point1", "one end, body-local")),
    required(point_field<1>("point2", "the other end, distinct from point1")),
};

constexpr SceneField<ShapeDef> kChainFields[] = {
    required(field<&ShapeDef::points>(
        "points", FieldKind::points,
        "at least 2 (3 for a loop); each segment collides on its right side")),
    field<&ShapeDef::loop>("loop", FieldKind::boolean, "join the last point to the first"),
};

constexpr SceneShapeForm kShapeForms[] = {
    {"circle", ShapeType::circle, kCircleFields},
    {"capsule", ShapeType::capsule, kCapsuleFields},
    {"segment", ShapeType::segment, kSegmentFields},
    {"chain", ShapeType::chain, kChainFields},
};

constexpr SceneField<SceneBox> kBoxFields[] = {
    required(
        field<&SceneBox::half_extents>("half_extents", FieldKind::vec2, "[hx, hy]", kPositive)),
    field<&SceneBox::center>("center", FieldKind::vec2, "body-local centre"),
    field<&SceneBox::angle>("angle", FieldKind::real, "radians"),
};

constexpr SceneField<SceneRegularPolygon> kRegularPolygonFields[] = {
    required(field<&SceneRegularPolygon::count>("count", FieldKind::integer, "vertex count",
                                                {3, 1'000'000})),
    required(field<&SceneRegularPolygon::radius>("radius", FieldKind::real,
                                                 "circumradius (not rounding)", kPositive)),
    field<&SceneRegularPolygon::center>("center", FieldKind::vec2, "body-local centre"),
};

}  // namespace

std::span<const SceneField<WorldDef>> world_fields() noexcept {
  return kWorldFields;
}
std::span<const SceneField<BodyDef>> body_fields() noexcept {
  return kBodyFields;
}
std::span<const SceneField<ShapeDef>> shape_fields() noexcept {
  return kShapeFields;
}
std::span<const SceneField<Filter>> filter_fields() noexcept {
  return kFilterFields;
}
std::span<const SceneField<ShapeScale>> scale_fields() noexcept {
  return kScaleFields;
}
std::span<const SceneShapeForm> shape_forms() noexcept {
  return kShapeForms;
}
std::span<const SceneField<SceneJointRecord>> joint_fields() noexcept {
  return joint_rows();
}
std::span<const SceneJointPart> joint_parts() noexcept {
  return part_list();
}
std::span<const SceneField<SceneBox>> box_fields() noexcept {
  return kBoxFields;
}
std::span<const SceneField<SceneRegularPolygon>> regular_polygon_fields() noexcept {
  return kRegularPolygonFields;
}

}  // namespace mink
