#include "recording.hpp"

#include <array>
#include <cstring>
#include <string>

#include "mink/byte_stream.hpp"
#include "output_files.hpp"

namespace mink::cli {

namespace {

// The file: these 8 bytes, a format version, the snapshot (its length first), then entries
// each led by a tag, and an end tag so a cut-off file is told from a complete one.
constexpr std::array<char, 8> kMagic{'M', 'I', 'N', 'K', 'R', 'E', 'C', 'D'};
constexpr std::uint32_t kVersion = 1;
enum Tag : std::uint8_t { kEnd = 0, kCall = 1, kStep = 2 };

}  // namespace

void save_recording(const std::filesystem::path& file, const Recording& recording) {
  ByteWriter out;
  out.raw(kMagic.data(), kMagic.size());
  out.value(kVersion);
  out.value(static_cast<std::uint64_t>(recording.snapshot.size()));
  out.raw(recording.snapshot.data(), recording.snapshot.size());
  for (const Recording::Entry& entry : recording.entries) {
    if (entry.is_step) {
      out.value(kStep);
      out.value(entry.step);
      out.value(entry.hash);
    } else {
      out.value(kCall);
      out.value(static_cast<std::uint64_t>(entry.call.size()));
      out.raw(entry.call.data(), entry.call.size());
    }
  }
  out.value(kEnd);
  write_file_atomically(file, out.bytes(), "--record file");
}

Recording load_recording(const std::filesystem::path& file) {
  const std::vector<std::uint8_t> bytes = read_file_bytes(file, "recording");
  ByteReader in(bytes);
  std::array<char, 8> magic{};
  in.raw(magic.data(), magic.size());
  if (magic != kMagic) {
    throw SnapshotError("'" + file.string() + "' is not a recording (no MINKRECD header)");
  }
  const auto version = in.get<std::uint32_t>();
  if (version != kVersion) {
    throw SnapshotError("recording format version " + std::to_string(version) +
                        ", this build reads version " + std::to_string(kVersion));
  }
  Recording recording;
  recording.snapshot.resize(in.count(1));
  in.raw(recording.snapshot.data(), recording.snapshot.size());
  for (;;) {
    const auto tag = in.get<std::uint8_t>();
    if (tag == kEnd) break;
    Recording::Entry entry;
    if (tag == kStep) {
      entry.is_step = true;
      in.value(entry.step);
      in.value(entry.hash);
    } else if (tag == kCall) {
      entry.call.resize(in.count(1));
      in.raw(entry.call.data(), entry.call.size());
    } else {
      in.fail("an entry tag " + std::to_string(tag) + " that is neither a call nor a step");
    }
    recording.entries.push_back(std::move(entry));
  }
  if (in.remaining() != 0) in.fail("bytes after the end of the recording");
  return recording;
}

RunRecorder::RunRecorder(World& world) : world_(world) {
  recording_.snapshot = world.snapshot();
  world.set_recorder(this);
}

RunRecorder::~RunRecorder() {
  world_.set_recorder(nullptr);
}

void RunRecorder::call(std::span<const std::uint8_t> encoded) {
  Recording::Entry entry;
  entry.call.assign(encoded.begin(), encoded.end());
  recording_.entries.push_back(std::move(entry));
}

void RunRecorder::stepped(const World& world) {
  Recording::Entry entry;
  entry.is_step = true;
  entry.step = world.step_count();
  entry.hash = world.state_hash();
  recording_.entries.push_back(std::move(entry));
  ++steps_;
}

namespace {

// Set on the replaying world: checks each step against the recording's next step entry.
class Checker final : public Recorder {
 public:
  Checker(const Recording& recording, ReplayResult& result)
      : recording_(recording), result_(result) {}
  std::size_t next = 0;  // the entry after the call being replayed
  void call(std::span<const std::uint8_t>) override {}
  void stepped(const World& world) override {
    if (result_.diverged_at) return;
    const std::uint64_t hash = world.state_hash();
    if (next >= recording_.entries.size() || !recording_.entries[next].is_step ||
        recording_.entries[next].step != world.step_count() ||
        recording_.entries[next].hash != hash) {
      result_.diverged_at = world.step_count();
      result_.replayed_hash = hash;
      const bool recorded = next < recording_.entries.size() && recording_.entries[next].is_step;
      result_.recorded_hash = recorded ? recording_.entries[next].hash : 0;
      return;
    }
    ++next;
    ++result_.steps;
  }

 private:
  const Recording& recording_;
  ReplayResult& result_;
};

}  // namespace

ReplayResult replay(const Recording& recording, int worker_count) {
  World world = World::from_snapshot(recording.snapshot, worker_count);
  ReplayResult result;
  result.first_step = world.step_count();
  Checker checker(recording, result);
  world.set_recorder(&checker);
  std::size_t i = 0;
  while (i < recording.entries.size() && !result.diverged_at) {
    const Recording::Entry& entry = recording.entries[i];
    if (entry.is_step) {
      // A step the replay did not take where the recording took one.
      result.diverged_at = entry.step;
      result.recorded_hash = entry.hash;
      result.replayed_hash = world.state_hash();
      break;
    }
    checker.next = i + 1;
    try {
      world.replay_call(entry.call);
    } catch (const SnapshotError&) {
      throw;
    } catch (const Error&) {
      // The call failed when it was recorded too (it is recorded before it runs), leaving the
      // world unchanged; a difference would show in the next hash.
    }
    i = checker.next;
  }
  world.set_recorder(nullptr);
  return result;
}

}  // namespace mink::cli
