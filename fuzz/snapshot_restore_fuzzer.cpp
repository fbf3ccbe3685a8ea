// Snapshot restore on any bytes. The input is a snapshot's state, the part after its header:
// the harness puts this build's header around it (magic, format version, fingerprint, size and
// checksum), so the search gets past the checksum to the state reader. An input whose first
// byte is 'M' is taken whole instead, header and all, so the header checks are searched too.
//
// World::from_snapshot and World::restore either take the bytes or throw SnapshotError, nothing
// else; a refused restore leaves the world's state hash as it was. A world made from accepted
// bytes restores into a live world with the same state hash, its own snapshot reads back to the
// same bytes and state, and it steps at 1 and 2 workers to bitwise equal states without
// throwing.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <span>
#include <string>
#include <vector>

#include "mink/byte_stream.hpp"
#include "mink/engine/world.hpp"
#include "mink/error.hpp"

namespace {

[[noreturn]] void fail(const std::string& what) {
  std::fprintf(stderr, "fuzz_snapshot_restore: %s\n", what.c_str());
  std::abort();
}

// Magic, format version, fingerprint, payload size, payload checksum.
constexpr std::size_t kHeaderSize = 8 + 4 + 8 + 8 + 8;
constexpr std::size_t kSizeAt = 20, kChecksumAt = 28;

// A small live world to restore into: a box on the ground.
mink::World make_target() {
  mink::World world;
  const mink::BodyId ground = world.create_body({});
  world.create_shape(ground, mink::ShapeDef::box(5, 0.5));
  mink::BodyDef def;
  def.type = mink::BodyType::dynamic;
  def.position = mink::Vec2(0, 2);
  world.create_shape(world.create_body(def), mink::ShapeDef::box(0.5, 0.5));
  for (int i = 0; i < 5; ++i) world.step();
  return world;
}

std::vector<std::uint8_t> with_header(std::span<const std::uint8_t> payload) {
  static const std::vector<std::uint8_t> header = [] {
    const std::vector<std::uint8_t> any = mink::World().snapshot();
    return std::vector<std::uint8_t>(any.begin(), any.begin() + kHeaderSize);
  }();
  std::vector<std::uint8_t> bytes(header);
  bytes.insert(bytes.end(), payload.begin(), payload.end());
  const std::uint64_t size = payload.size();
  const std::uint64_t checksum = mink::hash_bytes(payload);
  std::memcpy(bytes.data() + kSizeAt, &size, sizeof size);
  std::memcpy(bytes.data() + kChecksumAt, &checksum, sizeof checksum);
  return bytes;
}

// Throws only SnapshotError; anything else is a finding.
template <class Call>
bool accepted(const char* name, Call&& call) {
  try {
    call();
    return true;
  } catch (const mink::SnapshotError&) {
    return false;
  } catch (const std::exception& error) {
    fail(std::string(name) + " threw something other than SnapshotError: " + error.what());
  } catch (...) {
    fail(std::string(name) + " threw something that is not an exception");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 65536) return 0;
  const std::span<const std::uint8_t> input(data, size);
  const std::vector<std::uint8_t> bytes =
      size > 0 && data[0] == 'M' ? std::vector<std::uint8_t>(input.begin(), input.end())
                                 : with_header(input);

  mink::World target = make_target();
  const std::uint64_t target_hash = target.state_hash();
  const bool restored = accepted("restore", [&] { target.restore(bytes); });
  if (!restored && target.state_hash() != target_hash) {
    fail("a refused restore changed the world");
  }

  mink::World one;
  if (!accepted("from_snapshot", [&] { one = mink::World::from_snapshot(bytes, 1); })) {
    if (restored) fail("restore took bytes from_snapshot refuses");
    return 0;
  }
  if (!restored) fail("from_snapshot took bytes restore refuses");
  // Accepted bytes need not be canonical (a flag byte of 2 reads as true); what the world
  // writes is, and reads back to itself exactly.
  const std::vector<std::uint8_t> rewritten = one.snapshot();
  if (mink::World::from_snapshot(rewritten).snapshot() != rewritten) {
    fail("a world's own snapshot does not read back to the same bytes");
  }
  if (mink::World::from_snapshot(rewritten).state_hash() != one.state_hash()) {
    fail("a world's own snapshot reads back to another state");
  }
  if (target.state_hash() != one.state_hash()) {
    fail("restore and from_snapshot give different states");
  }
  mink::World two = mink::World::from_snapshot(bytes, 2);
  for (int step = 0; step < 3; ++step) {
    try {
      one.step();
      two.step();
    } catch (const std::exception& error) {
      fail(std::string("a restored world fails to step: ") + error.what());
    }
    if (one.state_hash() != two.state_hash()) {
      fail("a restored world steps differently at 1 and 2 workers");
    }
  }
  return 0;
}
