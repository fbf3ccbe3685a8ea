#pragma once

// Recordings (`mink run --record FILE`, `mink replay FILE`): the world's snapshot when recording
// began, then, in order, every call that changed the world (the scene's schedule, the sandbox's
// mouse and keys, an embedder's calls: whatever went through World's recorder hook) and the state
// hash after every step. Replaying runs the calls on a world restored from the snapshot and checks
// each step's hash.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <vector>

#include "mink/engine/recorder.hpp"
#include "mink/engine/world.hpp"

namespace mink::cli {

struct Recording {
  // A call (the bytes World::replay_call takes) or a step's end (its step count and hash).
  struct Entry {
    bool is_step = false;
    std::vector<std::uint8_t> call;
    std::uint64_t step = 0;
    std::uint64_t hash = 0;
  };
  std::vector<std::uint8_t> snapshot;
  std::vector<Entry> entries;
};

// Writes `recording` to `file` whole or not at all; throws OutputError when it cannot.
void save_recording(const std::filesystem::path& file, const Recording& recording);
// Reads a recording; throws SnapshotError naming what is wrong with a file that is not one
// (truncated at byte N, a bad entry), InvalidArgumentError for an unreadable file.
Recording load_recording(const std::filesystem::path& file);

// Records a world from now on: a snapshot at once, then every call and step (set as the
// world's recorder while it lives).
class RunRecorder final : public Recorder {
 public:
  explicit RunRecorder(World& world);
  ~RunRecorder() override;
  RunRecorder(const RunRecorder&) = delete;
  RunRecorder& operator=(const RunRecorder&) = delete;
  void call(std::span<const std::uint8_t> encoded) override;
  void stepped(const World& world) override;
  const Recording& recording() const { return recording_; }
  std::size_t steps() const { return steps_; }

 private:
  World& world_;
  Recording recording_;
  std::size_t steps_ = 0;
};

struct ReplayResult {
  std::uint64_t first_step = 0;  // the step count the recording starts at
  std::uint64_t steps = 0;       // steps replayed with the recorded hash
  // The first step whose hash differs (its step count, after the step), and both hashes.
  std::optional<std::uint64_t> diverged_at;
  std::uint64_t recorded_hash = 0, replayed_hash = 0;
};

// Replays `recording` on `worker_count` workers, stopping at the first step that diverges.
ReplayResult replay(const Recording& recording, int worker_count);

}  // namespace mink::cli
