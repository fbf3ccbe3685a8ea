#include "sandbox.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <utility>

#include "mink/engine/scene_file.hpp"
#include "mink/engine/shape_def.hpp"
#include "mink/geometry/point_sets.hpp"
#include "mink/render/bitmap_font.hpp"
#include "text_wrap.hpp"

namespace mink::cli {

namespace {

constexpr Real kFrameSeconds = 1.0 / 60.0;
// The dragged point closes this fraction of its gap to the cursor per second (a stiff spring
// without the spring's overshoot), capped so a fast flick does not tunnel through bodies.
constexpr Real kDragRate = 12;
constexpr Real kDragMaxSpeed = 40;

struct LayerKey {
  char key;
  DrawLayer layer;
  const char* name;
};
constexpr std::array<LayerKey, 8> kLayerKeys{{
    {'1', draw_shapes, "shapes"},
    {'2', draw_aabbs, "aabbs"},
    {'3', draw_contact_points, "contacts"},
    {'4', draw_contact_normals, "normals"},
    {'5', draw_broadphase_pairs, "pairs"},
    {'6', draw_velocities, "velocities"},
    {'7', draw_sleep_state, "sleep"},
    {'8', draw_centers_of_mass, "centres"},
}};

std::string lower(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace

Sandbox::Sandbox(Renderer& renderer, const std::string& scene)
    : Sandbox(renderer, scene, resolve_scene(scene)) {}

Sandbox::Sandbox(Renderer& renderer, std::string name, SceneDef scene)
    : renderer_(renderer), scene_(std::move(name)), scene_def_(std::move(scene)), run_(scene_def_) {
  renderer_.layers = draw_shapes | draw_contact_points;
  fit_camera();
}

void Sandbox::reset() {
  run_ = SceneRun(scene_def_);
  dragged_.reset();
  drops_ = 0;
  fit_camera();
}

void Sandbox::fit_camera() {
  // The camera shows the moving bodies (every shape when nothing moves) with room around
  // them and above for dropping hulls; it stays put afterwards so the mouse maps to the same
  // place in the world. Grounds reach past the edges.
  const World& world = run_.world();
  for (const bool moving_only : {true, false}) {
    Vec2 lower(0, 0);
    Vec2 upper(0, 0);
    bool first = true;
    for (const BodyId body : world.bodies()) {
      if (moving_only && world.body_type(body) == BodyType::static_body) continue;
      for (const ShapeId shape : world.body_shapes(body)) {
        const Aabb box = world.shape_aabb(shape);
        lower = first ? box.lower : lower.cwiseMin(box.lower);
        upper = first ? box.upper : upper.cwiseMax(box.upper);
        first = false;
      }
    }
    if (first) continue;
    const Vec2 size = (upper - lower).cwiseMax(Vec2(2, 2));
    renderer_.camera().fit(lower - Vec2(0.25 * size.x(), 0.25 * size.y()),
                           upper + Vec2(0.25 * size.x(), 0.5 * size.y()), 24);
    return;
  }
}

void Sandbox::key(std::string_view name) {
  const std::string k = lower(name);
  if (k == "space") {
    paused_ = !paused_;
  } else if (k == "s") {
    step_once_ = true;
  } else if (k == "r") {
    reset();
  } else if (k == "n") {
    const auto names = builtin_scene_names();
    // From a scene file, the first built-in.
    const auto at = std::find(names.begin(), names.end(), scene_);
    scene_ = std::string(at == names.end() || at + 1 == names.end() ? names.front() : *(at + 1));
    scene_def_ = builtin_scene(scene_);
    reset();
  } else if (k == "escape" || k == "q") {
    quit_ = true;
  } else if (k.size() == 1) {
    for (const LayerKey& layer : kLayerKeys) {
      if (layer.key == k[0]) renderer_.layers ^= layer.layer;
    }
  }
}

void Sandbox::mouse_down(const Vec2& pixel) {
  cursor_ = renderer_.camera().pixel_to_world(pixel);
  World& world = run_.world();
  for (const ShapeId shape : world.query_point(cursor_)) {
    const BodyId body = world.shape_body(shape);
    if (world.body_type(body) != BodyType::dynamic) continue;
    dragged_ = body;
    grab_local_ = world.pose(body).apply_inverse(cursor_);
    world.set_awake(body, true);
    return;
  }
  drop_hull(cursor_);
}

void Sandbox::mouse_move(const Vec2& pixel) {
  cursor_ = renderer_.camera().pixel_to_world(pixel);
}

void Sandbox::mouse_up(const Vec2& pixel) {
  mouse_move(pixel);
  dragged_.reset();
}

void Sandbox::drop_hull(const Vec2& world_point) {
  // A random convex shape about a unit across: the hull of a few points of a disk.
  ++drops_;
  BodyDef body;
  body.type = BodyType::dynamic;
  body.position = world_point;
  ShapeDef shape;
  shape.points = generate_points(PointDistribution::uniform_disk, 7, drops_);
  // Centred on the points' mean, which lies inside their hull: the body is where the click was.
  Vec2 mean(0, 0);
  for (const Vec2& p : shape.points) mean += p / static_cast<Real>(shape.points.size());
  for (Vec2& p : shape.points) p -= mean;
  World& world = run_.world();
  const BodyId id = world.create_body(body);
  world.create_shape(id, shape);
}

void Sandbox::step() {
  World& world = run_.world();
  if (dragged_ && world.is_valid(*dragged_)) {
    // Kinematic drag through the World API: each step, the grabbed point is given the
    // velocity that moves it towards the cursor; spin is damped so the body does not whirl.
    const BodyId body = *dragged_;
    const Vec2 grabbed = world.pose(body).apply(grab_local_);
    Vec2 velocity = kDragRate * (cursor_ - grabbed);
    if (velocity.norm() > kDragMaxSpeed) velocity *= kDragMaxSpeed / velocity.norm();
    world.set_linear_velocity(body, velocity);
    world.set_angular_velocity(body, 0.9 * world.angular_velocity(body));
    world.set_awake(body, true);
  }
  run_.step();
}

void Sandbox::frame() {
  if (!paused_ || step_once_) step();
  step_once_ = false;
  const World& world = run_.world();
  renderer_.begin_frame(background);
  world.draw(renderer_);
  char line[200];
  std::snprintf(
      line, sizeof line,
      "scene %s%s\nstep %llu  time %.2f s\nbodies %zu  contacts %zu\nlayers:", scene_.c_str(),
      paused_ ? "  [paused]" : "", static_cast<unsigned long long>(world.step_count()),
      world.time(), world.body_count(), world.counters().touching_contacts);
  std::string text = line;
  for (const LayerKey& layer : kLayerKeys) {
    if (renderer_.layers & layer.layer) text.append(" ").append(layer.name);
  }
  renderer_.draw_overlay(text);
  // The help line at the bottom, broken between its entries when the window is narrow.
  const int scale = renderer_.options().text_scale;
  const auto columns = static_cast<std::size_t>(
      std::max(1, (renderer_.width() - 16) / (BitmapFont::advance * scale)));
  if (columns != help_columns_) {
    wrapped_help_ = wrap(help, columns, "  ");
    help_columns_ = columns;
  }
  const Vec2 help_at(8, renderer_.height() - 8 - BitmapFont::text_height(wrapped_help_) * scale);
  renderer_.draw_screen_rect(
      help_at - Vec2(4, 4),
      Vec2(help_at.x() + BitmapFont::text_width(wrapped_help_) * scale + 4, renderer_.height() - 4),
      Color{0, 0, 0, 0.55f});
  renderer_.draw_screen_text(help_at, wrapped_help_, Color{0.9f, 0.9f, 0.6f, 1});
  renderer_.end_frame();
}

}  // namespace mink::cli
