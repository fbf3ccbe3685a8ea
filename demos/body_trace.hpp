#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

#include "mink/engine/world.hpp"
#include "mink/output_file.hpp"

namespace mink::cli {

// `mink run --trace`: a CSV of every body's state for plotting,
// `step,body,x,y,angle,vx,vy,w`, one row per body for step 0 (the initial state) and every
// `every`-th step after it. `body` is the index in the scene's bodies array, (x, y) the body
// origin, (vx, vy) the velocity of that origin (as in scene files, so vx is dx/dt), angle and
// w in radians and radians per second. Numbers have 17 significant digits: they round-trip.
// A body destroyed during the run (by the scene's schedule) has no rows after it is gone;
// bodies the schedule creates are not traced.
class BodyTrace {
 public:
  // `bodies[i]` is body i of the scene. Throws OutputError when `path` cannot be written.
  BodyTrace(const std::filesystem::path& path, std::span<const BodyId> bodies, std::uint64_t every);

  // Writes the rows of the world's current step when it is one to trace.
  void write_step(const World& world);
  // Flushes and closes the file; throws OutputError when anything was lost.
  void close();
  std::uint64_t rows_written() const { return rows_; }

 private:
  std::filesystem::path path_;
  OutputFile out_;
  std::vector<BodyId> bodies_;
  std::uint64_t every_;
  std::uint64_t rows_ = 0;
};

}  // namespace mink::cli
