// The recorder hook and its other half: World::replay_call runs a call as the hook saw it.

#include <tuple>
#include <vector>

#include "mink/byte_stream.hpp"
#include "mink/engine/world.hpp"
#include "record_scope.hpp"
#include "world_state.hpp"

namespace mink {

namespace {

template <typename T>
T read(LoadArchive& archive) {
  T value{};
  archive(value);
  return value;
}

// Reads the arguments in order (a braced list is evaluated left to right), checks that they
// are all the bytes hold, then makes the call.
template <typename... Args, typename Call>
void replay(LoadArchive& archive, Call&& call) {
  std::tuple<Args...> args{read<Args>(archive)...};
  if (archive.in.remaining() != 0) archive.in.fail("a recorded call longer than its arguments");
  std::apply(call, args);
}

}  // namespace

void World::set_recorder(Recorder* recorder) noexcept {
  state_->recorder = recorder;
}

void World::replay_call(std::span<const std::uint8_t> encoded) {
  ByteReader in(encoded);
  LoadArchive a{in, state_->serial};
  const auto call = static_cast<detail::Call>(read<std::uint8_t>(a));
  using C = detail::Call;
  switch (call) {
    case C::create_body:
      return replay<BodyDef>(a, [&](const BodyDef& d) { create_body(d); });
    case C::destroy_body:
      return replay<BodyId>(a, [&](BodyId id) { destroy_body(id); });
    case C::create_shape:
      return replay<BodyId, ShapeDef>(a, [&](BodyId b, const ShapeDef& d) { create_shape(b, d); });
    case C::create_chain:
      return replay<BodyId, ShapeDef>(a, [&](BodyId b, const ShapeDef& d) { create_chain(b, d); });
    case C::destroy_shape:
      return replay<ShapeId>(a, [&](ShapeId id) { destroy_shape(id); });
    case C::set_gravity:
      return replay<Vec2>(a, [&](const Vec2& g) { set_gravity(g); });
    case C::enable_sleep:
      return replay<bool>(a, [&](bool on) { enable_sleep(on); });
    case C::set_transform:
      return replay<BodyId, Vec2, Real>(
          a, [&](BodyId id, const Vec2& p, Real angle) { set_transform(id, p, angle); });
    case C::set_linear_velocity:
      return replay<BodyId, Vec2>(a, [&](BodyId id, const Vec2& v) { set_linear_velocity(id, v); });
    case C::set_angular_velocity:
      return replay<BodyId, Real>(a, [&](BodyId id, Real w) { set_angular_velocity(id, w); });
    case C::apply_force:
      return replay<BodyId, Vec2, Vec2>(
          a, [&](BodyId id, const Vec2& f, const Vec2& p) { apply_force(id, f, p); });
    case C::apply_torque:
      return replay<BodyId, Real>(a, [&](BodyId id, Real t) { apply_torque(id, t); });
    case C::apply_linear_impulse:
      return replay<BodyId, Vec2, Vec2>(
          a, [&](BodyId id, const Vec2& i, const Vec2& p) { apply_linear_impulse(id, i, p); });
    case C::set_awake:
      return replay<BodyId, bool>(a, [&](BodyId id, bool on) { set_awake(id, on); });
    case C::set_body_type:
      return replay<BodyId, BodyType>(a, [&](BodyId id, BodyType t) { set_body_type(id, t); });
    case C::set_enabled:
      return replay<BodyId, bool>(a, [&](BodyId id, bool on) { set_enabled(id, on); });
    case C::set_fixed_rotation:
      return replay<BodyId, bool>(a, [&](BodyId id, bool on) { set_fixed_rotation(id, on); });
    case C::set_bullet:
      return replay<BodyId, bool>(a, [&](BodyId id, bool on) { set_bullet(id, on); });
    case C::set_continuous_threshold:
      return replay<BodyId, Real>(a, [&](BodyId id, Real t) { set_continuous_threshold(id, t); });
    case C::set_target_transform:
      return replay<BodyId, Vec2, Real, Real>(a,
                                              [&](BodyId id, const Vec2& p, Real angle, Real dt) {
                                                set_target_transform(id, p, angle, dt);
                                              });
    case C::set_mass_data:
      return replay<BodyId, MassData>(a,
                                      [&](BodyId id, const MassData& m) { set_mass_data(id, m); });
    case C::set_shape_density:
      return replay<ShapeId, Real>(a, [&](ShapeId id, Real v) { set_shape_density(id, v); });
    case C::set_shape_friction:
      return replay<ShapeId, Real>(a, [&](ShapeId id, Real v) { set_shape_friction(id, v); });
    case C::set_shape_restitution:
      return replay<ShapeId, Real>(a, [&](ShapeId id, Real v) { set_shape_restitution(id, v); });
    case C::set_shape_filter:
      return replay<ShapeId, Filter>(a,
                                     [&](ShapeId id, const Filter& f) { set_shape_filter(id, f); });
    case C::create_joint:
      return replay<JointDef>(a, [&](const JointDef& d) { create_joint(d); });
    case C::destroy_joint:
      return replay<JointId>(a, [&](JointId id) { destroy_joint(id); });
    case C::set_joint_motor:
      return replay<JointId, JointMotor>(
          a, [&](JointId id, const JointMotor& m) { set_joint_motor(id, m); });
    case C::set_joint_spring:
      return replay<JointId, JointSpring>(
          a, [&](JointId id, const JointSpring& s) { set_joint_spring(id, s); });
    case C::set_joint_limit:
      return replay<JointId, JointLimit>(
          a, [&](JointId id, const JointLimit& l) { set_joint_limit(id, l); });
    case C::set_distance_length:
      return replay<JointId, Real>(a, [&](JointId id, Real l) { set_distance_length(id, l); });
    case C::set_motor_target:
      return replay<JointId, Vec2, Real>(
          a, [&](JointId id, const Vec2& o, Real angle) { set_motor_target(id, o, angle); });
    case C::set_motor_limits:
      return replay<JointId, Real, Real>(
          a, [&](JointId id, Real f, Real t) { set_motor_limits(id, f, t); });
    case C::set_weld_springs:
      return replay<JointId, Real, Real, Real, Real>(
          a, [&](JointId id, Real lh, Real ld, Real ah, Real ad) {
            set_weld_springs(id, lh, ld, ah, ad);
          });
    case C::set_joint_break:
      return replay<JointId, Real, Real>(
          a, [&](JointId id, Real f, Real t) { set_joint_break(id, f, t); });
    case C::step:
      return replay<>(a, [&] { step(); });
    case C::step_with:
      return replay<Real, int>(a, [&](Real dt, int substeps) { step(dt, substeps); });
    case C::advance:
      return replay<Real>(a, [&](Real seconds) { advance(seconds); });
    case C::restore:
      return replay<std::vector<std::uint8_t>>(
          a, [&](const std::vector<std::uint8_t>& bytes) { restore(bytes); });
    case C::count:
      break;
  }
  in.fail("recorded call kind " + std::to_string(static_cast<int>(call)) + " is unknown");
}

}  // namespace mink
