#include "mink/engine/scene_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include "mink/engine/scene_fields.hpp"
#include "mink/engine/world.hpp"

namespace mink {
namespace {

template <class Object>
void expect_same_fields(std::span<const SceneField<Object>> fields, const Object& a,
                        const Object& b, const std::string& where) {
  for (const SceneField<Object>& field : fields) {
    if (field.applies != nullptr && !field.applies(a)) continue;
    EXPECT_TRUE(field.get(a) == field.get(b)) << where << "." << field.key;
  }
}

void expect_same_shape(const ShapeDef& a, const ShapeDef& b, const std::string& where) {
  EXPECT_EQ(a.type, b.type) << where;
  EXPECT_EQ(a.points, b.points) << where;
  EXPECT_EQ(a.radius, b.radius) << where;
  EXPECT_EQ(a.loop, b.loop) << where;
  expect_same_fields(shape_fields(), a, b, where);
  expect_same_fields(filter_fields(), a.filter, b.filter, where + ".filter");
  ASSERT_EQ(a.scale.has_value(), b.scale.has_value()) << where;
  if (a.scale) expect_same_fields(scale_fields(), *a.scale, *b.scale, where + ".scale");
}

// Every field of every table, exactly: the file keeps doubles in shortest round-trip form.
void expect_same_scene(const SceneDef& a, const SceneDef& b) {
  expect_same_fields(world_fields(), a.world, b.world, "world");
  ASSERT_EQ(a.bodies.size(), b.bodies.size());
  for (std::size_t i = 0; i < a.bodies.size(); ++i) {
    const std::string where = "bodies[" + std::to_string(i) + "]";
    expect_same_fields(body_fields(), a.bodies[i].body, b.bodies[i].body, where);
    ASSERT_EQ(a.bodies[i].shapes.size(), b.bodies[i].shapes.size()) << where;
    for (std::size_t k = 0; k < a.bodies[i].shapes.size(); ++k) {
      expect_same_shape(a.bodies[i].shapes[k], b.bodies[i].shapes[k],
                        where + ".shapes[" + std::to_string(k) + "]");
    }
  }
  // Joints, key by key: tests/engine/joint_scene_test.cpp.
  ASSERT_EQ(a.joints.size(), b.joints.size());
}

// A value of the field's kind, in its range, that is not `current`; `salt` keeps the points of
// one object apart (a capsule's two centres must differ).
template <class Object>
FieldValue other_value(const SceneField<Object>& field, const FieldValue& current, int salt) {
  switch (field.kind) {
    case FieldKind::real:
      return std::get<Real>(current) + 0.1 + 0.01 * salt;  // not a binary fraction
    case FieldKind::integer:
      return std::get<std::int64_t>(current) + 1 + salt;
    case FieldKind::boolean:
      return !std::get<bool>(current);
    case FieldKind::vec2:
      return Vec2(std::get<Vec2>(current) + Vec2(0.1 * (salt + 1), -0.3 * (salt + 1)));
    case FieldKind::points:
      return std::vector<Vec2>{Vec2(0.1, 0), Vec2(1.1, 0.3), Vec2(0.3, 1.7), Vec2(0.2, 0.4)};
    case FieldKind::bits:
      // Past 2^63, so both the unsigned range and the hex form are exercised.
      return std::get<std::uint64_t>(current) ^ 0xA000'0000'0000'0005ull;
    case FieldKind::user_data:
      return std::numeric_limits<std::uint64_t>::max() - static_cast<std::uint64_t>(salt);
    case FieldKind::name:
      for (const std::string_view name : field.names()) {
        if (name != std::get<std::string>(current)) return std::string(name);
      }
  }
  ADD_FAILURE() << field.key << ": no other value";
  return current;
}

// Sets every field that applies to `object` to a value other than its default.
template <class Object>
void set_every_field(std::span<const SceneField<Object>> fields, Object& object) {
  const Object defaults{};
  int salt = 0;
  for (const SceneField<Object>& field : fields) {
    if (field.applies != nullptr && !field.applies(object)) continue;
    const FieldValue value = other_value(field, field.get(object), salt++);
    field.set(object, value);
    EXPECT_TRUE(field.get(object) == value) << field.key;
    EXPECT_FALSE(field.get(object) == field.get(defaults)) << field.key << " kept its default";
  }
}

ShapeDef shape_with_every_field(ShapeType type, std::span<const SceneField<ShapeDef>> form) {
  ShapeDef shape;
  shape.type = type;
  set_every_field(form, shape);
  set_every_field(shape_fields(), shape);
  set_every_field(filter_fields(), shape.filter);
  if (type == ShapeType::polygon) {
    shape.scale = ShapeScale{};
    set_every_field(scale_fields(), *shape.scale);
  }
  if (type == ShapeType::chain) shape.is_sensor = false;  // a chain cannot be a sensor
  return shape;
}

TEST(SceneFile, EveryTableFieldRoundTripsWithANonDefaultValue) {
  SceneDef scene;
  set_every_field(world_fields(), scene.world);
  SceneBody body;
  set_every_field(body_fields(), body.body);
  body.shapes.push_back(shape_with_every_field(ShapeType::polygon, {}));
  for (const SceneShapeForm& form : shape_forms()) {
    body.shapes.push_back(shape_with_every_field(form.type, form.fields));
  }
  scene.bodies.push_back(body);
  scene.bodies.push_back(SceneBody{});  // and a body of defaults next to it

  const std::string text = scene_to_json(scene);
  const SceneDef loaded = parse_scene_json(text);
  expect_same_scene(scene, loaded);
  EXPECT_EQ(scene_to_json(loaded), text);
  // Each kind in its own form, never as points.
  for (const SceneShapeForm& form : shape_forms()) {
    std::string key = "\"";
    key.append(form.key).append("\": {");
    EXPECT_NE(text.find(key), std::string::npos) << form.key;
  }
}

// Big scenes (thousands of bodies) get a couple of steps only: same code, shorter test.
#ifdef MINK_SANITIZED_BUILD
constexpr int kSteps = 5;
constexpr int kBigSteps = 0;
#else
constexpr int kSteps = 30;
constexpr int kBigSteps = 2;
#endif

void expect_same_state(World& a, World& b, int steps) {
  for (int i = 0; i < steps; ++i) {
    a.step();
    b.step();
  }
  const auto ids_a = a.bodies();
  const auto ids_b = b.bodies();
  ASSERT_EQ(ids_a.size(), ids_b.size());
  ASSERT_EQ(a.shape_count(), b.shape_count());
  for (std::size_t i = 0; i < ids_a.size(); ++i) {
    ASSERT_EQ(a.position(ids_a[i]), b.position(ids_b[i])) << "body " << i;
    ASSERT_EQ(a.angle(ids_a[i]), b.angle(ids_b[i])) << "body " << i;
    ASSERT_EQ(a.linear_velocity(ids_a[i]), b.linear_velocity(ids_b[i])) << "body " << i;
    ASSERT_EQ(a.mass(ids_a[i]), b.mass(ids_b[i])) << "body " << i;
    const auto shapes_a = a.body_shapes(ids_a[i]);
    const auto shapes_b = b.body_shapes(ids_b[i]);
    ASSERT_EQ(shapes_a.size(), shapes_b.size()) << "body " << i;
    for (std::size_t k = 0; k < shapes_a.size(); ++k) {
      ASSERT_EQ(a.shape_type(shapes_a[k]), b.shape_type(shapes_b[k]));
      ASSERT_EQ(a.shape_aabb(shapes_a[k]).lower, b.shape_aabb(shapes_b[k]).lower);
      ASSERT_EQ(a.shape_aabb(shapes_a[k]).upper, b.shape_aabb(shapes_b[k]).upper);
    }
  }
}

TEST(SceneFile, EveryBuiltinRoundTripsAndSimulatesTheSame) {
  for (const std::string_view name : builtin_scene_names()) {
    SCOPED_TRACE(std::string(name));
    const SceneDef original = builtin_scene(name);
    const std::string text = scene_to_json(original);
    const SceneDef loaded = parse_scene_json(text);
    expect_same_scene(original, loaded);
    EXPECT_EQ(scene_to_json(loaded), text);
    World a = build_world(original);
    World b = build_world(loaded);
    expect_same_state(a, b, original.bodies.size() > 1000 ? kBigSteps : kSteps);
  }
}

TEST(SceneFile, SavedShapesSceneLoadsBackIdenticalAndBuildsTheSameWorld) {
  const auto file =
      std::filesystem::path(testing::TempDir()) / "mink_scene_file_test" / "shapes.json";
  const SceneDef original = builtin_scene("shapes");
  save_scene_file(file, original);
  const SceneDef loaded = load_scene_file(file);
  expect_same_scene(original, loaded);
  std::size_t chains = 0;
  for (const SceneBody& body : loaded.bodies) {
    for (const ShapeDef& shape : body.shapes) chains += shape.type == ShapeType::chain;
  }
  EXPECT_EQ(chains, 1u);
  World from_file = build_world(loaded);
  World builtin = build_world(builtin_scene("shapes"));
  expect_same_state(from_file, builtin, 120);
}

TEST(SceneFile, HelpersDefaultsAndTheFilterForms) {
  const SceneDef scene = parse_scene_json(R"({
    "world": {"gravity": [0, -9.8]},
    "bodies": [
      {"type": "static", "shapes": [{"box": {"half_extents": [5, 0.5]}, "radius": 0.1}]},
      {"type": "dynamic", "position": [1, 2], "angle": 0.5, "linear_velocity": [3, 0],
       "shapes": [{"polygon": {"count": 6, "radius": 0.5}, "friction": 0.2},
                  {"points": [[0, 0], [1, 0], [0, 1], [0.2, 0.2]], "density": 2},
                  {"circle": {"radius": 0.25}, "filter": {"category": "0xFFFF",
                   "mask": 18446744073709551615, "group": -2147483648}},
                  {"segment": {"point1": [0, 0], "point2": [1, 0]},
                   "filter": {"category": "0x8000000000000000", "mask": 0}}]}
    ]})");
  ASSERT_EQ(scene.bodies.size(), 2u);
  EXPECT_EQ(scene.world.gravity, Vec2(0, -9.8));
  EXPECT_EQ(scene.world.substeps, WorldDef{}.substeps);
  EXPECT_EQ(scene.bodies[0].shapes[0].points, ShapeDef::box(5, 0.5).points);
  EXPECT_EQ(scene.bodies[0].shapes[0].radius, 0.1);
  const SceneBody& body = scene.bodies[1];
  EXPECT_EQ(body.body.type, BodyType::dynamic);
  EXPECT_EQ(body.body.angle, 0.5);
  EXPECT_EQ(body.body.linear_velocity, Vec2(3, 0));
  EXPECT_EQ(body.shapes[0].points, ShapeDef::regular_polygon(6, 0.5).points);
  EXPECT_EQ(body.shapes[0].radius, 0);
  EXPECT_EQ(body.shapes[0].friction, 0.2);
  EXPECT_EQ(body.shapes[1].density, 2);
  EXPECT_EQ(body.shapes[2].type, ShapeType::circle);
  EXPECT_EQ(body.shapes[2].points, std::vector<Vec2>{Vec2(0, 0)});
  EXPECT_EQ(body.shapes[2].filter.category, 0xFFFFu);
  EXPECT_EQ(body.shapes[2].filter.mask, std::numeric_limits<std::uint64_t>::max());
  EXPECT_EQ(body.shapes[2].filter.group, std::numeric_limits<std::int32_t>::min());
  EXPECT_EQ(body.shapes[3].filter.category, 0x8000'0000'0000'0000ull);
  EXPECT_EQ(body.shapes[3].filter.mask, 0u);
  EXPECT_EQ(body.shapes[3].filter.group, 0);
}

struct BadScene {
  std::string name;
  std::string json;
  std::string path;     // the path the message starts with
  std::string problem;  // expected in the message
};

// A one-shape scene with `shape` as its shape.
std::string one_shape(const std::string& shape) {
  return R"({"bodies": [{"type": "dynamic", "shapes": [)" + shape + "]}]}";
}

const std::string kShape = "bodies[0].shapes[0]";

TEST(SceneFile, EveryBadValueGetsItsPathAndProblem) {
  const std::string circle = R"("circle": {"radius": 1})";
  const BadScene cases[] = {
      {"missing_bodies", R"({"world": {}})", "bodies", "missing field"},
      {"missing_type", R"({"bodies": [{"shapes": []}]})", "bodies[0].type", "missing field"},
      {"missing_shape_form", R"({"bodies": [{"type": "dynamic", "shapes": [{"density": 1}]}]})",
       "bodies[0].shapes[0]", "missing field: one of points, box, polygon, circle"},
      {"two_shape_forms", R"({"bodies": [{"type": "dynamic", "shapes": [
         {"circle": {"radius": 1}, "points": [[0, 0], [1, 0], [0, 1]]}]}]})",
       "bodies[0].shapes[0]", "give only one of"},
      {"missing_half_extents", R"({"bodies": [{"type": "static", "shapes": [{"box": {}}]}]})",
       "bodies[0].shapes[0].box.half_extents", "missing field"},
      {"zero_half_extent",
       R"({"bodies": [{"type": "static", "shapes": [{"box": {"half_extents": [1, 0]}}]}]})",
       "bodies[0].shapes[0].box.half_extents[1]", "must be > 0, got 0"},
      {"polygon_count", R"({"bodies": [{"type": "static", "shapes": [
         {"polygon": {"count": 2, "radius": 1}}]}]})",
       "bodies[0].shapes[0].polygon.count", "must be in 3..1000000, got 2"},
      {"wrong_type_number", R"({"bodies": [{"type": "dynamic", "angle": "0.5", "shapes": []}]})",
       "bodies[0].angle", "expected a number, got a string"},
      {"wrong_type_point",
       R"({"bodies": [{"type": "dynamic", "shapes": [{"points": [[0,0],[1,0],[0,1],[1,"a"]]}]}]})",
       "bodies[0].shapes[0].points[3][1]", "expected a number"},
      {"wrong_type_body", R"({"bodies": [{"type": "dynamic", "shapes": []}, 7]})", "bodies[1]",
       "expected an object"},
      {"bad_body_type", R"({"bodies": [{"type": "wobbly", "shapes": []}]})", "bodies[0].type",
       R"(expected "static", "kinematic" or "dynamic", got "wobbly")"},
      {"nan_coordinate",
       R"({"bodies": [{"type": "dynamic", "shapes": [{"points": [[0,0],[1,0],[0,1e999]]}]}]})",
       "bodies[0].shapes[0].points[2][1]", "not a finite number"},
      {"nan_gravity", R"({"world": {"gravity": [0, -1e999]}, "bodies": []})", "world.gravity[1]",
       "not a finite number"},
      {"degenerate_hull", R"({"bodies": [{"type": "static", "shapes": []}, {"type": "dynamic",
         "shapes": [{"points": [[0,0],[1,1],[2,2],[3,3]]}]}]})",
       "bodies[1].shapes[0].points", "degenerate hull"},
      {"unknown_key", R"({"bodies": [{"type": "dynamic", "shapes": [], "velocity": [1, 0]}]})",
       "bodies[0].velocity", "unknown key"},
      {"unknown_top_key", R"({"bodies": [], "gravity": [0, -10]})", "gravity", "unknown key"},
      {"bad_time_step", R"({"world": {"time_step": -1}, "bodies": []})", "world.time_step",
       "must be > 0, got -1"},
      {"bad_substeps", R"({"world": {"substeps": 0}, "bodies": []})", "world.substeps",
       "must be in 1..1000, got 0"},
      {"bad_hit_event_threshold", R"({"world": {"hit_event_threshold": -0.5}, "bodies": []})",
       "world.hit_event_threshold", "must be >= 0, got -0.5"},
      {"negative_density",
       R"({"bodies": [{"type": "dynamic", "shapes": [{"box": {"half_extents": [1, 1]},
          "density": -1}]}]})",
       "bodies[0].shapes[0].density", "must be >= 0, got -1"},
      {"not_json", R"({"bodies": [)", "file.json", "not valid JSON"},
      {"body_bullet", R"({"bodies": [{"type": "dynamic", "bullet": 1, "shapes": []}]})",
       "bodies[0].bullet", "expected true or false, got a number"},
      {"body_fixed_rotation",
       R"({"bodies": [{"type": "dynamic", "fixed_rotation": "yes", "shapes": []}]})",
       "bodies[0].fixed_rotation", "expected true or false, got a string"},
      {"body_enabled", R"({"bodies": [{"type": "dynamic", "enabled": null, "shapes": []}]})",
       "bodies[0].enabled", "expected true or false, got null"},
      {"body_user_data", R"({"bodies": [{"type": "dynamic", "user_data": -1, "shapes": []}]})",
       "bodies[0].user_data", "expected an integer in 0..18446744073709551615, got -1"},
  };
  const std::string shape = kShape;
  const BadScene shape_cases[] = {
      {"circle_missing_radius", R"({"circle": {"center": [0, 0]}})", "circle.radius",
       "missing field"},
      {"circle_zero_radius", R"({"circle": {"radius": 0}})", "circle.radius", "must be > 0, got 0"},
      {"circle_center", R"({"circle": {"radius": 1, "center": [0]}})", "circle.center",
       "expected [x, y], got an array of 1"},
      {"circle_unknown", R"({"circle": {"radius": 1, "centre": [0, 0]}})", "circle.centre",
       "unknown key"},
      {"capsule_missing_center2", R"({"capsule": {"center1": [0, 0], "radius": 1}})",
       "capsule.center2", "missing field"},
      {"capsule_same_centers",
       R"({"capsule": {"center1": [1, 2], "center2": [1, 2], "radius": 1}})", "capsule",
       "must differ"},
      {"capsule_negative_radius",
       R"({"capsule": {"center1": [0, 0], "center2": [1, 0], "radius": -1}})", "capsule.radius",
       "must be > 0, got -1"},
      {"segment_missing_point2", R"({"segment": {"point1": [0, 0]}})", "segment.point2",
       "missing field"},
      {"segment_radius", R"({"segment": {"point1": [0, 0], "point2": [1, 0]}, "radius": 1})",
       "radius", "only allowed on polygon shapes"},
      {"chain_one_point", R"({"chain": {"points": [[0, 0]]}})", "chain", "at least 2"},
      {"chain_loop_two_points", R"({"chain": {"points": [[0, 0], [1, 0]], "loop": true}})", "chain",
       "at least 3"},
      {"chain_loop_type", R"({"chain": {"points": [[0, 0], [1, 0]], "loop": 1}})", "chain.loop",
       "expected true or false"},
      {"chain_point", R"({"chain": {"points": [[0, 0], [1, "x"]]}})", "chain.points[1][1]",
       "expected a number"},
      {"chain_sensor", R"({"chain": {"points": [[0, 0], [1, 0]]}, "sensor": true})", "chain",
       "sensor"},
      {"rounding_negative", R"({"box": {"half_extents": [1, 1]}, "radius": -0.1})", "radius",
       "must be >= 0, got -0.1"},
      {"rounding_on_circle", R"({"circle": {"radius": 1}, "radius": 0.1})", "radius",
       "only allowed on polygon shapes"},
      {"algorithm_on_circle", R"({"circle": {"radius": 1}, "algorithm": "chan"})", "algorithm",
       "only allowed on polygon shapes"},
      {"bad_algorithm", R"({"points": [[0, 0], [1, 0], [0, 1]], "algorithm": "quick"})",
       "algorithm", R"(expected "chan", "divide-conquer")"},
      {"scale_on_capsule",
       R"({"capsule": {"center1": [0, 0], "center2": [1, 0], "radius": 1}, "scale": {}})", "scale",
       "only allowed on polygon shapes"},
      {"scale_unknown", R"({"box": {"half_extents": [1, 1]}, "scale": {"factors": [1, 1]}})",
       "scale.factors", "unknown key"},
      {"sensor_type", R"({)" + circle + R"(, "sensor": "yes"})", "sensor",
       "expected true or false, got a string"},
      {"contact_events_type", R"({)" + circle + R"(, "contact_events": 0})", "contact_events",
       "expected true or false"},
      {"sensor_events_type", R"({)" + circle + R"(, "sensor_events": [true]})", "sensor_events",
       "expected true or false, got an array"},
      {"hit_events_type", R"({)" + circle + R"(, "hit_events": {}})", "hit_events",
       "expected true or false, got an object"},
      {"shape_user_data", R"({)" + circle + R"(, "user_data": 1.5})", "user_data",
       "expected an integer in 0..18446744073709551615, got 1.5"},
      {"filter_not_object", R"({)" + circle + R"(, "filter": 3})", "filter",
       "expected an object, got a number"},
      {"filter_negative_category", R"({)" + circle + R"(, "filter": {"category": -1}})",
       "filter.category", R"(or a hex string like "0xFFFF", got -1)"},
      {"filter_category_past_64_bits",
       R"({)" + circle + R"(, "filter": {"category": 18446744073709551616}})", "filter.category",
       "expected an integer in 0..18446744073709551615"},
      {"filter_bad_hex", R"({)" + circle + R"(, "filter": {"mask": "0xFFZZ"}})", "filter.mask",
       R"(expected a hex string of 1 to 16 digits like "0xFFFF", got "0xFFZZ")"},
      {"filter_hex_too_long", R"({)" + circle + R"(, "filter": {"mask": "0x1FFFFFFFFFFFFFFFF"}})",
       "filter.mask", "expected a hex string of 1 to 16 digits"},
      {"filter_hex_no_prefix", R"({)" + circle + R"(, "filter": {"mask": "FFFF"}})", "filter.mask",
       "expected a hex string"},
      {"filter_group_too_big", R"({)" + circle + R"(, "filter": {"group": 2147483648}})",
       "filter.group", "must be in -2147483648..2147483647, got 2147483648"},
      {"filter_group_fraction", R"({)" + circle + R"(, "filter": {"group": 0.5}})", "filter.group",
       "expected an integer, got a number"},
      {"filter_unknown", R"({)" + circle + R"(, "filter": {"categories": 1}})", "filter.categories",
       "unknown key"},
  };
  const auto expect_refused = [](const std::string& json, const std::string& path,
                                 const std::string& problem) {
    try {
      (void)parse_scene_json(json, "file.json");
      ADD_FAILURE() << "accepted";
    } catch (const SceneFileError& error) {
      const std::string message = error.what();
      EXPECT_EQ(error.json_path(), path) << message;
      EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
      EXPECT_NE(message.find(problem), std::string::npos) << message;
    }
  };
  for (const BadScene& bad : cases) {
    SCOPED_TRACE(bad.name);
    expect_refused(bad.json, bad.path, bad.problem);
  }
  for (const BadScene& bad : shape_cases) {
    SCOPED_TRACE(bad.name);
    expect_refused(one_shape(bad.json), shape + "." + bad.path, bad.problem);
  }
}

TEST(SceneFile, LoadNamesTheFileAndResolveKnowsBuiltins) {
  const auto dir = std::filesystem::path(testing::TempDir()) / "mink_scene_file_test";
  std::filesystem::create_directories(dir);
  const auto file = dir / "bad.json";
  {
    std::ofstream out(file);
    out << one_shape(R"({"circle": {"radius": 0}})");
  }
  try {
    (void)load_scene_file(file);
    ADD_FAILURE() << "accepted";
  } catch (const SceneFileError& error) {
    EXPECT_EQ(error.json_path(), kShape + ".circle.radius");
    EXPECT_NE(std::string(error.what()).find("(in " + file.string() + ")"), std::string::npos);
  }
  EXPECT_THROW((void)load_scene_file(dir / "missing.json"), InvalidArgumentError);
  EXPECT_EQ(resolve_scene("shapes").bodies.size(), builtin_scene("shapes").bodies.size());
  EXPECT_THROW((void)resolve_scene("no_such_scene"), InvalidArgumentError);
}

}  // namespace
}  // namespace mink
