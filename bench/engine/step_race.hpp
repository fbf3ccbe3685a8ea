#pragma once

// One run of the race against Box2D v3 (bench/run_step.sh): one scene of its suite, one engine
// at one worker count, in a process of its own, so that the process's peak memory is that
// scene's. The two runner programs (step_v3_box2d.cpp, step_v3_mink.cpp) supply the engine;
// the command line, the timing and the report are here, the same for both. Box2D v3 and
// Box2D 2.4.1 define the same b2* symbols, so Box2D v3 lives in its own runner program.
//
// Usage: RUNNER --list    (the suite: each scene's name and steps, one a line)
//        RUNNER SCENE [--workers=N] [--steps=N] [--warmup=K] [--samples=FILE]
//               [--implementation=NAME] [--sleep=app|off] [--turn-ms=T]
//   --workers=N         threads stepping the world, the calling one among them (default 1)
//   --steps=N           steps to run (default: as many as Box2D v3's app runs the scene)
//   --warmup=K          first steps left out of the timing (default 1, as Box2D v3's app)
//   --samples=FILE      append each timed step's wall time and CPU time (every thread of the
//                       process) in nanoseconds, one step a line
//   --implementation=   which of the runner's implementations (default: its first)
//   --sleep=app|off     app (default): sleeping as Box2D v3's app has it, off only where the
//                       scene turns it off; off: off in every scene
//   --profile           also print the mean time per step of each phase the engine reports
//                       (a `phase name=... ms=...` line each, after the race line)
//   --turn-ms=T         stop (SIGSTOP) once the world is built, and then after the first step
//                       that ends T ms or more after the last stop, for mink_bench_take_turns to
//                       run the runners of a race in turns; the first step after each stop is
//                       not timed (its caches are the other engine's)
//
// It prints one line, `race scene=... workers=... implementation=... steps=... timed=...
// median_ns=... cpu_median_ns=... peak_kib=... base_kib=... bodies=... shapes=... joints=...
// contacts=...`
// (peak_kib: the process's peak resident memory; base_kib: the same before the scene was
// built), or `IMPLEMENTATION: no scene NAME; skipped` when the engine does not have the scene.
// Exit status 0 after either, 2 for a usage error, 1 for a failure.

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "step_v3_suite.hpp"

namespace mink::bench {

/// What is in a world at the end of a run, counted as Box2D v3's b2World_GetCounters counts.
struct RaceCounts {
  long long bodies = 0;
  long long shapes = 0;
  long long joints = 0;
  long long contacts = 0;  ///< contact records (pairs whose bounds overlap), touching or not
};

/// One engine's world of one scene.
class RaceWorld {
 public:
  virtual ~RaceWorld() = default;
  /// Step `index` (0 for the first): the scene's own per-step actions, then one world step.
  virtual void step(int index) = 0;
  virtual RaceCounts counts() const = 0;
  /// The phases of the last step and their times in milliseconds, as the engine reports them.
  virtual std::vector<std::pair<std::string, double>> profile() const = 0;
};

/// What a runner is asked to build.
struct RaceRequest {
  const SuiteScene* scene = nullptr;
  int workers = 1;
  std::string_view implementation;
  bool sleep = true;  ///< false: sleeping off, whatever the scene says
};

/// A runner's engine: the names it reports under and how it builds a scene's world (nullptr
/// when it does not have the scene; the run is then skipped).
struct RaceEngine {
  std::vector<std::string_view> implementations;  ///< the first is the default
  std::function<std::unique_ptr<RaceWorld>(const RaceRequest&)> build;
};

/// Parses the command line, builds the world, steps and times it, and reports (see above).
/// Returns the exit status.
int race_main(int argc, char** argv, const RaceEngine& engine);

}  // namespace mink::bench
