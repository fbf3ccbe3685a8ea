// `mink_soak [SCENES [STEPS [FIRST_SEED]]]`: the full soak (make soak). Runs SCENES randomised
// scenes (default 10) of STEPS steps each (default 10^4, so 10^5 steps in all) at 1 and 2
// workers, prints each run's figures and a total, and exits 1 when an invariant failed.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "soak.hpp"

int main(int argc, char** argv) {
  const int scenes = argc > 1 ? std::atoi(argv[1]) : 10;
  const int steps = argc > 2 ? std::atoi(argv[2]) : 10'000;
  const std::uint64_t first_seed = argc > 3 ? std::strtoull(argv[3], nullptr, 10) : 1;
  if (scenes < 1 || steps < 1200) {
    std::fprintf(stderr, "usage: mink_soak [SCENES >= 1 [STEPS >= 1200 [FIRST_SEED]]]\n");
    return 2;
  }
  int failures = 0;
  long long total_steps = 0;
  double worst_gain = 0;
  long worst_growth = 0;
  for (int scene = 0; scene < scenes; ++scene) {
    std::uint64_t hashes[2] = {0, 0};
    for (const int workers : {1, 2}) {
      mink::soak::SoakOptions options;
      options.seed = first_seed + static_cast<std::uint64_t>(scene);
      options.steps = steps;
      options.workers = workers;
      const mink::soak::SoakResult r = mink::soak::run_soak(options);
      mink::soak::print_soak(options, r, stdout);
      std::fflush(stdout);
      total_steps += r.steps;
      worst_gain = std::max(worst_gain, r.worst_energy_gain);
      worst_growth = std::max(worst_growth, r.peak_rss_kb - r.warm_rss_kb);
      const bool failed = r.non_finite != 0 || r.escaped != 0 || r.stopped != 0 ||
                          r.energy_violations != 0 || r.peak_rss_kb > r.warm_rss_kb + 4096;
      if (failed) {
        std::printf("  FAILED\n");
        ++failures;
      }
      hashes[workers - 1] = r.final_hash;
    }
    if (hashes[0] != hashes[1]) {
      std::printf("  FAILED: 1 and 2 workers ended in different states\n");
      ++failures;
    }
  }
  std::printf(
      "soak: %d scenes, %lld steps in all; worst quiet-phase energy gain %.3g J; largest "
      "memory growth after warm-up %ld kB; %d failures\n",
      scenes, total_steps, worst_gain, worst_growth, failures);
  return failures == 0 ? 0 : 1;
}
