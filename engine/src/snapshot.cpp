// World snapshots: the whole simulation state as bytes (World::snapshot), read back into a
// fresh state that replaces the world's only once it is whole and checked (World::restore),
// and the state's hash for desync checks (World::state_hash).

#include <array>
#include <cmath>
#include <cstring>
#include <string>

#include "mink/byte_stream.hpp"
#include "mink/engine/world.hpp"
#include "record_scope.hpp"
#include "snapshot_checks.hpp"
#include "snapshot_io.hpp"
#include "world_state.hpp"

namespace mink {

namespace {

constexpr std::array<char, 8> kMagic{'M', 'I', 'N', 'K', 'S', 'N', 'A', 'P'};
constexpr std::uint32_t kFormatVersion = 5;
// Magic, format version, build fingerprint, payload size, payload checksum.
constexpr std::size_t kHeaderSize = 8 + 4 + 8 + 8 + 8;

// What a snapshot's bytes depend on besides the format: the number type, the byte order and
// the records' layouts (a field added to one changes its size, and most likely the format).
std::uint64_t build_fingerprint() {
  ByteWriter w;
  w.value(static_cast<std::uint32_t>(sizeof(Real)));
  w.value(static_cast<std::uint32_t>(std::numeric_limits<Real>::digits));
  w.value(std::uint32_t{0x01020304});  // its bytes in this machine's order
  w.value(static_cast<std::uint32_t>(sizeof(detail::Body)));
  w.value(static_cast<std::uint32_t>(sizeof(detail::Shape)));
  w.value(static_cast<std::uint32_t>(sizeof(detail::Contact)));
  w.value(static_cast<std::uint32_t>(sizeof(detail::Joint)));
  w.value(static_cast<std::uint32_t>(sizeof(detail::JointKind)));
  w.value(static_cast<std::uint32_t>(sizeof(detail::SensorState)));
  w.value(static_cast<std::uint32_t>(sizeof(WorldDef)));
  w.value(static_cast<std::uint32_t>(detail::kGraphColors));
  return hash_bytes(w.bytes());
}

// Every field that decides what later steps do, in one order for saving and loading. Left out:
// the worker settings (not state: a snapshot continues the same at any worker count), the
// events and counters of the last step, and the step's scratch, rebuilt by every step.
template <typename Archive>
void state_fields(Archive& a, WorldState& w) {
  WorldDef& d = w.def;
  a(d.gravity);
  a(d.time_step);
  a(d.substeps);
  a(d.contact_hertz);
  a(d.contact_damping_ratio);
  a(d.joint_hertz);
  a(d.joint_damping_ratio);
  a(d.joint_iterations);
  a(d.direct_joint_chains);
  a(d.enable_continuous);
  a(d.continuous_fast_pairs);
  a(d.fast_body_margin);
  a(d.contact_push_max_velocity);
  a(d.restitution_threshold);
  a(d.hit_event_threshold);
  a(d.linear_slop);
  a(d.max_linear_speed);
  a(d.enable_sleep);
  a(d.time_to_sleep);
  a(d.linear_sleep_tolerance);
  a(d.angular_sleep_tolerance);
  a(d.max_steps_per_advance);
  a(d.simd_solver);
  a(d.reuse_manifolds);
  a(d.manifold_reuse_distance);

  a(w.time);
  a(w.accumulator);
  a(w.step_count);
  a(w.next_chain);
  a(w.dt);
  a(w.substeps);
  w.bodies.fields(a);
  w.shapes.fields(a);
  w.joints.fields(a);
  if constexpr (Archive::loading) {
    w.broadphase.load(a);
  } else {
    w.broadphase.save(a);
  }
  a(w.pending_proxy_destroys);
  if constexpr (Archive::loading) {
    w.contacts.resize(a.count(1));
    w.contact_impulses.resize(w.contacts.size());
  } else {
    a.count(w.contacts.size());
  }
  for (std::size_t i = 0; i < w.contacts.size(); ++i) {
    detail::contact_io(a, w.contacts[i], w.contact_impulses[i]);
  }
  a(w.sensors);
  std::uint64_t touching = w.touching_count;
  a(touching);
  w.touching_count = static_cast<std::size_t>(touching);
  for (std::vector<std::uint64_t>& bits : w.graph.bits()) a(bits);
  a(w.newly_acting);
  a(w.awake_list);
  a(w.island_stamp);
}

std::vector<std::uint8_t> payload_of(const WorldState& w) {
  ByteWriter out;
  SaveArchive archive{out};
  state_fields(archive, const_cast<WorldState&>(w));
  return std::move(out.bytes());
}

template <typename T>
T read_at(std::span<const std::uint8_t> bytes, std::size_t offset) {
  T v;
  std::memcpy(&v, bytes.data() + offset, sizeof v);
  return v;
}

// A whole, checked state from the bytes, with the worker settings of `runtime` and ids of
// world `serial`; throws SnapshotError naming what is wrong.
std::unique_ptr<WorldState> parse(std::span<const std::uint8_t> bytes, const WorldDef& runtime,
                                  std::uint32_t serial) {
  if (bytes.size() < kHeaderSize) {
    throw SnapshotError("snapshot truncated at byte " + std::to_string(bytes.size()) +
                        ": the header needs " + std::to_string(kHeaderSize) + " bytes");
  }
  if (std::memcmp(bytes.data(), kMagic.data(), kMagic.size()) != 0) {
    throw SnapshotError("not a Minkowski snapshot: the first 8 bytes are not MINKSNAP");
  }
  const auto version = read_at<std::uint32_t>(bytes, 8);
  if (version != kFormatVersion) {
    throw SnapshotError("snapshot format version " + std::to_string(version) +
                        ", this build reads version " + std::to_string(kFormatVersion));
  }
  const auto fingerprint = read_at<std::uint64_t>(bytes, 12);
  if (fingerprint != build_fingerprint()) {
    throw SnapshotError(
        "snapshot from another build: its fingerprint (number type, byte order, record "
        "layouts) " +
        std::to_string(fingerprint) + " is not this build's " +
        std::to_string(build_fingerprint()));
  }
  const auto size = read_at<std::uint64_t>(bytes, 20);
  if (size > bytes.size() - kHeaderSize) {
    throw SnapshotError("snapshot truncated at byte " + std::to_string(bytes.size()) +
                        ": the header announces " + std::to_string(kHeaderSize + size) + " bytes");
  }
  if (size < bytes.size() - kHeaderSize) {
    throw SnapshotError("snapshot has " + std::to_string(bytes.size() - kHeaderSize - size) +
                        " bytes after its end at byte " + std::to_string(kHeaderSize + size));
  }
  const std::span<const std::uint8_t> payload = bytes.subspan(kHeaderSize);
  if (hash_bytes(payload) != read_at<std::uint64_t>(bytes, 28)) {
    throw SnapshotError("snapshot checksum mismatch: its " + std::to_string(size) +
                        " bytes of state are corrupt");
  }
  auto state = std::make_unique<WorldState>();
  state->def = runtime;
  state->serial = serial;
  ByteReader in(payload, kHeaderSize);
  LoadArchive archive{in, serial};
  state_fields(archive, *state);
  if (in.remaining() != 0) in.fail("state ends before the snapshot does");
  detail::check_snapshot_state(*state, in);
  try {
    detail::check_world_def(state->def);
  } catch (const Error& e) {
    throw SnapshotError(std::string("snapshot with bad world settings: ") + e.what());
  }
  for (std::uint32_t i = 0; i < state->joints.size(); ++i) state->set_joint_bodies(i);
  state->rebuild_contact_slots();
  state->find_bare_boxes();
  state->contact_index.reserve(state->contacts.size());
  for (std::uint32_t i = 0; i < state->contacts.size(); ++i) {
    const detail::Contact& c = state->contacts[i];
    const std::uint64_t key = detail::pair_key(c.proxy_a, c.proxy_b);
    if (state->contact_index.contains(key)) {
      throw SnapshotError("snapshot with two contacts of the proxy pair (" +
                          std::to_string(c.proxy_a) + ", " + std::to_string(c.proxy_b) + ")");
    }
    state->contact_index.set(key, i);
  }
  return state;
}

}  // namespace

std::vector<std::uint8_t> World::snapshot() const {
  ByteWriter out;
  out.raw(kMagic.data(), kMagic.size());
  out.value(kFormatVersion);
  out.value(build_fingerprint());
  out.value(std::uint64_t{0});  // payload size and checksum, filled in below
  out.value(std::uint64_t{0});
  SaveArchive archive{out};
  state_fields(archive, *state_);
  std::vector<std::uint8_t>& bytes = out.bytes();
  const std::uint64_t size = bytes.size() - kHeaderSize;
  const std::uint64_t checksum =
      hash_bytes(std::span<const std::uint8_t>(bytes).subspan(kHeaderSize));
  std::memcpy(bytes.data() + 20, &size, sizeof size);
  std::memcpy(bytes.data() + 28, &checksum, sizeof checksum);
  return std::move(bytes);
}

void World::restore(std::span<const std::uint8_t> snapshot) {
  const detail::RecordScope record(*this, detail::Call::restore, snapshot);
  std::unique_ptr<WorldState> fresh = parse(snapshot, state_->def, state_->serial);
  // Nothing below throws: the world changes whole or not at all. It keeps its workers and
  // its recorder.
  std::swap(fresh->tasks, state_->tasks);
  fresh->recorder = state_->recorder;
  fresh->call_depth = state_->call_depth;
  state_ = std::move(fresh);
}

World World::from_snapshot(std::span<const std::uint8_t> snapshot, int worker_count,
                           const TaskSystem& task_system) {
  WorldDef def;
  def.worker_count = worker_count;
  def.task_system = task_system;
  World world(def);
  world.restore(snapshot);
  return world;
}

std::uint64_t World::state_hash() const {
  return hash_bytes(payload_of(*state_));
}

std::uint32_t World::serial() const noexcept {
  return state_->serial;
}

}  // namespace mink
