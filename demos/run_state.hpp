#pragma once

// The solver state that travels beside a scene file: `mink run --save FILE` writes FILE (the
// human-readable scene) and FILE.state (the world's snapshot, with a hash of FILE's text), and
// `mink run FILE` resumes from FILE.state when it belongs to FILE as it is now, so the run
// continues exactly as if it had never stopped.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <ostream>
#include <vector>

#include "mink/engine/world.hpp"

namespace mink::cli {

// FILE.state for scene file FILE.
std::filesystem::path state_file_for(const std::filesystem::path& scene_file);

// Writes the world as scene file `file` and its state beside it, each whole or not at all.
// Throws OutputError when either cannot be written.
void save_run(const std::filesystem::path& file, const World& world);

// The snapshot saved with scene file `file`, when FILE.state exists and was saved with the
// file's current text. A state saved with other text (the scene was edited since) is left
// unused, with a one-line notice on `notice`: the run then starts from the scene file, its
// contacts cold. Throws SnapshotError for a FILE.state that is not one.
std::optional<std::vector<std::uint8_t>> find_saved_state(const std::filesystem::path& file,
                                                          std::ostream& notice);

}  // namespace mink::cli
