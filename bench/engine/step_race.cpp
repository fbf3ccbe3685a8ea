#include "step_race.hpp"

#include <sys/resource.h>

#include <csignal>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <ctime>
#include <exception>
#include <string>

namespace mink::bench {
namespace {

constexpr int kUsage = 2;

struct Options {
  const SuiteScene* scene = nullptr;
  int workers = 1;
  int steps = 0;  // 0: the suite's count
  int warmup = 1;
  int turn_ms = 0;     // 0: no turns
  int turn_steps = 0;  // 0: turns by time (or none)
  std::string samples;
  std::string_view implementation;
  bool sleep_off = false;  // in every scene
  bool profile = false;
};

long long clock_ns(clockid_t clock) {
  timespec t{};
  clock_gettime(clock, &t);
  return static_cast<long long>(t.tv_sec) * 1000000000LL + t.tv_nsec;
}

// A step's time is wall time: with more than one worker the work is spread over threads, and
// waiting for the slowest of them is part of the step. Its CPU time (every thread of the
// process) is kept beside it: on a shared machine the wall time also counts the time the
// process waited for a core, the CPU time does not (at one worker it is the step's time on a
// core of its own; at more it is the work of all workers, spinning included).
struct StepTime {
  long long wall = 0;
  long long cpu = 0;
};

StepTime now() {
  return {clock_ns(CLOCK_MONOTONIC), clock_ns(CLOCK_PROCESS_CPUTIME_ID)};
}

long peak_kib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;  // KiB on Linux
}

// The value of `--name=VALUE` as a whole number of at least `least`, or false after naming the
// bad argument.
bool parse_count(std::string_view arg, std::string_view name, int least, int& out) {
  const std::string_view value = arg.substr(name.size());
  int parsed = 0;
  const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), parsed);
  if (error != std::errc() || end != value.data() + value.size() || parsed < least) {
    std::fprintf(stderr, "%.*s: expected a whole number of at least %d\n",
                 static_cast<int>(arg.size()), arg.data(), least);
    return false;
  }
  out = parsed;
  return true;
}

bool parse(int argc, char** argv, const RaceEngine& engine, Options& options) {
  options.implementation = engine.implementations.front();
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg.starts_with("--workers=")) {
      if (!parse_count(arg, "--workers=", 1, options.workers)) return false;
    } else if (arg.starts_with("--steps=")) {
      if (!parse_count(arg, "--steps=", 1, options.steps)) return false;
    } else if (arg.starts_with("--warmup=")) {
      if (!parse_count(arg, "--warmup=", 0, options.warmup)) return false;
    } else if (arg.starts_with("--turn-ms=")) {
      if (!parse_count(arg, "--turn-ms=", 1, options.turn_ms)) return false;
    } else if (arg.starts_with("--turn-steps=")) {
      if (!parse_count(arg, "--turn-steps=", 2, options.turn_steps)) return false;
    } else if (arg.starts_with("--samples=")) {
      options.samples = std::string(arg.substr(10));
    } else if (arg.starts_with("--implementation=")) {
      const std::string_view name = arg.substr(17);
      const auto& names = engine.implementations;
      if (std::find(names.begin(), names.end(), name) == names.end()) {
        std::fprintf(stderr, "%s: unknown implementation\n", argv[i]);
        return false;
      }
      options.implementation = name;
    } else if (arg == "--profile") {
      options.profile = true;
    } else if (arg == "--sleep=app" || arg == "--sleep=off") {
      options.sleep_off = arg == "--sleep=off";
    } else if (!arg.starts_with("-") && options.scene == nullptr) {
      options.scene = find_suite_scene(arg);
      if (options.scene == nullptr) {
        std::fprintf(stderr, "%s: not a scene of Box2D v3's benchmark suite\n", argv[i]);
        return false;
      }
    } else {
      std::fprintf(stderr, "%s: unknown argument\n", argv[i]);
      return false;
    }
  }
  if (options.scene == nullptr) {
    std::fprintf(stderr,
                 "usage: %s SCENE [--workers=N] [--steps=N] [--warmup=K] "
                 "[--samples=FILE] [--implementation=NAME] [--sleep=app|off] [--profile] "
                 "[--turn-ms=T | --turn-steps=K]\n",
                 argv[0]);
    return false;
  }
  if (options.turn_ms > 0 && options.turn_steps > 0) {
    std::fprintf(stderr, "--turn-ms and --turn-steps: turns are by time or by steps, not both\n");
    return false;
  }
  if (options.steps == 0) options.steps = options.scene->steps;
  if (options.warmup >= options.steps) {
    std::fprintf(stderr, "--warmup=%d: leaves none of the %d steps to time\n", options.warmup,
                 options.steps);
    return false;
  }
  return true;
}

long long median(std::vector<long long> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

int run(const Options& options, const RaceEngine& engine) {
  const long base = peak_kib();
  const RaceRequest request{options.scene, options.workers, options.implementation,
                            !options.sleep_off && !options.scene->sleep_off};
  const std::unique_ptr<RaceWorld> world = engine.build(request);
  if (!world) {
    std::printf("%.*s: no scene %.*s; skipped\n", static_cast<int>(options.implementation.size()),
                options.implementation.data(), static_cast<int>(options.scene->name.size()),
                options.scene->name.data());
    return 0;
  }
  std::vector<long long> times, cpu_times;
  std::vector<int> timed_steps;
  times.reserve(static_cast<std::size_t>(options.steps));
  cpu_times.reserve(static_cast<std::size_t>(options.steps));
  long long turn_end = 0;  // wall time at which the current turn is over
  std::vector<std::pair<std::string, double>> phases;  // summed over the timed steps
  for (int i = 0; i < options.steps; ++i) {
    bool turn_starts = false;
    if (options.turn_steps > 0 ? i % options.turn_steps == 0
                               : options.turn_ms > 0 && clock_ns(CLOCK_MONOTONIC) >= turn_end) {
      std::raise(SIGSTOP);
      turn_starts = true;
      turn_end = clock_ns(CLOCK_MONOTONIC) + options.turn_ms * 1000000LL;
    }
    const StepTime start = now();
    world->step(i);
    const StepTime end = now();
    if (i >= options.warmup && !turn_starts) {
      times.push_back(end.wall - start.wall);
      cpu_times.push_back(end.cpu - start.cpu);
      timed_steps.push_back(i);
      if (options.profile) {
        const auto step_phases = world->profile();
        if (phases.empty()) {
          for (const auto& [name, ms] : step_phases) phases.emplace_back(name, 0.0);
        }
        for (std::size_t k = 0; k < step_phases.size(); ++k)
          phases[k].second += step_phases[k].second;
      }
    }
  }
  const RaceCounts counts = world->counts();
  const long peak = peak_kib();

  if (!options.samples.empty()) {
    FILE* out = std::fopen(options.samples.c_str(), "a");
    if (out == nullptr) {
      std::fprintf(stderr, "--samples=%s: cannot append to it\n", options.samples.c_str());
      return 1;
    }
    for (std::size_t i = 0; i < times.size(); ++i) {
      std::fprintf(out, "%lld %lld %d\n", times[i], cpu_times[i], timed_steps[i]);
    }
    std::fclose(out);
  }
  std::printf(
      "race scene=%.*s workers=%d implementation=%.*s steps=%d timed=%zu median_ns=%lld "
      "cpu_median_ns=%lld peak_kib=%ld base_kib=%ld bodies=%lld shapes=%lld joints=%lld "
      "contacts=%lld\n",
      static_cast<int>(options.scene->name.size()), options.scene->name.data(), options.workers,
      static_cast<int>(options.implementation.size()), options.implementation.data(), options.steps,
      times.size(), median(times), median(cpu_times), peak, base, counts.bodies, counts.shapes,
      counts.joints, counts.contacts);
  // Each line names its run: the runs of a scene take turns on one output.
  for (const auto& [name, ms] : phases) {
    std::printf("phase scene=%.*s workers=%d implementation=%.*s name=%s ms=%.4f\n",
                static_cast<int>(options.scene->name.size()), options.scene->name.data(),
                options.workers, static_cast<int>(options.implementation.size()),
                options.implementation.data(), name.c_str(),
                ms / static_cast<double>(times.size()));
  }
  return 0;
}

}  // namespace

int race_main(int argc, char** argv, const RaceEngine& engine) {
  if (argc == 2 && std::string_view(argv[1]) == "--list") {
    for (const SuiteScene& scene : kSuite) {
      std::printf("%.*s %d\n", static_cast<int>(scene.name.size()), scene.name.data(), scene.steps);
    }
    return 0;
  }
  Options options;
  if (!parse(argc, argv, engine, options)) return kUsage;
  try {
    return run(options, engine);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s %.*s: %s\n", argv[0], static_cast<int>(options.scene->name.size()),
                 options.scene->name.data(), e.what());
    return 1;
  }
}

}  // namespace mink::bench
