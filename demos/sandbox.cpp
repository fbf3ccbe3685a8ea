#include "sandbox.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <utility>
#include <vector>

#include "mink/engine/joint_def.hpp"
#include "mink/engine/scene_file.hpp"
#include "mink/engine/shape_def.hpp"
#include "mink/geometry/point_sets.hpp"
#include "mink/render/bitmap_font.hpp"
#include "text_wrap.hpp"

namespace mink::cli {

namespace {

// The drag's motor joint accelerates the grabbed body at up to kDragLift g: enough to carry
// it anywhere on screen in a fraction of a second, while a flick over d metres reaches only
// about sqrt(kDragLift g d) m/s (14 m/s over 1 m), so the body does not tunnel through others
// and what it hits is pushed, not blown apart. The force is capped at what kHeavyBodies
// typical bodies (the median dynamic mass) would get, so heavy bodies resist: one
// kDragLift * kHeavyBodies = 100 typical masses heavy can just be held up, a heavier one not
// even that (a force proportional to the mass alone would drag every body alike).
constexpr Real kDragLift = 20;
constexpr Real kHeavyBodies = 5;
// The unit of those forces where the world has no gravity, m/s^2.
constexpr Real kUnitGravity = 10;

struct LayerKey {
  char key;
  DrawLayer layer;
  const char* name;
};
constexpr std::array<LayerKey, 9> kLayerKeys{{
    {'1', draw_shapes, "shapes"},
    {'2', draw_aabbs, "aabbs"},
    {'3', draw_contact_points, "contacts"},
    {'4', draw_contact_normals, "normals"},
    {'5', draw_broadphase_pairs, "pairs"},
    {'6', draw_velocities, "velocities"},
    {'7', draw_sleep_state, "sleep"},
    {'8', draw_centers_of_mass, "centres"},
    {'9', draw_joints, "joints"},
}};

std::string lower(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// The median mass of the world's dynamic bodies (there is at least the one being grabbed).
Real typical_mass(const World& world) {
  std::vector<Real> masses;
  for (const BodyId body : world.bodies()) {
    if (world.body_type(body) == BodyType::dynamic) masses.push_back(world.mass(body));
  }
  const auto middle = masses.begin() + static_cast<std::ptrdiff_t>(masses.size() / 2);
  std::nth_element(masses.begin(), middle, masses.end());
  return *middle;
}

// The body under `point`: a dynamic one first, else a static or kinematic one.
std::optional<BodyId> body_at(const World& world, const Vec2& point) {
  std::optional<BodyId> found;
  for (const ShapeId shape : world.query_point(point)) {
    const BodyId body = world.shape_body(shape);
    if (world.body_type(body) == BodyType::dynamic) return body;
    if (!found) found = body;
  }
  return found;
}

}  // namespace

Sandbox::Sandbox(Renderer& renderer, const std::string& scene)
    : Sandbox(renderer, scene, resolve_scene(scene)) {}

Sandbox::Sandbox(Renderer& renderer, std::string name, SceneDef scene)
    : renderer_(renderer),
      scene_(std::move(name)),
      scene_def_(std::move(scene)),
      run_(scene_def_),
      start_(run_.snapshot()) {
  renderer_.layers = draw_shapes | draw_contact_points | draw_joints;
  start_afresh();
}

Sandbox::~Sandbox() = default;

void Sandbox::record_to(std::filesystem::path file) {
  finish_recording();
  record_file_ = std::move(file);
  recorder_ = std::make_unique<RunRecorder>(run_.world());
}

std::optional<std::size_t> Sandbox::finish_recording() {
  if (!recorder_) return std::nullopt;
  const std::unique_ptr<RunRecorder> recorder = std::move(recorder_);
  save_recording(record_file_, recorder->recording());
  return recorder->steps();
}

void Sandbox::reset() {
  // Rolled back rather than rebuilt, so the world (and a recording of it) goes on.
  run_.restore(start_);
  start_afresh();
}

void Sandbox::load_scene() {
  const bool recorded = finish_recording().has_value();
  run_ = SceneRun(scene_def_);
  start_ = run_.snapshot();
  start_afresh();
  if (recorded) joint_message_ = "recording written to " + record_file_.string();
}

void Sandbox::start_afresh() {
  // What was made after the start means nothing now.
  world_anchor_.reset();
  drag_.reset();
  joint_first_.reset();
  joint_message_.clear();
  drops_ = 0;
  history_.clear();
  fit_camera();
}

void Sandbox::step_back() {
  release();
  const std::uint64_t now = run_.world().step_count();
  while (!history_.empty() && history_.back().step >= now) history_.pop_back();
  if (history_.empty()) {
    joint_message_ = "nothing kept to step back to";
    return;
  }
  // Kept, not dropped: stepping on from it keeps new moments after it.
  run_.restore(history_.back().snapshot);
  // A drag under way when that moment was kept has ended since: its motor joint goes, or it
  // would hold the body at that moment's cursor.
  const std::optional<JointId> kept_drag = history_.back().drag_joint;
  if (kept_drag && run_.world().is_valid(*kept_drag)) run_.world().destroy_joint(*kept_drag);
  // Ids of what was made after that moment are stale now.
  if (world_anchor_ && !run_.world().is_valid(*world_anchor_)) world_anchor_.reset();
  if (joint_first_ && !run_.world().is_valid(*joint_first_)) joint_first_.reset();
  joint_message_ = "stepped back to step " + std::to_string(history_.back().step);
}

void Sandbox::fit_camera() {
  // The camera shows the moving bodies (every shape when nothing moves) with room around
  // them and above for dropping hulls; it stays put afterwards so the mouse maps to the same
  // place in the world. Grounds reach past the edges.
  for (const bool moving_only : {true, false}) {
    Vec2 lower(0, 0);
    Vec2 upper(0, 0);
    bool first = true;
    for (const BodyId body : run_.world().bodies()) {
      if (moving_only && run_.world().body_type(body) == BodyType::static_body) continue;
      for (const ShapeId shape : run_.world().body_shapes(body)) {
        const Aabb box = run_.world().shape_aabb(shape);
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
  } else if (k == "b") {
    step_back();
  } else if (k == "n") {
    const auto names = builtin_scene_names();
    // From a scene file, the first built-in.
    const auto at = std::find(names.begin(), names.end(), scene_);
    scene_ = std::string(at == names.end() || at + 1 == names.end() ? names.front() : *(at + 1));
    scene_def_ = builtin_scene(scene_);
    load_scene();
  } else if (k == "j") {
    release();
    joint_mode_ = !joint_mode_;
    joint_first_.reset();
    joint_message_.clear();
  } else if (k == "escape" || k == "q") {
    quit_ = true;
  } else if (k.size() == 1) {
    for (const LayerKey& layer : kLayerKeys) {
      if (layer.key == k[0]) renderer_.layers ^= layer.layer;
    }
  }
}

std::optional<BodyId> Sandbox::dragged() const {
  if (!drag_) return std::nullopt;
  return drag_->body;
}

std::optional<JointId> Sandbox::drag_joint() const {
  if (!drag_) return std::nullopt;
  return drag_->joint;
}

void Sandbox::mouse_down(const Vec2& pixel) {
  cursor_ = renderer_.camera().pixel_to_world(pixel);
  if (joint_mode_) {
    pick_joint_body(cursor_);
    return;
  }
  release();  // a press whose release the window never delivered
  const std::optional<BodyId> body = body_at(run_.world(), cursor_);
  if (body && run_.world().body_type(*body) == BodyType::dynamic) {
    grab(*body);
  } else {
    drop_hull(cursor_);
  }
}

void Sandbox::mouse_move(const Vec2& pixel) {
  cursor_ = renderer_.camera().pixel_to_world(pixel);
}

void Sandbox::mouse_up(const Vec2& pixel) {
  mouse_move(pixel);
  release();
}

BodyId Sandbox::world_anchor() {
  if (!world_anchor_) {
    BodyDef anchor;
    anchor.type = BodyType::static_body;
    world_anchor_ = run_.world().create_body(anchor);
  }
  return *world_anchor_;
}

void Sandbox::grab(BodyId body) {
  // The motor joint drives B's origin and angle, not a point of B. Holding the angle the body
  // had when grabbed and aiming the origin where that angle puts the grabbed point under the
  // cursor makes the grabbed point follow the cursor (rather than the centre), as a firm grip
  // would. The anchor sits at the origin unrotated, so offsets in its frame are world ones.
  const Pose pose = run_.world().pose(body);
  const Real mass = run_.world().mass(body);
  const Real gravity = run_.world().def().gravity.norm();
  MotorJointDef def;
  def.body_a = world_anchor();
  def.body_b = body;
  def.linear_offset = pose.position;
  def.angular_offset = run_.world().angle(body);
  def.max_force = kDragLift * (gravity > 0 ? gravity : kUnitGravity) *
                  std::min(mass, kHeavyBodies * typical_mass(run_.world()));
  // The same bound on the acceleration of a point at the body's radius of gyration.
  def.max_torque = def.max_force * std::sqrt(run_.world().rotational_inertia(body) / mass);
  drag_ =
      Drag{body, run_.world().create_joint(def), pose.apply_inverse(cursor_), def.angular_offset};
}

void Sandbox::release() {
  if (!drag_) return;
  if (run_.world().is_valid(drag_->joint)) run_.world().destroy_joint(drag_->joint);
  drag_.reset();
}

void Sandbox::pick_joint_body(const Vec2& world_point) {
  const std::optional<BodyId> hit = body_at(run_.world(), world_point);
  const BodyId body = hit ? *hit : world_anchor();
  if (!joint_first_) {
    joint_first_ = body;
    joint_message_.clear();
    return;
  }
  const BodyId first = *joint_first_;
  joint_first_.reset();
  if (first == body) {
    joint_message_ = "A and B are the same body: no joint";
  } else if (run_.world().body_type(first) != BodyType::dynamic &&
             run_.world().body_type(body) != BodyType::dynamic) {
    joint_message_ = "neither A nor B moves: no joint";
  } else {
    run_.world().create_joint(revolute_joint_at(run_.world(), first, body, world_point));
    joint_message_ = "revolute joint made";
  }
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
  const BodyId id = run_.world().create_body(body);
  run_.world().create_shape(id, shape);
}

void Sandbox::step() {
  if (drag_ && run_.world().is_valid(drag_->joint)) {
    const Vec2 origin = cursor_ - Rotation::from_angle(drag_->angle).apply(drag_->grab_local);
    run_.world().set_motor_target(drag_->joint, origin, drag_->angle);
    // A body resting at the target would fall asleep and not notice the cursor move on.
    run_.world().set_awake(drag_->body, true);
  }
  run_.step();
  const std::uint64_t now = run_.world().step_count();
  if (now % kKeepEvery == 0) {
    history_.push_back({now, run_.snapshot(), drag_ ? std::optional(drag_->joint) : std::nullopt});
    if (history_.size() > kKeptCount) history_.pop_front();
  }
}

void Sandbox::frame() {
  if (!paused_ || step_once_) step();
  step_once_ = false;
  renderer_.begin_frame(background);
  run_.world().draw(renderer_);
  char line[200];
  std::snprintf(line, sizeof line,
                "scene %s%s\nstep %llu  time %.2f s\nbodies %zu  contacts %zu  joints %zu\nlayers:",
                scene_.c_str(), paused_ ? "  [paused]" : "",
                static_cast<unsigned long long>(run_.world().step_count()), run_.world().time(),
                run_.world().body_count(), run_.world().counters().touching_contacts,
                run_.world().joint_count());
  std::string text = line;
  for (const LayerKey& layer : kLayerKeys) {
    if (renderer_.layers & layer.layer) text.append(" ").append(layer.name);
  }
  if (joint_mode_) {
    text += joint_first_ ? "\njoint mode: click body B (the joint goes there)"
                         : "\njoint mode: click body A (empty space: the world)";
    if (!joint_message_.empty()) text.append("\n").append(joint_message_);
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
