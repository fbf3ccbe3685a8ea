// Broadphase time per step: N unit boxes moving randomly, every box moved every step (as the
// engine does for awake bodies), then the pairs brought up to date. Ours (SweepAndPrune:
// move_proxy + update_pairs, which also maintains the pair set and its begun/ended events)
// against Box2D 2.4.1's b2BroadPhase (MoveProxy + UpdatePairs, which only reports candidate
// pairs). Both replay exactly the same motion: same seed, same steps, same fat margin (0.1,
// Box2D's b2_aabbExtension); Box2D also gets the displacement it uses to stretch its boxes.
//
// Own flags (the rest go to Google Benchmark):
//   --csv=PATH      write case,size,implementation,median_ns to PATH
//   --max-size=N    only sizes up to N

#include <benchmark/benchmark.h>
#include <box2d/b2_broad_phase.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "mink/broadphase/sweep_and_prune.hpp"

namespace {

using mink::Aabb;
using mink::Real;
using mink::Vec2;

constexpr Real kMargin = 0.1;  // b2_aabbExtension in Box2D 2.4.1
constexpr Real kTimeStep = 1.0 / 60;
constexpr Real kMaxSpeed = 2.0;  // m/s
constexpr Real kKick = 0.5;      // random change of velocity per step, m/s
constexpr int kWarmupSteps = 10;

enum class Layout { uniform, dense_pile };
const char* name_of(Layout layout) {
  return layout == Layout::uniform ? "uniform" : "dense-pile";
}

// Boxes of side 1 in a square box; they drift with random velocities and bounce off the
// walls, so the layout stays uniform / piled for the whole run.
class Scene {
 public:
  Scene(Layout layout, std::size_t n)
      : random_(0x6d696e6bULL + n + 7919 * static_cast<int>(layout)) {
    // Uniform: a quarter of the area covered, a few neighbours each. Dense pile: two boxes
    // per unit area, about ten overlapping neighbours each.
    const Real density = layout == Layout::uniform ? 0.25 : 2.0;
    side_ = std::sqrt(static_cast<Real>(n) / density);
    std::uniform_real_distribution<Real> position(0.5, side_ - 0.5);
    std::uniform_real_distribution<Real> velocity(-kMaxSpeed, kMaxSpeed);
    for (std::size_t i = 0; i < n; ++i) {
      centers_.emplace_back(position(random_), position(random_));
      velocities_.emplace_back(velocity(random_), velocity(random_));
    }
    displacements_.assign(n, Vec2::Zero());
  }

  void step() {
    std::uniform_real_distribution<Real> kick(-kKick, kKick);
    for (std::size_t i = 0; i < centers_.size(); ++i) {
      Vec2& v = velocities_[i];
      v += Vec2(kick(random_), kick(random_));
      v = v.cwiseMax(-kMaxSpeed).cwiseMin(kMaxSpeed);
      Vec2 c = centers_[i] + v * kTimeStep;
      for (int axis = 0; axis < 2; ++axis) {
        if (c[axis] < 0.5 || c[axis] > side_ - 0.5) {
          v[axis] = -v[axis];
          c[axis] = std::clamp(c[axis], 0.5, side_ - 0.5);
        }
      }
      displacements_[i] = c - centers_[i];
      centers_[i] = c;
    }
  }

  Aabb box(std::size_t i) const {
    return {centers_[i] - Vec2(0.5, 0.5), centers_[i] + Vec2(0.5, 0.5)};
  }
  const Vec2& displacement(std::size_t i) const { return displacements_[i]; }
  std::size_t size() const { return centers_.size(); }

 private:
  std::mt19937_64 random_;
  Real side_ = 0;
  std::vector<Vec2> centers_;
  std::vector<Vec2> velocities_;
  std::vector<Vec2> displacements_;
};

// Steps timed per repetition: enough work per repetition at every size.
std::int64_t steps_for(std::size_t n) {
  return n <= 1000 ? 400 : n <= 10000 ? 80 : 16;
}

// The CPU time of this thread: the machine is shared, and wall time would charge other
// processes' time slices to whichever implementation happened to be running.
double thread_seconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

void time_ours(benchmark::State& state, Layout layout, std::size_t n) {
  Scene scene(layout, n);
  mink::SweepAndPrune broadphase(kMargin);
  std::vector<mink::ProxyId> ids;
  for (std::size_t i = 0; i < n; ++i) {
    ids.push_back(broadphase.create_proxy(scene.box(i), mink::ProxyKind::moving, i));
  }
  mink::PairEvents events;
  std::size_t refattened = 0;
  const auto run_step = [&] {
    for (std::size_t i = 0; i < n; ++i) {
      refattened += broadphase.move_proxy(ids[i], scene.box(i)) ? 1 : 0;
    }
    broadphase.update_pairs(events);
  };
  broadphase.update_pairs(events);
  for (int i = 0; i < kWarmupSteps; ++i) {
    scene.step();
    run_step();
  }
  std::size_t events_seen = 0;
  refattened = 0;
  for (auto _ : state) {
    scene.step();
    const double start = thread_seconds();
    run_step();
    state.SetIterationTime(thread_seconds() - start);
    events_seen += events.begun.size() + events.ended.size();
  }
  state.counters["pairs"] = static_cast<double>(broadphase.pairs().size());
  state.counters["refattened_per_step"] =
      static_cast<double>(refattened) / static_cast<double>(state.iterations());
  state.counters["events_per_step"] =
      static_cast<double>(events_seen) / static_cast<double>(state.iterations());
}

// Box2D's UpdatePairs hands each candidate pair to AddPair; counting them is the least a
// client can do.
struct PairCounter {
  void AddPair(void*, void*) { ++count; }
  std::size_t count = 0;
};

b2AABB to_box2d(const Aabb& box) {
  b2AABB out;
  out.lowerBound.Set(static_cast<float>(box.lower.x()), static_cast<float>(box.lower.y()));
  out.upperBound.Set(static_cast<float>(box.upper.x()), static_cast<float>(box.upper.y()));
  return out;
}

void time_box2d(benchmark::State& state, Layout layout, std::size_t n) {
  Scene scene(layout, n);
  b2BroadPhase broadphase;
  std::vector<std::int32_t> ids;
  for (std::size_t i = 0; i < n; ++i) {
    ids.push_back(broadphase.CreateProxy(to_box2d(scene.box(i)), nullptr));
  }
  PairCounter counter;
  std::vector<b2AABB> boxes(n);
  std::vector<b2Vec2> displacements(n);
  const auto prepare = [&] {
    scene.step();
    for (std::size_t i = 0; i < n; ++i) {
      boxes[i] = to_box2d(scene.box(i));
      displacements[i].Set(static_cast<float>(scene.displacement(i).x()),
                           static_cast<float>(scene.displacement(i).y()));
    }
  };
  const auto run_step = [&] {
    for (std::size_t i = 0; i < n; ++i) broadphase.MoveProxy(ids[i], boxes[i], displacements[i]);
    broadphase.UpdatePairs(&counter);
  };
  broadphase.UpdatePairs(&counter);
  for (int i = 0; i < kWarmupSteps; ++i) {
    prepare();
    run_step();
  }
  counter.count = 0;
  for (auto _ : state) {
    prepare();
    const double start = thread_seconds();
    run_step();
    state.SetIterationTime(thread_seconds() - start);
  }
  state.counters["candidates_per_step"] =
      static_cast<double>(counter.count) / static_cast<double>(state.iterations());
}

struct Key {
  std::string case_name;
  std::size_t size;
  std::string implementation;
};

// Prints as usual and appends each benchmark's median over the repetitions to the CSV.
class CsvReporter : public benchmark::ConsoleReporter {
 public:
  CsvReporter(const std::string& path, std::vector<std::pair<std::string, Key>> keys)
      : keys_(std::move(keys)) {
    if (path.empty()) return;
    csv_.open(path, std::ios::trunc);
    csv_ << "case,size,implementation,median_ns\n" << std::flush;
  }
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      if (run.run_type != Run::RT_Aggregate || run.aggregate_name != "median") continue;
      for (const auto& [name, key] : keys_) {
        if (run.run_name.function_name != name) continue;
        if (csv_.is_open()) {
          csv_ << key.case_name << ',' << key.size << ',' << key.implementation << ','
               << std::llround(run.GetAdjustedRealTime()) << '\n'
               << std::flush;
        }
      }
    }
  }

 private:
  std::vector<std::pair<std::string, Key>> keys_;
  std::ofstream csv_;
};

}  // namespace

int main(int argc, char** argv) {
  std::string csv_path;
  std::size_t max_size = 100000;
  std::vector<char*> rest{argv[0]};
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg.starts_with("--csv=")) {
      csv_path = std::string(arg.substr(6));
    } else if (arg.starts_with("--max-size=")) {
      max_size = std::stoull(std::string(arg.substr(11)));
    } else {
      rest.push_back(argv[i]);
    }
  }
  std::vector<std::pair<std::string, Key>> keys;
  for (const Layout layout : {Layout::uniform, Layout::dense_pile}) {
    for (const std::size_t n : {std::size_t{1000}, std::size_t{10000}, std::size_t{100000}}) {
      if (n > max_size) continue;
      // Each implementation right after the other on the same case: same machine state.
      const std::string stem =
          std::string("broadphase/") + name_of(layout) + "/" + std::to_string(n);
      keys.push_back({stem + "/minkowski-sap", {name_of(layout), n, "minkowski-sap"}});
      benchmark::RegisterBenchmark(keys.back().first.c_str(), time_ours, layout, n)
          ->UseManualTime()
          ->Iterations(steps_for(n))
          ->Repetitions(5);
      keys.push_back({stem + "/box2d", {name_of(layout), n, "box2d"}});
      benchmark::RegisterBenchmark(keys.back().first.c_str(), time_box2d, layout, n)
          ->UseManualTime()
          ->Iterations(steps_for(n))
          ->Repetitions(5);
    }
  }
  int rest_count = static_cast<int>(rest.size());
  benchmark::Initialize(&rest_count, rest.data());
  CsvReporter reporter(csv_path, keys);
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}
