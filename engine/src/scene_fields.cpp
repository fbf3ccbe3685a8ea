#include "mink/engine/scene_fields.hpp"

#include <array>
#include <charconv>
#include <cmath>
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

constexpr SceneField<WorldDef> kWorldFields[] = {
    field<&WorldDef::gravity>("gravity", FieldKind::vec2, "m/s^2, world frame"),
    field<&WorldDef::time_step>("time_step", FieldKind::real, "seconds per fixed step", kPositive),
    field<&WorldDef::substeps>("substeps", FieldKind::integer, "soft-step substeps per step",
                               {1, 1000}),
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
                                       "joint passes per substep in the biased solve", {1, 1000}),
    field<&WorldDef::direct_joint_chains>("direct_joint_chains", FieldKind::boolean,
                                          "solve chains of revolute joints exactly as one system"),
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
                                  "solve four contacts at a time (same results)"),
    field<&WorldDef::reuse_manifolds>("reuse_manifolds", FieldKind::boolean,
                                      "keep manifolds while a pair barely moves"),
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
std::span<const SceneField<SceneBox>> box_fields() noexcept {
  return kBoxFields;
}
std::span<const SceneField<SceneRegularPolygon>> regular_polygon_fields() noexcept {
  return kRegularPolygonFields;
}

}  // namespace mink
