// Time per step of the engine against Box2D 2.4.1 on the same scenes, in the same run:
// pyramid_100 (5050 boxes, 500 steps at 1/60 s) and pyramid_grid (20 x 20 pyramids of base
// 10, 200 steps), at our own world settings, sleeping off in both engines, Box2D with 8 velocity
// and 3 position iterations. Each repetition builds a fresh world (not timed) and times every step
// in thread CPU time (the machine is shared: wall time would charge other processes to whichever
// engine runs at that moment); the CSV gets the median step time over all steps of all
// repetitions.
//
// Own flags (the rest go to Google Benchmark):
//   --csv=PATH         write case,size,implementation,median_ns to PATH
//   --repetitions=N    fresh worlds per case and engine (default 3)
//   --cases=A,B        only these cases

#include <benchmark/benchmark.h>
#include <box2d/box2d.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "box2d_scene.hpp"
#include "mink/engine/scene.hpp"

namespace mink::bench {
namespace {

struct Case {
  std::string name;
  int steps;
};

const std::vector<Case> kCases = {{"pyramid_100", 500}, {"pyramid_grid", 200}};
constexpr std::string_view kOurs = "minkowski";
constexpr std::string_view kBox2d = "box2d-2.4.1";

// Per (case, implementation): every step time in nanoseconds, and the body count.
std::map<std::pair<std::string, std::string>, std::vector<double>> g_samples;
std::map<std::string, std::size_t> g_sizes;

SceneDef bench_scene(const std::string& name) {
  SceneDef scene = builtin_scene(name);
  scene.world.enable_sleep = false;
  return scene;
}

std::size_t dynamic_count(const SceneDef& scene) {
  return static_cast<std::size_t>(
      std::count_if(scene.bodies.begin(), scene.bodies.end(),
                    [](const SceneBody& b) { return b.body.type == BodyType::dynamic; }));
}

double thread_cpu_ns() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e9 + static_cast<double>(t.tv_nsec);
}

template <typename Step>
void time_steps(benchmark::State& state, int steps, std::vector<double>& samples, Step&& step) {
  double total = 0;
  for (int i = 0; i < steps; ++i) {
    const double start = thread_cpu_ns();
    step();
    const double ns = thread_cpu_ns() - start;
    samples.push_back(ns);
    total += ns;
  }
  state.SetIterationTime(total * 1e-9 / steps);
}

void run_ours(benchmark::State& state, const Case& c) {
  for (auto _ : state) {
    const SceneDef scene = bench_scene(c.name);
    g_sizes[c.name] = dynamic_count(scene);
    World world = build_world(scene);
    BodyId top;
    for (const BodyId id : world.bodies()) {
      if (world.body_type(id) == BodyType::dynamic &&
          (top.is_null() || world.position(id).y() > world.position(top).y())) {
        top = id;
      }
    }
    const Vec2 start = world.position(top);
    time_steps(state, c.steps, g_samples[{c.name, std::string(kOurs)}], [&] { world.step(); });
    state.counters["top_moved"] = (world.position(top) - start).norm();
    state.counters["touching"] = static_cast<double>(world.counters().touching_contacts);
  }
}

void run_box2d(benchmark::State& state, const Case& c) {
  for (auto _ : state) {
    interop::Box2dScene scene = interop::build_box2d_world(bench_scene(c.name));
    const b2Vec2 start = scene.top->GetPosition();
    const float dt = static_cast<float>(bench_scene(c.name).world.time_step);
    time_steps(state, c.steps, g_samples[{c.name, std::string(kBox2d)}],
               [&] { scene.world->Step(dt, 8, 3); });
    state.counters["top_moved"] = (scene.top->GetPosition() - start).Length();
    state.counters["touching"] = static_cast<double>(scene.world->GetContactCount());
  }
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

}  // namespace
}  // namespace mink::bench

int main(int argc, char** argv) {
  using namespace mink::bench;
  std::string csv_path;
  int repetitions = 3;
  std::string only;
  std::vector<char*> rest;
  for (int i = 0; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg.starts_with("--csv=")) {
      csv_path = std::string(arg.substr(6));
    } else if (arg.starts_with("--repetitions=")) {
      repetitions = std::atoi(std::string(arg.substr(14)).c_str());
    } else if (arg.starts_with("--cases=")) {
      only = ",";
      only += arg.substr(8);
      only += ",";
    } else {
      rest.push_back(argv[i]);
    }
  }
  for (const Case& c : kCases) {
    std::string key = ",";
    key += c.name;
    key += ",";
    if (!only.empty() && only.find(key) == std::string::npos) continue;
    // Ours and Box2D alternate per repetition so both see the same machine conditions.
    for (int r = 0; r < repetitions; ++r) {
      benchmark::RegisterBenchmark((c.name + "/" + std::string(kOurs)).c_str(),
                                   [c](benchmark::State& s) { run_ours(s, c); })
          ->UseManualTime()
          ->Iterations(1)
          ->Unit(benchmark::kMillisecond);
      benchmark::RegisterBenchmark((c.name + "/" + std::string(kBox2d)).c_str(),
                                   [c](benchmark::State& s) { run_box2d(s, c); })
          ->UseManualTime()
          ->Iterations(1)
          ->Unit(benchmark::kMillisecond);
    }
  }
  int rest_count = static_cast<int>(rest.size());
  benchmark::Initialize(&rest_count, rest.data());
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();

  FILE* out = csv_path.empty() ? nullptr : std::fopen(csv_path.c_str(), "w");
  if (!csv_path.empty() && !out) {
    std::fprintf(stderr, "cannot write %s\n", csv_path.c_str());
    return 1;
  }
  if (out) std::fprintf(out, "case,size,implementation,median_ns\n");
  for (const Case& c : kCases) {
    const auto ours = g_samples.find({c.name, std::string(kOurs)});
    const auto theirs = g_samples.find({c.name, std::string(kBox2d)});
    if (ours == g_samples.end() || theirs == g_samples.end()) continue;
    const double ours_ns = median(ours->second), theirs_ns = median(theirs->second);
    for (const auto& [impl, ns] : {std::pair{kOurs, ours_ns}, std::pair{kBox2d, theirs_ns}}) {
      if (out) {
        std::fprintf(out, "%s,%zu,%s,%.0f\n", c.name.c_str(), g_sizes[c.name],
                     std::string(impl).c_str(), ns);
      }
    }
    std::printf("%s: minkowski %.3f ms, box2d %.3f ms per step (median), ratio %.3f\n",
                c.name.c_str(), ours_ns * 1e-6, theirs_ns * 1e-6, ours_ns / theirs_ns);
  }
  if (out) std::fclose(out);
  return 0;
}
