#pragma once

// The snapshot loader's checks of a state read from bytes that passed their checksum but may
// have been made by hand: what the API would refuse to make is refused here too.

#include "mink/byte_stream.hpp"
#include "world_state.hpp"

namespace mink::detail {

// Fails `in` (SnapshotError) when an index the step follows without checking names no slot,
// or when a live record holds a value the API refuses: a non-finite number where it keeps
// finite ones, a negative mass, friction or radius, a rotation that is not one, a joint
// definition create_joint would refuse, an enum value with no name.
void check_snapshot_state(const WorldState& w, ByteReader& in);

}  // namespace mink::detail
