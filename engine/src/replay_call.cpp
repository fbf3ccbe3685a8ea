// The recorder hook and its other half: World::replay_call runs a call as the hook saw it.

#include <tuple>
#include <type_traits>
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

// Reads the arguments of `member` in order (a braced list is evaluated left to right), checks
// that they are all the bytes hold, then calls it on `world`.
template <typename Result, typename... Params>
void replay(World& world, LoadArchive& archive, Result (World::*member)(Params...)) {
  std::tuple<std::decay_t<Params>...> args{read<std::decay_t<Params>>(archive)...};
  if (archive.in.remaining() != 0) archive.in.fail("a recorded call longer than its arguments");
  std::apply([&](const auto&... arg) { (void)(world.*member)(arg...); }, args);
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
      return replay(*this, a, &World::create_body);
    case C::destroy_body:
      return replay(*this, a, &World::destroy_body);
    case C::create_shape:
      return replay(*this, a, &World::create_shape);
    case C::create_chain:
      return replay(*this, a, &World::create_chain);
    case C::destroy_shape:
      return replay(*this, a, &World::destroy_shape);
    case C::set_gravity:
      return replay(*this, a, &World::set_gravity);
    case C::enable_sleep:
      return replay(*this, a, &World::enable_sleep);
    case C::set_transform:
      return replay(*this, a, &World::set_transform);
    case C::set_linear_velocity:
      return replay(*this, a, &World::set_linear_velocity);
    case C::set_angular_velocity:
      return replay(*this, a, &World::set_angular_velocity);
    case C::apply_force:
      return replay(*this, a, &World::apply_force);
    case C::apply_torque:
      return replay(*this, a, &World::apply_torque);
    case C::apply_linear_impulse:
      return replay(*this, a, &World::apply_linear_impulse);
    case C::set_awake:
      return replay(*this, a, &World::set_awake);
    case C::set_body_type:
      return replay(*this, a, &World::set_body_type);
    case C::set_enabled:
      return replay(*this, a, &World::set_enabled);
    case C::set_fixed_rotation:
      return replay(*this, a, &World::set_fixed_rotation);
    case C::set_bullet:
      return replay(*this, a, &World::set_bullet);
    case C::set_continuous_threshold:
      return replay(*this, a, &World::set_continuous_threshold);
    case C::set_target_transform:
      return replay(*this, a, &World::set_target_transform);
    case C::set_mass_data:
      return replay(*this, a, &World::set_mass_data);
    case C::set_shape_density:
      return replay(*this, a, &World::set_shape_density);
    case C::set_shape_friction:
      return replay(*this, a, &World::set_shape_friction);
    case C::set_shape_restitution:
      return replay(*this, a, &World::set_shape_restitution);
    case C::set_shape_filter:
      return replay(*this, a, &World::set_shape_filter);
    case C::create_joint:
      return replay(*this, a, &World::create_joint);
    case C::destroy_joint:
      return replay(*this, a, &World::destroy_joint);
    case C::set_joint_motor:
      return replay(*this, a, &World::set_joint_motor);
    case C::set_joint_spring:
      return replay(*this, a, &World::set_joint_spring);
    case C::set_joint_limit:
      return replay(*this, a, &World::set_joint_limit);
    case C::set_distance_length:
      return replay(*this, a, &World::set_distance_length);
    case C::set_motor_target:
      return replay(*this, a, &World::set_motor_target);
    case C::set_motor_limits:
      return replay(*this, a, &World::set_motor_limits);
    case C::set_weld_springs:
      return replay(*this, a, &World::set_weld_springs);
    case C::set_joint_break:
      return replay(*this, a, &World::set_joint_break);
    case C::step:
      return replay(*this, a, static_cast<void (World::*)()>(&World::step));
    case C::step_with:
      return replay(*this, a, static_cast<void (World::*)(Real, int)>(&World::step));
    case C::advance:
      return replay(*this, a, &World::advance);
    case C::restore: {
      // Recorded as a byte list; restore takes a view of one.
      const auto bytes = read<std::vector<std::uint8_t>>(a);
      if (in.remaining() != 0) in.fail("a recorded call longer than its arguments");
      return restore(bytes);
    }
    case C::count:
      break;
  }
  in.fail("recorded call kind " + std::to_string(static_cast<int>(call)) + " is unknown");
}

}  // namespace mink
