#include "scene_file.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "mink/engine/world.hpp"
#include "output_files.hpp"

namespace mink::cli {

namespace {

using Json = nlohmann::json;

constexpr const char* kFormat = "minkowski-scene";
constexpr int kVersion = 1;

const char* type_name(const Json& value) {
  if (value.is_null()) return "null";
  if (value.is_boolean()) return "a boolean";
  if (value.is_number()) return "a number";
  if (value.is_string()) return "a string";
  if (value.is_array()) return "an array";
  return "an object";
}

// An object being read: tracks which keys were used so leftovers are reported as unknown.
class ObjectReader {
 public:
  ObjectReader(const Json& value, std::string path) : value_(value), path_(std::move(path)) {
    if (!value_.is_object()) {
      throw SceneFileError(path_, std::string("expected an object, got ") + type_name(value_));
    }
  }

  std::string child(std::string_view key) const { return join(path_, key); }
  const std::string& path() const { return path_; }
  bool has(const std::string& key) const { return value_.contains(key); }

  const Json* find(const std::string& key) {
    const auto it = value_.find(key);
    if (it == value_.end()) return nullptr;
    used_.insert(key);
    return &*it;
  }
  const Json& require(const std::string& key) {
    const Json* value = find(key);
    if (value == nullptr) throw SceneFileError(child(key), "missing field");
    return *value;
  }

  void number(const std::string& key, Real& out) {
    if (const Json* v = find(key)) out = read_number(*v, child(key));
  }
  void integer(const std::string& key, int& out, int lo, int hi) {
    if (const Json* v = find(key)) {
      if (!v->is_number_integer()) {
        throw SceneFileError(child(key), std::string("expected an integer, got ") + type_name(*v));
      }
      const auto n = v->get<long long>();
      if (n < lo || n > hi) {
        throw SceneFileError(child(key), "must be in " + std::to_string(lo) + ".." +
                                             std::to_string(hi) + ", got " + std::to_string(n));
      }
      out = static_cast<int>(n);
    }
  }
  void boolean(const std::string& key, bool& out) {
    if (const Json* v = find(key)) {
      if (!v->is_boolean()) {
        throw SceneFileError(child(key),
                             std::string("expected true or false, got ") + type_name(*v));
      }
      out = v->get<bool>();
    }
  }
  void vec2(const std::string& key, Vec2& out) {
    if (const Json* v = find(key)) out = read_vec2(*v, child(key));
  }

  // Throws for the first key never asked for (a typo would otherwise be silently ignored).
  void finish() const {
    for (const auto& [key, value] : value_.items()) {
      if (used_.count(key) == 0) throw SceneFileError(child(key), "unknown key");
    }
  }

  static std::string join(const std::string& path, std::string_view key) {
    return path.empty() ? std::string(key) : path + "." + std::string(key);
  }

  static Real read_number(const Json& v, const std::string& path) {
    if (!v.is_number()) {
      throw SceneFileError(path, std::string("expected a number, got ") + type_name(v));
    }
    const Real x = v.get<Real>();
    if (!std::isfinite(x)) throw SceneFileError(path, "not a finite number (NaN or infinite)");
    return x;
  }
  static Vec2 read_vec2(const Json& v, const std::string& path) {
    if (!v.is_array() || v.size() != 2) {
      throw SceneFileError(path, std::string("expected [x, y], got ") +
                                     (v.is_array() ? "an array of " + std::to_string(v.size())
                                                   : std::string(type_name(v))));
    }
    return {read_number(v[0], path + "[0]"), read_number(v[1], path + "[1]")};
  }

 private:
  const Json& value_;
  std::string path_;
  std::set<std::string> used_;
};

const Json& require_array(const Json& v, const std::string& path) {
  if (!v.is_array())
    throw SceneFileError(path, std::string("expected an array, got ") + type_name(v));
  return v;
}

WorldDef read_world(const Json& value, const std::string& path) {
  ObjectReader r(value, path);
  WorldDef w;
  r.vec2("gravity", w.gravity);
  r.number("time_step", w.time_step);
  r.integer("substeps", w.substeps, 1, 1000);
  r.number("contact_hertz", w.contact_hertz);
  r.number("contact_damping_ratio", w.contact_damping_ratio);
  r.number("contact_push_max_velocity", w.contact_push_max_velocity);
  r.number("restitution_threshold", w.restitution_threshold);
  r.number("linear_slop", w.linear_slop);
  r.number("max_linear_speed", w.max_linear_speed);
  r.boolean("enable_sleep", w.enable_sleep);
  r.number("time_to_sleep", w.time_to_sleep);
  r.number("linear_sleep_tolerance", w.linear_sleep_tolerance);
  r.number("angular_sleep_tolerance", w.angular_sleep_tolerance);
  r.integer("max_steps_per_advance", w.max_steps_per_advance, 1, 1'000'000);
  r.boolean("simd_solver", w.simd_solver);
  r.boolean("reuse_manifolds", w.reuse_manifolds);
  r.finish();
  try {
    World check(w);  // the world's own validation names the bad field
  } catch (const Error& error) {
    throw SceneFileError(path, error.what());
  }
  return w;
}

BodyType parse_body_type(const Json& v, const std::string& path) {
  if (v.is_string()) {
    const std::string s = v.get<std::string>();
    for (const BodyType type : {BodyType::static_body, BodyType::kinematic, BodyType::dynamic}) {
      if (s == to_string(type)) return type;
    }
  }
  throw SceneFileError(path, "expected \"static\", \"kinematic\" or \"dynamic\", got " + v.dump());
}

ShapeDef read_shape(const Json& value, const std::string& path) {
  ObjectReader r(value, path);
  const int forms = int(r.has("points")) + int(r.has("box")) + int(r.has("polygon"));
  if (forms != 1) {
    throw SceneFileError(path, forms == 0 ? "missing field: one of points, box, polygon"
                                          : "give only one of points, box, polygon");
  }
  ShapeDef shape;
  if (const Json* points = r.find("points")) {
    const std::string p = r.child("points");
    for (std::size_t i = 0; i < require_array(*points, p).size(); ++i) {
      shape.points.push_back(
          ObjectReader::read_vec2((*points)[i], p + "[" + std::to_string(i) + "]"));
    }
  } else if (const Json* box = r.find("box")) {
    ObjectReader b(*box, r.child("box"));
    const Vec2 half = ObjectReader::read_vec2(b.require("half_extents"), b.child("half_extents"));
    Vec2 center{0, 0};
    Real angle = 0;
    b.vec2("center", center);
    b.number("angle", angle);
    b.finish();
    if (!(half.x() > 0 && half.y() > 0)) {
      throw SceneFileError(b.child("half_extents"), "both half extents must be positive");
    }
    shape = ShapeDef::box(half.x(), half.y(), center, angle);
  } else {
    ObjectReader g(*r.find("polygon"), r.child("polygon"));
    int count = 0;
    if (!g.has("count")) throw SceneFileError(g.child("count"), "missing field");
    g.integer("count", count, 3, 1'000'000);
    const Real radius = ObjectReader::read_number(g.require("radius"), g.child("radius"));
    Vec2 center{0, 0};
    g.vec2("center", center);
    g.finish();
    if (!(radius > 0)) throw SceneFileError(g.child("radius"), "must be positive");
    shape = ShapeDef::regular_polygon(count, radius, center);
  }
  if (const Json* algorithm = r.find("algorithm")) {
    try {
      if (!algorithm->is_string()) throw InvalidArgumentError("expected a string");
      shape.algorithm = parse_hull_algorithm(algorithm->get<std::string>());
    } catch (const Error& error) {
      throw SceneFileError(r.child("algorithm"), error.what());
    }
  }
  r.number("density", shape.density);
  r.number("friction", shape.friction);
  r.number("restitution", shape.restitution);
  if (const Json* scale = r.find("scale")) {
    ObjectReader s(*scale, r.child("scale"));
    ShapeScale sc;
    s.vec2("fixed_point", sc.fixed_point);
    s.vec2("factor", sc.factor);
    s.finish();
    shape.scale = sc;
  }
  r.finish();
  // Hull now, so a degenerate or non-finite shape is reported before anything runs.
  try {
    (void)make_shape_hull(shape);
  } catch (const NonFiniteInputError& error) {
    throw SceneFileError(r.child("points") + "[" + std::to_string(error.index()) + "]",
                         "not a finite number (NaN or infinite)");
  } catch (const DegenerateInputError& error) {
    throw SceneFileError(r.has("points") ? r.child("points") : path,
                         std::string("degenerate hull: ") + error.what());
  } catch (const Error& error) {
    throw SceneFileError(path, error.what());
  }
  return shape;
}

SceneBody read_body(const Json& value, const std::string& path) {
  ObjectReader r(value, path);
  SceneBody body;
  BodyDef& b = body.body;
  b.type = parse_body_type(r.require("type"), r.child("type"));
  r.vec2("position", b.position);
  r.number("angle", b.angle);
  r.vec2("linear_velocity", b.linear_velocity);
  r.number("angular_velocity", b.angular_velocity);
  r.number("linear_damping", b.linear_damping);
  r.number("angular_damping", b.angular_damping);
  r.number("gravity_scale", b.gravity_scale);
  r.boolean("allow_sleep", b.allow_sleep);
  r.boolean("awake", b.awake);
  if (const Json* v = r.find("user_data")) {
    if (!v->is_number_unsigned() && !(v->is_number_integer() && v->get<long long>() >= 0)) {
      throw SceneFileError(r.child("user_data"), "expected a non-negative integer");
    }
    b.user_data = v->get<std::uint64_t>();
  }
  const std::string shapes_path = r.child("shapes");
  const Json& shapes = require_array(r.require("shapes"), shapes_path);
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    body.shapes.push_back(read_shape(shapes[i], shapes_path + "[" + std::to_string(i) + "]"));
  }
  r.finish();
  return body;
}

Json vec_json(const Vec2& v) {
  return Json::array({v.x(), v.y()});
}

// Re-reads text the DOM parser refused for a number too large for a double, to name where
// that number is: the SAX events keep the path of the value being read.
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
        p.push_back('[');
        p.append(std::to_string(f.index));
        p.push_back(']');
      } else {
        if (!p.empty()) p.push_back('.');
        p.append(f.key);
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

}  // namespace

SceneDef parse_scene_json(std::string_view text, const std::string& source) {
  Json root;
  try {
    root = Json::parse(text);
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
  ObjectReader r(root, "");
  if (const Json* format = r.find("format")) {
    if (!format->is_string() || format->get<std::string>() != kFormat) {
      throw SceneFileError("format",
                           std::string("expected \"") + kFormat + "\", got " + format->dump());
    }
  }
  if (const Json* version = r.find("version")) {
    if (!version->is_number_integer() || version->get<long long>() != kVersion) {
      throw SceneFileError("version", "only version " + std::to_string(kVersion) +
                                          " is known, got " + version->dump());
    }
  }
  SceneDef scene;
  if (const Json* world = r.find("world")) scene.world = read_world(*world, "world");
  const Json& bodies = require_array(r.require("bodies"), "bodies");
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    scene.bodies.push_back(read_body(bodies[i], "bodies[" + std::to_string(i) + "]"));
  }
  r.finish();
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
    throw SceneFileError(error.json_path(),
                         std::string(error.what()).substr(error.json_path().size() + 2) + " (in " +
                             path.string() + ")");
  }
}

std::string scene_to_json(const SceneDef& scene) {
  const WorldDef& w = scene.world;
  Json world = {{"gravity", vec_json(w.gravity)},
                {"time_step", w.time_step},
                {"substeps", w.substeps},
                {"contact_hertz", w.contact_hertz},
                {"contact_damping_ratio", w.contact_damping_ratio},
                {"contact_push_max_velocity", w.contact_push_max_velocity},
                {"restitution_threshold", w.restitution_threshold},
                {"linear_slop", w.linear_slop},
                {"max_linear_speed", w.max_linear_speed},
                {"enable_sleep", w.enable_sleep},
                {"time_to_sleep", w.time_to_sleep},
                {"linear_sleep_tolerance", w.linear_sleep_tolerance},
                {"angular_sleep_tolerance", w.angular_sleep_tolerance},
                {"max_steps_per_advance", w.max_steps_per_advance},
                {"simd_solver", w.simd_solver},
                {"reuse_manifolds", w.reuse_manifolds}};
  Json bodies = Json::array();
  for (const SceneBody& body : scene.bodies) {
    const BodyDef& b = body.body;
    Json shapes = Json::array();
    for (const ShapeDef& s : body.shapes) {
      Json points = Json::array();
      for (const Vec2& p : s.points) points.push_back(vec_json(p));
      Json shape = {{"points", points},
                    {"algorithm", std::string(to_string(s.algorithm))},
                    {"density", s.density},
                    {"friction", s.friction},
                    {"restitution", s.restitution}};
      if (s.scale) {
        shape["scale"] = {{"fixed_point", vec_json(s.scale->fixed_point)},
                          {"factor", vec_json(s.scale->factor)}};
      }
      shapes.push_back(std::move(shape));
    }
    bodies.push_back({{"type", std::string(to_string(b.type))},
                      {"position", vec_json(b.position)},
                      {"angle", b.angle},
                      {"linear_velocity", vec_json(b.linear_velocity)},
                      {"angular_velocity", b.angular_velocity},
                      {"linear_damping", b.linear_damping},
                      {"angular_damping", b.angular_damping},
                      {"gravity_scale", b.gravity_scale},
                      {"allow_sleep", b.allow_sleep},
                      {"awake", b.awake},
                      {"user_data", b.user_data},
                      {"shapes", std::move(shapes)}});
  }
  Json root = {{"format", kFormat}, {"version", kVersion}, {"world", world}, {"bodies", bodies}};
  return root.dump(1) + "\n";
}

void save_scene_file(const std::filesystem::path& path, const SceneDef& scene) {
  std::ofstream out = open_output_file(path, "scene file");
  out << scene_to_json(scene);
  close_output_file(out, path, "scene file");
}

SceneDef resolve_scene(const std::string& name_or_path) {
  const auto names = builtin_scene_names();
  if (std::find(names.begin(), names.end(), name_or_path) != names.end()) {
    return builtin_scene(name_or_path);
  }
  if (!std::filesystem::exists(name_or_path)) {
    std::string list;
    for (std::string_view n : names) list += (list.empty() ? "" : ", ") + std::string(n);
    throw InvalidArgumentError("'" + name_or_path + "' is neither a built-in scene (" + list +
                               ") nor a scene file");
  }
  return load_scene_file(name_or_path);
}

}  // namespace mink::cli
