#pragma once

// What the recorder hook sees of a World call: its kind and arguments as bytes, reported
// before the call runs when it is the outermost one (World::set_recorder, replay_call).

#include <cstdint>

#include "mink/byte_stream.hpp"
#include "mink/engine/world.hpp"
#include "snapshot_io.hpp"
#include "world_state.hpp"

namespace mink::detail {

// Every World call that changes the world; the numbers are part of the recording format.
enum class Call : std::uint8_t {
  create_body,
  destroy_body,
  create_shape,
  create_chain,
  destroy_shape,
  set_gravity,
  enable_sleep,
  set_transform,
  set_linear_velocity,
  set_angular_velocity,
  apply_force,
  apply_torque,
  apply_linear_impulse,
  set_awake,
  set_body_type,
  set_enabled,
  set_fixed_rotation,
  set_bullet,
  set_continuous_threshold,
  set_target_transform,
  set_mass_data,
  set_shape_density,
  set_shape_friction,
  set_shape_restitution,
  set_shape_filter,
  create_joint,
  destroy_joint,
  set_joint_motor,
  set_joint_spring,
  set_joint_limit,
  set_distance_length,
  set_motor_target,
  set_motor_limits,
  set_weld_springs,
  set_joint_break,
  step,
  step_with,
  advance,
  restore,
  count  // not a call: how many there are
};

// Held for the length of a World call: reports it when it is the outermost and a recorder is
// set. It reaches the state through the World, which restore() replaces.
class RecordScope {
 public:
  template <typename... Args>
  RecordScope(World& world, Call call, const Args&... args) : world_(world) {
    WorldState& w = *world.state_;
    if (w.recorder != nullptr && w.call_depth == 0) {
      ByteWriter out;
      SaveArchive archive{out};
      archive(static_cast<std::uint8_t>(call));
      (archive(args), ...);
      w.recorder->call(out.bytes());
    }
    ++w.call_depth;
  }
  ~RecordScope() { --world_.state_->call_depth; }
  RecordScope(const RecordScope&) = delete;
  RecordScope& operator=(const RecordScope&) = delete;

 private:
  World& world_;
};

}  // namespace mink::detail

namespace mink {

// The bytes restore() is given, recorded as a byte list.
template <typename Archive>
void io(Archive& archive, std::span<const std::uint8_t>& bytes) {
  static_assert(!Archive::loading, "read back as a std::vector<std::uint8_t>");
  archive.count(bytes.size());
  archive.out.raw(bytes.data(), bytes.size());
}

}  // namespace mink
