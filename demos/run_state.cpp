#include "run_state.hpp"

#include <array>
#include <cstring>
#include <span>
#include <string>

#include "mink/byte_stream.hpp"
#include "mink/engine/scene.hpp"
#include "mink/engine/scene_file.hpp"
#include "output_files.hpp"

namespace mink::cli {

namespace {

// A state file: these 8 bytes, the hash of the scene file's text, then the world's snapshot.
constexpr std::array<char, 8> kStateMagic{'M', 'I', 'N', 'K', 'S', 'T', 'A', 'T'};
constexpr std::size_t kStateHeader = 16;

std::uint64_t text_hash(std::string_view text) {
  return hash_bytes({reinterpret_cast<const std::uint8_t*>(text.data()), text.size()});
}

}  // namespace

std::filesystem::path state_file_for(const std::filesystem::path& scene_file) {
  std::filesystem::path state = scene_file;
  state += ".state";
  return state;
}

void save_run(const std::filesystem::path& file, const World& world) {
  const std::string text = scene_to_json(capture_scene(world));
  ByteWriter state;
  state.raw(kStateMagic.data(), kStateMagic.size());
  state.value(text_hash(text));
  const std::vector<std::uint8_t> snapshot = world.snapshot();
  state.raw(snapshot.data(), snapshot.size());
  // The state first: a scene file is never left beside a state of another one.
  write_file_atomically(state_file_for(file), state.bytes(), "--save state file");
  write_file_atomically(file, {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()},
                        "--save scene file");
}

std::optional<std::vector<std::uint8_t>> find_saved_state(const std::filesystem::path& file,
                                                          std::ostream& notice) {
  const std::filesystem::path state_file = state_file_for(file);
  std::error_code error;
  if (!std::filesystem::is_regular_file(state_file, error)) return std::nullopt;
  const std::vector<std::uint8_t> text = read_file_bytes(file, "scene file");
  std::vector<std::uint8_t> state = read_file_bytes(state_file, "state file");
  if (state.size() < kStateHeader ||
      std::memcmp(state.data(), kStateMagic.data(), kStateMagic.size()) != 0) {
    throw SnapshotError("'" + state_file.string() + "' is not a state file (no MINKSTAT header)");
  }
  std::uint64_t saved_hash = 0;
  std::memcpy(&saved_hash, state.data() + kStateMagic.size(), sizeof saved_hash);
  if (saved_hash != text_hash({reinterpret_cast<const char*>(text.data()), text.size()})) {
    notice << "notice: " << file.string() << " changed since " << state_file.string()
           << " was saved; starting from the scene file, contacts cold\n";
    return std::nullopt;
  }
  state.erase(state.begin(), state.begin() + kStateHeader);
  return state;
}

}  // namespace mink::cli
