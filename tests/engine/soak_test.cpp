// The soak at CI size (see soak.hpp; `make soak` runs it at full length): two randomised
// scenes, each at 1 and 2 workers.
#include <gtest/gtest.h>

#include "soak.hpp"

namespace {

using namespace mink;

void expect_soak_holds(std::uint64_t seed, int steps) {
  soak::SoakResult results[2];
  for (const int workers : {1, 2}) {
    soak::SoakOptions options;
    options.seed = seed;
    options.steps = steps;
    options.workers = workers;
    const soak::SoakResult r = soak::run_soak(options);
    soak::print_soak(options, r, stdout);
    EXPECT_EQ(r.steps, steps);
    EXPECT_EQ(r.non_finite, 0u) << "seed " << seed << ", " << workers << " workers";
    // Nothing in it is beyond the solver: the divergence stop never acts.
    EXPECT_EQ(r.stopped, 0u) << "seed " << seed << ", " << workers << " workers";
    EXPECT_EQ(r.escaped, 0u) << "seed " << seed << ", " << workers << " workers";
    EXPECT_GE(r.quiet_phases, 1);
    EXPECT_EQ(r.energy_violations, 0u)
        << "seed " << seed << ": energy rose by " << r.worst_energy_gain << " J in a quiet phase";
    // Churn happened: bodies, joints and bullets were made and destroyed.
    EXPECT_GT(r.bodies_destroyed, 10u);
    EXPECT_GT(r.joints_created, 5u);
    EXPECT_GT(r.bullets_fired, 5u);
#ifndef MINK_SANITIZED_BUILD
    // Memory flat after warm-up: within 4 MB (allocator slack) of its level then. Not under
    // the sanitizers: ASan holds freed blocks in its quarantine and TSan maps shadow memory,
    // so resident memory there grows with churn alone; LeakSanitizer checks for leaks instead.
    EXPECT_LE(r.peak_rss_kb, r.warm_rss_kb + 4096) << "seed " << seed;
#endif
    results[workers - 1] = r;
  }
  EXPECT_EQ(results[0].final_hash, results[1].final_hash) << "seed " << seed;
}

TEST(Soak, RandomisedSceneHoldsItsInvariants) {
  expect_soak_holds(1, test::long_run(3000, 1500));
}

TEST(Soak, AnotherSeedHoldsItsInvariants) {
  expect_soak_holds(2, test::long_run(3000, 1500));
}

}  // namespace
