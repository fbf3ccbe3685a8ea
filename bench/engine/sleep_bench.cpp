// What sleeping saves: a world of about 20,000 boxes (19 x 20 pyramids of base 10) stepped
// once every body has fallen asleep, against the same world with sleeping switched off (every
// body awake, the same contacts). Persistent sleep means a sleeping island costs nothing per
// step; the ratio of the two medians shows it. Thread CPU time per step, median over the
// steps of several fresh worlds.
//
// Usage: mink_bench_sleep [--csv=PATH] [--repetitions=N] [--steps=N]

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <string_view>
#include <vector>

#include "mink/engine/scene.hpp"
#include "mink/engine/world.hpp"

namespace {

double thread_cpu_ns() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e9 * static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec);
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  std::string csv;
  int repetitions = 3, steps = 60;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg.starts_with("--csv=")) {
      csv = std::string(arg.substr(6));
    } else if (arg.starts_with("--repetitions=")) {
      repetitions = std::atoi(argv[i] + 14);
    } else if (arg.starts_with("--steps=")) {
      steps = std::atoi(argv[i] + 8);
    } else {
      std::fprintf(stderr, "mink_bench_sleep: unknown argument %s\n", argv[i]);
      return 2;
    }
  }
  if (repetitions < 1 || steps < 1) {
    std::fprintf(stderr, "mink_bench_sleep: repetitions and steps must be positive\n");
    return 2;
  }
  const mink::SceneDef scene = mink::many_pyramids_scene(19, 20, 10);
  std::vector<double> asleep, awake;
  std::size_t bodies = 0;
  for (int r = 0; r < repetitions; ++r) {
    mink::World world = mink::build_world(scene);
    bodies = world.body_count();
    int settle = 0;
    while (world.counters().awake_bodies > 0 || settle == 0) {
      world.step();
      if (++settle > 5000) {
        std::fprintf(stderr, "mink_bench_sleep: the world did not fall asleep\n");
        return 1;
      }
    }
    for (int i = 0; i < steps; ++i) {
      const double t0 = thread_cpu_ns();
      world.step();
      asleep.push_back(thread_cpu_ns() - t0);
    }
    world.enable_sleep(false);  // wakes every body; the contacts stay as they were
    for (int i = 0; i < steps; ++i) {
      const double t0 = thread_cpu_ns();
      world.step();
      awake.push_back(thread_cpu_ns() - t0);
    }
  }
  const double asleep_ns = median(asleep), awake_ns = median(awake);
  std::printf("sleeping_boxes: %zu bodies, asleep %.0f ns, awake %.0f ns per step: %.4f%%\n",
              bodies, asleep_ns, awake_ns, 100 * asleep_ns / awake_ns);
  if (!csv.empty()) {
    std::FILE* out = std::fopen(csv.c_str(), "w");
    if (out == nullptr) {
      std::fprintf(stderr, "mink_bench_sleep: cannot write %s\n", csv.c_str());
      return 1;
    }
    std::fprintf(out, "case,size,implementation,median_ns\n");
    std::fprintf(out, "sleeping_boxes,%zu,minkowski-asleep,%.0f\n", bodies, asleep_ns);
    std::fprintf(out, "sleeping_boxes,%zu,minkowski-awake,%.0f\n", bodies, awake_ns);
    std::fclose(out);
  }
  return 0;
}
