#pragma once

#include <cstdint>
#include <span>

namespace mink {

class World;

/// The recorder hook (World::set_recorder): told of every call that changes the world, as
/// bytes World::replay_call takes, and of every step's end. A recording is then a snapshot,
/// the calls in order and the state hash of each step; replaying the calls on a world restored
/// from the snapshot must give the same hashes (`mink replay` checks it).
class Recorder {
 public:
  virtual ~Recorder() = default;
  /// A call that changes the world, before it runs. Calls the world makes of itself are not
  /// reported (only the outermost), nor are calls that only read.
  virtual void call(std::span<const std::uint8_t> encoded) = 0;
  /// At the end of each step (step() runs one, advance() any number, each reported).
  virtual void stepped(const World& world) = 0;
};

}  // namespace mink
