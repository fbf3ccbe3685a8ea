#include "mink/engine/scene_file.hpp"

#include "mink/output_file.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <sstream>

#include "body.hpp"
#include "mink/engine/scene_fields.hpp"
#include "mink/engine/world.hpp"
#include "shape.hpp"

namespace mink {

namespace {

using Json = nlohmann::json;

constexpr const char* kFormat = "minkowski-scene";
constexpr int kVersion = 1;

std::string type_name(const Json& value) {
  if (value.is_null()) return "null";
  if (value.is_boolean()) return "a boolean";
  if (value.is_number()) return "a number";
  if (value.is_string()) return "a string";
  if (value.is_array()) return "an array";
  return "an object";
}

std::string index_path(const std::string& path, std::size_t index) {
  return path + "[" + std::to_string(index) + "]";
}

// An object being read: remembers which keys were asked for, so that finish() can report any
// other key (a typo must never be silently ignored).
class ObjectReader {
 public:
  ObjectReader(const Json& value, std::string path) : value_(value), path_(std::move(path)) {
    if (!value_.is_object()) {
      throw SceneFileError(path_, "expected an object, got " + type_name(value_));
    }
  }

  std::string child(std::string_view key) const {
    return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
  }
  const std::string& path() const { return path_; }
  bool has(std::string_view key) const { return value_.contains(key); }

  const Json* find(std::string_view key) {
    const auto it = value_.find(key);
    if (it == value_.end()) return nullptr;
    used_.emplace(key);
    return &*it;
  }
  const Json& require(std::string_view key) {
    const Json* value = find(key);
    if (value == nullptr) throw SceneFileError(child(key), "missing field");
    return *value;
  }

  void finish() const {
    for (const auto& [key, value] : value_.items()) {
      if (used_.count(key) == 0) throw SceneFileError(child(key), "unknown key");
    }
  }

 private:
  const Json& value_;
  std::string path_;
  std::set<std::string, std::less<>> used_;
};

const Json& require_array(const Json& v, const std::string& path) {
  if (!v.is_array()) throw SceneFileError(path, "expected an array, got " + type_name(v));
  return v;
}

// "must be > 0, got -1", "must be in 1..1000, got 0".
void check_range(const FieldRange& range, Real value, const Json& v, const std::string& path) {
  if (range.contains(value)) return;
  const bool interval =
      std::isfinite(range.min) && std::isfinite(range.max) && !range.min_exclusive;
  throw SceneFileError(path, std::string("must be ") + (interval ? "in " : "") + range.describe() +
                                 ", got " + v.dump());
}

Real read_number(const Json& v, const std::string& path, const FieldRange& range) {
  if (!v.is_number()) throw SceneFileError(path, "expected a number, got " + type_name(v));
  const Real x = v.get<Real>();
  if (!std::isfinite(x)) throw SceneFileError(path, "not a finite number (NaN or infinite)");
  check_range(range, x, v, path);
  return x;
}

Vec2 read_vec2(const Json& v, const std::string& path, const FieldRange& range) {
  if (!v.is_array() || v.size() != 2) {
    throw SceneFileError(
        path, "expected [x, y], got " +
                  (v.is_array() ? "an array of " + std::to_string(v.size()) : type_name(v)));
  }
  return {read_number(v[0], index_path(path, 0), range),
          read_number(v[1], index_path(path, 1), range)};
}

std::int64_t read_integer(const Json& v, const std::string& path, const FieldRange& range) {
  if (!v.is_number_integer()) {
    throw SceneFileError(path, "expected an integer, got " + type_name(v));
  }
  // Integers past int64 only come unsigned; every range here is far inside int64.
  const bool huge =
      v.is_number_unsigned() &&
      v.get<std::uint64_t>() > std::uint64_t(std::numeric_limits<std::int64_t>::max());
  const std::int64_t n = huge ? std::numeric_limits<std::int64_t>::max() : v.get<std::int64_t>();
  check_range(range, huge ? std::numeric_limits<Real>::infinity() : static_cast<Real>(n), v, path);
  return n;
}

std::uint64_t read_user_data(const Json& v, const std::string& path) {
  if (v.is_number_unsigned()) return v.get<std::uint64_t>();
  throw SceneFileError(path, "expected an integer in 0..18446744073709551615, got " +
                                 (v.is_number() ? v.dump() : type_name(v)));
}

// Bit sets read best in hex, so "0xFFFF" is accepted as well as a plain integer.
std::uint64_t read_bits(const Json& v, const std::string& path) {
  if (v.is_number_unsigned()) return v.get<std::uint64_t>();
  if (v.is_string()) {
    const std::string& s = v.get_ref<const std::string&>();
    const char* digits = s.data() + 2;
    const char* end = s.data() + s.size();
    std::uint64_t bits = 0;
    if (s.size() > 2 && s.size() <= 18 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X') &&
        std::isxdigit(static_cast<unsigned char>(*digits))) {
      const auto [ptr, error] = std::from_chars(digits, end, bits, 16);
      if (error == std::errc() && ptr == end) return bits;
    }
    throw SceneFileError(
        path, "expected a hex string of 1 to 16 digits like \"0xFFFF\", got " + v.dump());
  }
  throw SceneFileError(path,
                       "expected an integer in 0..18446744073709551615 or a hex string like "
                       "\"0xFFFF\", got " +
                           (v.is_number() ? v.dump() : type_name(v)));
}

std::string read_name(const Json& v, const std::string& path,
                      std::span<const std::string_view> names) {
  if (v.is_string()) {
    const std::string& s = v.get_ref<const std::string&>();
    if (std::find(names.begin(), names.end(), s) != names.end()) return s;
  }
  std::string list;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) list.append(i + 1 == names.size() ? " or " : ", ");
    list.append(1, '"').append(names[i]).append(1, '"');
  }
  throw SceneFileError(path, "expected " + list + ", got " + v.dump());
}

template <class Object>
FieldValue read_value(const Json& v, const std::string& path, const SceneField<Object>& field) {
  switch (field.kind) {
    case FieldKind::real:
      return read_number(v, path, field.range);
    case FieldKind::integer:
      return read_integer(v, path, field.range);
    case FieldKind::boolean:
      if (!v.is_boolean())
        throw SceneFileError(path, "expected true or false, got " + type_name(v));
      return v.get<bool>();
    case FieldKind::vec2:
      return read_vec2(v, path, field.range);
    case FieldKind::points: {
      std::vector<Vec2> points;
      for (std::size_t i = 0; i < require_array(v, path).size(); ++i) {
        points.push_back(read_vec2(v[i], index_path(path, i), field.range));
      }
      return points;
    }
    case FieldKind::bits:
      return read_bits(v, path);
    case FieldKind::user_data:
      return read_user_data(v, path);
    case FieldKind::name:
      return read_name(v, path, field.names());
  }
  throw SceneFileError(path, "field of unknown kind");
}

// Reads every key of `fields` that is present into `object`; the caller finishes the reader.
template <class Object>
void read_fields(ObjectReader& reader, std::span<const SceneField<Object>> fields, Object& object) {
  for (const SceneField<Object>& field : fields) {
    const Json* value = reader.find(field.key);
    const std::string path = reader.child(field.key);
    const bool applies = field.applies == nullptr || field.applies(object);
    if (value == nullptr) {
      if (field.required && applies) throw SceneFileError(path, "missing field");
      continue;
    }
    if (!applies) throw SceneFileError(path, "only allowed on " + std::string(field.applies_to));
    field.set(object, read_value(*value, path, field));
  }
}

// A nested object read entirely from one table.
template <class Object>
void read_object(const Json& value, const std::string& path,
                 std::span<const SceneField<Object>> fields, Object& object) {
  ObjectReader reader(value, path);
  read_fields(reader, fields, object);
  reader.finish();
}

Json vec_json(const Vec2& v) {
  return Json::array({v.x(), v.y()});
}

Json write_value(const FieldValue& value, FieldKind kind) {
  switch (kind) {
    case FieldKind::real:
      return std::get<Real>(value);
    case FieldKind::integer:
      return std::get<std::int64_t>(value);
    case FieldKind::boolean:
      return std::get<bool>(value);
    case FieldKind::vec2:
      return vec_json(std::get<Vec2>(value));
    case FieldKind::points: {
      Json points = Json::array();
      for (const Vec2& p : std::get<std::vector<Vec2>>(value)) points.push_back(vec_json(p));
      return points;
    }
    case FieldKind::bits: {
      std::array<char, 16> digits{};
      const char* end = std::to_chars(digits.data(), digits.data() + digits.size(),
                                      std::get<std::uint64_t>(value), 16)
                            .ptr;
      std::string hex = "0x";
      for (const char* c = digits.data(); c != end; ++c) {
        hex.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(*c))));
      }
      return hex;
    }
    case FieldKind::user_data:
      return std::get<std::uint64_t>(value);
    case FieldKind::name:
      return std::get<std::string>(value);
  }
  return nullptr;
}

template <class Object>
Json write_fields(std::span<const SceneField<Object>> fields, const Object& object) {
  Json out = Json::object();
  for (const SceneField<Object>& field : fields) {
    if (field.applies != nullptr && !field.applies(object)) continue;
    if (field.present != nullptr && !field.present(object)) continue;
    out[std::string(field.key)] = write_value(field.get(object), field.kind);
  }
  return out;
}

void check_world(const WorldDef& world, const std::string& path) {
  try {
    World check(world);  // settings valid one by one may still clash
  } catch (const Error& error) {
    throw SceneFileError(path, error.what());
  }
}

WorldDef read_world(const Json& value, const std::string& path) {
  WorldDef world;
  read_object(value, path, world_fields(), world);
  check_world(world, path);
  return world;
}

// The keys that say what a shape's geometry is; exactly one per shape.
std::vector<std::string_view> geometry_keys() {
  std::vector<std::string_view> keys = {"points", "box", "polygon"};
  for (const SceneShapeForm& form : shape_forms()) keys.push_back(form.key);
  return keys;
}

// The core points a geometry form's fields fill in, so an optional centre defaults to the
// origin rather than to nothing.
std::size_t core_point_count(ShapeType type) {
  switch (type) {
    case ShapeType::circle:
      return 1;
    case ShapeType::capsule:
    case ShapeType::segment:
      return 2;
    default:
      return 0;
  }
}

// Reads the one geometry key; returns the path to blame for a shape the engine refuses.
std::string read_geometry(ObjectReader& reader, ShapeDef& shape) {
  std::vector<std::string_view> present;
  const std::vector<std::string_view> keys = geometry_keys();
  for (const std::string_view key : keys) {
    if (reader.has(key)) present.push_back(key);
  }
  if (present.size() != 1) {
    std::string list;
    for (const std::string_view key : keys) list += (list.empty() ? "" : ", ") + std::string(key);
    throw SceneFileError(reader.path(), present.empty() ? "missing field: one of " + list
                                                        : "give only one of " + list);
  }
  const std::string_view key = present.front();
  const std::string path = reader.child(key);
  if (key == "points") return path;  // a shape field: read with the others
  if (key == "box") {
    SceneBox box;
    read_object(*reader.find(key), path, box_fields(), box);
    shape = ShapeDef::box(box.half_extents.x(), box.half_extents.y(), box.center, box.angle);
  } else if (key == "polygon") {
    SceneRegularPolygon polygon;
    read_object(*reader.find(key), path, regular_polygon_fields(), polygon);
    shape =
        ShapeDef::regular_polygon(static_cast<int>(polygon.count), polygon.radius, polygon.center);
  } else {
    const auto forms = shape_forms();
    const auto form = std::find_if(forms.begin(), forms.end(),
                                   [&](const SceneShapeForm& f) { return f.key == key; });
    shape.type = form->type;
    shape.points.assign(core_point_count(form->type), Vec2(0, 0));
    read_object(*reader.find(key), path, form->fields, shape);
  }
  return path;
}

ShapeDef read_shape(const Json& value, const std::string& path) {
  ObjectReader reader(value, path);
  ShapeDef shape;
  const std::string geometry_path = read_geometry(reader, shape);
  read_fields(reader, shape_fields(), shape);
  if (const Json* filter = reader.find("filter")) {
    read_object(*filter, reader.child("filter"), filter_fields(), shape.filter);
  }
  if (const Json* scale = reader.find("scale")) {
    if (shape.type != ShapeType::polygon) {
      throw SceneFileError(reader.child("scale"), "only allowed on polygon shapes");
    }
    ShapeScale s;
    read_object(*scale, reader.child("scale"), scale_fields(), s);
    shape.scale = s;
  }
  reader.finish();
  // Hull and check now, so a shape the engine would refuse is reported before anything runs.
  std::optional<ShapeGeometry> polygon;
  try {
    if (shape.type == ShapeType::polygon) polygon = detail::make_geometry(shape);
    check_shape_def(shape);
  } catch (const NonFiniteInputError& error) {
    throw SceneFileError(index_path(geometry_path, error.index()),
                         "not a finite number once scaled");
  } catch (const DegenerateInputError& error) {
    throw SceneFileError(geometry_path, std::string("degenerate hull: ") + error.what());
  } catch (const Error& error) {
    throw SceneFileError(geometry_path, error.what());
  }
  // A density the solver could not invert the mass of is refused here, as create_shape would.
  if (shape.type != ShapeType::chain) {
    try {
      detail::check_shape_mass(polygon ? *polygon : detail::make_geometry(shape), shape.density,
                               "the shape");
    } catch (const Error& error) {
      throw SceneFileError(reader.child("density"), error.what());
    }
  }
  return shape;
}

SceneBody read_body(const Json& value, const std::string& path) {
  ObjectReader reader(value, path);
  SceneBody body;
  read_fields(reader, body_fields(), body.body);
  // What the fields' ranges do not say, as create_body would refuse it (a velocity beyond
  // max_setting_magnitude was read, then refused when the scene was built).
  try {
    detail::check_body_def(body.body);
  } catch (const Error& error) {
    throw SceneFileError(path, error.what());
  }
  const std::string shapes_path = reader.child("shapes");
  const Json& shapes = require_array(reader.require("shapes"), shapes_path);
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    body.shapes.push_back(read_shape(shapes[i], index_path(shapes_path, i)));
  }
  reader.finish();
  return body;
}

Json shape_json(const ShapeDef& shape) {
  Json out = write_fields(shape_fields(), shape);
  for (const SceneShapeForm& form : shape_forms()) {
    if (form.type == shape.type) out[std::string(form.key)] = write_fields(form.fields, shape);
  }
  out["filter"] = write_fields(filter_fields(), shape.filter);
  if (shape.scale && shape.type == ShapeType::polygon) {
    out["scale"] = write_fields(scale_fields(), *shape.scale);
  }
  return out;
}

// ---- Joints ----

// Shortest round-trip form, "3" rather than JSON's "3.0", as the numbers were likely written.
std::string number_text(Real x) {
  std::array<char, 32> buffer{};
  return std::string(buffer.data(),
                     std::to_chars(buffer.data(), buffer.data() + buffer.size(), x).ptr);
}

// Two keys that say the same thing in two frames; one of them at most.
void exclusive(const ObjectReader& reader, std::string_view world_key, std::string_view local_key) {
  if (reader.has(world_key) && reader.has(local_key)) {
    throw SceneFileError(reader.child(local_key), "give only one of " + std::string(world_key) +
                                                      " and " + std::string(local_key));
  }
}

// A limit is on when its bounds are given: both (a distance joint's min_length may be left
// out, 0), lower <= upper.
template <class Def>
void check_limit(const ObjectReader& reader, const Def& def, std::string_view lower_key,
                 std::string_view upper_key, bool lower_optional) {
  const bool lower = reader.has(lower_key), upper = reader.has(upper_key);
  if (lower && !upper) {
    throw SceneFileError(reader.child(upper_key),
                         "missing field (" + std::string(lower_key) + " is given)");
  }
  if (upper && !lower && !lower_optional) {
    throw SceneFileError(reader.child(lower_key),
                         "missing field (" + std::string(upper_key) + " is given)");
  }
  if (def.limit.enabled && def.limit.lower > def.limit.upper) {
    throw SceneFileError(reader.child(upper_key), "must be >= " + std::string(lower_key) + " (" +
                                                      number_text(def.limit.lower) + "), got " +
                                                      number_text(def.limit.upper));
  }
}

// A gear's joints: earlier ones (a gear is made after them), revolute or prismatic.
void check_gear(const ObjectReader& reader, const SceneJoint& joint, const SceneDef& scene,
                std::size_t index) {
  for (const auto& [key, j] :
       {std::pair{"joint1", joint.joint1}, std::pair{"joint2", joint.joint2}}) {
    if (j >= index) {
      throw SceneFileError(reader.child(key), "no joint " + std::to_string(j) +
                                                  " before this one (a gear comes after its "
                                                  "joints)");
    }
    const JointType type = joint_type(scene.joints[j].def);
    if (type != JointType::revolute && type != JointType::prismatic) {
      throw SceneFileError(reader.child(key),
                           "joint " + std::to_string(j) + " is a " + std::string(to_string(type)) +
                               " joint; a gear couples revolute or prismatic joints");
    }
  }
  if (joint.joint1 == joint.joint2) {
    throw SceneFileError(reader.child("joint2"),
                         "the same joint as joint1 (" + std::to_string(joint.joint1) + ")");
  }
  if (std::get<GearJointDef>(joint.def).ratio == 0) {
    throw SceneFileError(reader.child("ratio"), "must not be 0 for a gear");
  }
}

// The checks and conversions that need the scene: indices, world-frame keys turned body-local
// with the bodies' defined poses, and the defaults computed from them.
void resolve_joint(const ObjectReader& reader, SceneJointRecord& record, const SceneDef& scene,
                   std::size_t index) {
  SceneJoint& joint = record.joint;
  if (joint_type(joint.def) == JointType::gear) return check_gear(reader, joint, scene, index);
  for (const auto& [key, b] :
       {std::pair{"body_a", joint.body_a}, std::pair{"body_b", joint.body_b}}) {
    if (b >= scene.bodies.size()) {
      throw SceneFileError(reader.child(key), "no body " + std::to_string(b));
    }
  }
  if (joint.body_a == joint.body_b) {
    throw SceneFileError(reader.child("body_b"),
                         "the same body as body_a (" + std::to_string(joint.body_a) + ")");
  }
  exclusive(reader, "anchor", "local_anchor_a");
  exclusive(reader, "anchor", "local_anchor_b");
  exclusive(reader, "anchor_a", "local_anchor_a");
  exclusive(reader, "anchor_b", "local_anchor_b");
  exclusive(reader, "axis", "local_axis_a");
  const Pose pose_a = scene_body_pose(scene, joint.body_a);
  const Pose pose_b = scene_body_pose(scene, joint.body_b);
  std::visit(
      [&](auto& d) {
        using Def = std::decay_t<decltype(d)>;
        if constexpr (requires { d.local_anchor_a; }) {
          if (record.anchor) {
            d.local_anchor_a = pose_a.apply_inverse(*record.anchor);
            d.local_anchor_b = pose_b.apply_inverse(*record.anchor);
          }
          if (record.anchor_a) d.local_anchor_a = pose_a.apply_inverse(*record.anchor_a);
          if (record.anchor_b) d.local_anchor_b = pose_b.apply_inverse(*record.anchor_b);
        }
        if constexpr (requires { d.reference_angle; }) {
          // A joint placed by a world point holds the bodies as they are defined.
          if (record.anchor && !reader.has("reference_angle")) {
            d.reference_angle =
                scene.bodies[joint.body_b].body.angle - scene.bodies[joint.body_a].body.angle;
          }
        }
        if constexpr (requires { d.local_axis_a; }) {
          if (record.axis) {
            const Real length = record.axis->norm();
            if (length == 0) throw SceneFileError(reader.child("axis"), "must not be [0, 0]");
            d.local_axis_a = pose_a.rotation.apply_inverse(Vec2(*record.axis / length));
          } else if (std::abs(d.local_axis_a.norm() - 1) > 1e-6) {
            throw SceneFileError(reader.child("local_axis_a"), "must be a unit vector");
          }
        }
        if constexpr (std::is_same_v<Def, DistanceJointDef>) {
          check_limit(reader, d, "min_length", "max_length", true);
          if ((record.anchor_a || record.anchor_b) && !reader.has("length")) {
            d.length = (pose_b.apply(d.local_anchor_b) - pose_a.apply(d.local_anchor_a)).norm();
            if (!(d.length > 0)) {
              throw SceneFileError(reader.child("anchor_b"),
                                   "is anchor_a: give a length, the anchors' distance is 0");
            }
          }
        } else if constexpr (requires { d.limit; }) {
          check_limit(reader, d, "lower", "upper", false);
        }
        if constexpr (std::is_same_v<Def, PulleyJointDef>) {
          if (!(d.ratio > 0)) {
            throw SceneFileError(reader.child("ratio"),
                                 "must be > 0 for a pulley, got " + number_text(d.ratio));
          }
          const auto rope = [&](bool given, const char* key, Real& length, const Vec2& anchor,
                                const Vec2& ground) {
            if (!given || reader.has(key)) return;
            length = (anchor - ground).norm();
            if (!(length > 0)) {
              throw SceneFileError(reader.child(key),
                                   "missing field (the anchor is on the ground "
                                   "point: the rope's length would be 0)");
            }
          };
          rope(record.anchor_a.has_value(), "length_a", d.length_a, pose_a.apply(d.local_anchor_a),
               d.ground_anchor_a);
          rope(record.anchor_b.has_value(), "length_b", d.length_b, pose_b.apply(d.local_anchor_b),
               d.ground_anchor_b);
        }
      },
      joint.def);
}

SceneJoint read_joint(const Json& value, const std::string& path, const SceneDef& scene,
                      std::size_t index) {
  ObjectReader reader(value, path);
  SceneJointRecord record;
  read_fields(reader, joint_fields(), record);
  for (const SceneJointPart& part : joint_parts()) {
    const Json* nested = reader.find(part.key);
    if (nested == nullptr) continue;
    const std::string part_path = reader.child(part.key);
    if (!part.applies(record)) {
      throw SceneFileError(part_path, "only allowed on " + std::string(part.applies_to));
    }
    part.enable(record);
    read_object(*nested, part_path, part.fields, record);
  }
  reader.finish();
  resolve_joint(reader, record, scene, index);
  return record.joint;
}

// Anything else the engine refuses, found by making the joints between shapeless twins of the
// bodies (cheap: no shapes, no hulls).
void check_joints_in_engine(const SceneDef& scene) {
  if (scene.joints.empty()) return;
  SceneDef trial;
  trial.world = scene.world;
  for (const SceneBody& body : scene.bodies) trial.bodies.push_back({body.body, {}});
  trial.joints = scene.joints;
  try {
    (void)build_world(trial);
  } catch (const Error& error) {
    // build_world names the joint first: "joints[3]: problem".
    const std::string message = error.what();
    const std::size_t colon = message.find(": ");
    if (message.rfind("joints[", 0) == 0 && colon != std::string::npos) {
      throw SceneFileError(message.substr(0, colon), message.substr(colon + 2));
    }
    throw SceneFileError("joints", message);
  }
}

Json joint_json(const SceneJoint& joint) {
  SceneJointRecord record;
  record.joint = joint;
  Json out = write_fields(joint_fields(), record);
  for (const SceneJointPart& part : joint_parts()) {
    if (part.applies(record)) out[std::string(part.key)] = write_fields(part.fields, record);
  }
  return out;
}

// Re-reads text the DOM parser refused for a number too large for a double, to name where
// that number is: the SAX events carry the path of the value being read.
class PathTracker : public nlohmann::json_sax<Json> {
 public:
  std::string error_path;

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override {
    frames_.push_back({false, 0, ""});
    return true;
  }
  bool key(string_t& key) override {
    frames_.back().key = key;
    return true;
  }
  bool end_object() override { return end(); }
  bool start_array(std::size_t) override {
    frames_.push_back({true, 0, ""});
    return true;
  }
  bool end_array() override { return end(); }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override {
    error_path = path();
    return false;
  }

 private:
  struct Frame {
    bool array;
    std::size_t index;
    std::string key;
  };
  std::string path() const {
    std::string p;
    for (const Frame& f : frames_) {
      if (f.array) {
        p = index_path(p, f.index);
      } else {
        p += (p.empty() ? "" : ".") + f.key;
      }
    }
    return p;
  }
  bool value() {
    if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
    return true;
  }
  bool end() {
    frames_.pop_back();
    return value();
  }
  std::vector<Frame> frames_;
};

Json parse_json(std::string_view text, const std::string& source) {
  try {
    return Json::parse(text);
  } catch (const Json::parse_error& error) {
    throw SceneFileError(source, std::string("not valid JSON: ") + error.what());
  } catch (const Json::out_of_range&) {
    // JSON has no NaN or infinity; a literal like 1e999 is the only way to write one.
    PathTracker tracker;
    Json::sax_parse(text, &tracker);
    throw SceneFileError(tracker.error_path.empty() ? source : tracker.error_path,
                         "not a finite number (NaN or infinite)");
  } catch (const Json::exception& error) {
    throw SceneFileError(source, std::string("not valid JSON: ") + error.what());
  }
}

}  // namespace

void set_world_setting(WorldDef& world, std::string_view key, std::string_view value) {
  const std::string path = "world." + std::string(key);
  Json object = Json::object();
  object[std::string(key)] = parse_json(value, path);
  WorldDef changed = world;
  read_object(object, "world", world_fields(), changed);
  check_world(changed, path);
  world = changed;
}

SceneDef parse_scene_json(std::string_view text, const std::string& source) {
  const Json root = parse_json(text, source);
  ObjectReader reader(root, "");
  if (const Json* format = reader.find("format")) {
    if (!format->is_string() || format->get<std::string>() != kFormat) {
      throw SceneFileError("format",
                           std::string("expected \"") + kFormat + "\", got " + format->dump());
    }
  }
  if (const Json* version = reader.find("version")) {
    if (!version->is_number_integer() || version->get<long long>() != kVersion) {
      throw SceneFileError("version", "only version " + std::to_string(kVersion) +
                                          " is known, got " + version->dump());
    }
  }
  SceneDef scene;
  if (const Json* world = reader.find("world")) scene.world = read_world(*world, "world");
  const Json& bodies = require_array(reader.require("bodies"), "bodies");
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    scene.bodies.push_back(read_body(bodies[i], index_path("bodies", i)));
  }
  if (const Json* joints = reader.find("joints")) {
    require_array(*joints, "joints");
    for (std::size_t i = 0; i < joints->size(); ++i) {
      scene.joints.push_back(read_joint((*joints)[i], index_path("joints", i), scene, i));
    }
    check_joints_in_engine(scene);
  }
  reader.finish();
  return scene;
}

SceneDef load_scene_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InvalidArgumentError("cannot read scene file '" + path.string() + "'");
  std::ostringstream text;
  text << in.rdbuf();
  try {
    return parse_scene_json(text.str(), path.string());
  } catch (const SceneFileError& error) {
    const std::string problem = std::string(error.what()).substr(error.json_path().size() + 2);
    throw SceneFileError(error.json_path(), problem + " (in " + path.string() + ")");
  }
}

std::string scene_to_json(const SceneDef& scene) {
  Json bodies = Json::array();
  for (const SceneBody& body : scene.bodies) {
    Json shapes = Json::array();
    for (const ShapeDef& shape : body.shapes) shapes.push_back(shape_json(shape));
    Json b = write_fields(body_fields(), body.body);
    b["shapes"] = std::move(shapes);
    bodies.push_back(std::move(b));
  }
  Json root = {{"format", kFormat},
               {"version", kVersion},
               {"world", write_fields(world_fields(), scene.world)},
               {"bodies", std::move(bodies)}};
  if (!scene.joints.empty()) {
    Json joints = Json::array();
    for (const SceneJoint& joint : scene.joints) joints.push_back(joint_json(joint));
    root["joints"] = std::move(joints);
  }
  return root.dump(1) + "\n";
}

void save_scene_file(const std::filesystem::path& path, const SceneDef& scene) {
  const std::string text = scene_to_json(scene);
  OutputFile out(path, "scene file");
  out.stream() << text;
  out.commit();
}

SceneDef resolve_scene(const std::string& name_or_path) {
  if (is_builtin_scene(name_or_path)) return builtin_scene(name_or_path);
  if (!std::filesystem::exists(name_or_path)) {
    std::string list;
    for (const std::string_view n : builtin_scene_names())
      list += (list.empty() ? "" : ", ") + std::string(n);
    throw InvalidArgumentError("'" + name_or_path + "' is neither a built-in scene (" + list +
                               ") nor a scene file");
  }
  return load_scene_file(name_or_path);
}

}  // namespace mink
