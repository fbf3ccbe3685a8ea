// Hull build time against the number of points: the paper's figure 11 (Chan against divide and
// conquer) extended to every Minkowski hull algorithm, the Akl-Toussaint prefilter, CGAL and
// Qhull, on four point distributions and n = 10^2 ... 10^7.
//
// Own flags (the rest go to Google Benchmark, e.g. --benchmark_filter):
//   --csv=PATH               write case,size,implementation,median_ns to PATH
//   --max-size=N             only sizes up to N (quick runs)
//   --implementations=A,B    only these implementations (names as in the CSV)

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hull_report.hpp"
#include "library_hulls.hpp"
#include "mink/geometry/convex_hull.hpp"
#include "mink/geometry/orientation.hpp"
#include "mink/geometry/point_sets.hpp"

namespace mink::bench {
namespace {

constexpr std::array kCases = {PointDistribution::uniform_disk, PointDistribution::uniform_square,
                               PointDistribution::gaussian, PointDistribution::on_circle};
constexpr std::size_t kSmallestSize = 100;
constexpr std::size_t kLargestSize = 10'000'000;

// Jarvis costs about n * h orientation tests; beyond this many a single build takes over a
// second, too long to repeat.
constexpr double kJarvisWorkLimit = 5e8;

enum class Library { minkowski, cgal, qhull };

struct Implementation {
  std::string name;
  Library library = Library::minkowski;
  HullAlgorithm algorithm = HullAlgorithm::chan;  // Minkowski only
  bool prefilter = false;                         // Minkowski only
};

std::vector<Implementation> all_implementations() {
  std::vector<Implementation> implementations;
  for (HullAlgorithm algorithm : all_hull_algorithms()) {
    implementations.push_back({std::string(to_string(algorithm)), Library::minkowski, algorithm});
  }
  for (HullAlgorithm algorithm : {HullAlgorithm::chan, HullAlgorithm::divide_conquer}) {
    implementations.push_back(
        {std::string(to_string(algorithm)) + "+prefilter", Library::minkowski, algorithm, true});
  }
  implementations.push_back({"cgal", Library::cgal});
  implementations.push_back({"qhull", Library::qhull});
  return implementations;
}

// Expected hull size of n random points (asymptotic formulas from the literature on random
// polytopes); only used to decide where Jarvis is affordable.
double expected_hull_size(PointDistribution distribution, std::size_t n) {
  const double count = static_cast<double>(n);
  switch (distribution) {
    case PointDistribution::uniform_disk:
      return 3.38 * std::cbrt(count);
    case PointDistribution::uniform_square:
      return 8.0 / 3.0 * std::log(count);
    case PointDistribution::gaussian:
      return 2 * std::sqrt(2 * std::numbers::pi * std::log(count));
    default:
      return count;  // on a circle every point is a vertex
  }
}

bool worth_measuring(const Implementation& implementation, PointDistribution distribution,
                     std::size_t n) {
  if (implementation.library != Library::minkowski ||
      implementation.algorithm != HullAlgorithm::jarvis) {
    return true;
  }
  return static_cast<double>(n) * expected_hull_size(distribution, n) <= kJarvisWorkLimit;
}

// One fixed seed per (case, size): every implementation and every run sees the same points.
std::uint64_t seed_for(PointDistribution distribution, std::size_t n) {
  return 0x4d696e6b00000000ULL + static_cast<std::uint64_t>(distribution) * 1'000'000'007ULL + n;
}

// Everything derived from one point set, prepared outside the timed regions.
struct PointSet {
  PointSet(PointDistribution distribution_, std::size_t size_)
      : distribution(distribution_),
        size(size_),
        points(generate_points(distribution_, size_, seed_for(distribution_, size_))),
        cgal(points),
        qhull(points) {
    // The exact hull every result is checked against: CGAL's, independent of Minkowski,
    // rotated to Minkowski's canonical start (lowest x, then lowest y).
    cgal.build();
    exact_hull = cgal.vertices();
    std::rotate(exact_hull.begin(),
                std::min_element(exact_hull.begin(), exact_hull.end(), lex_less), exact_hull.end());
  }

  PointDistribution distribution;
  std::size_t size;
  std::vector<Vec2> points;
  CgalHullBuilder cgal;
  QhullHullBuilder qhull;
  std::vector<Vec2> exact_hull;
};

// Benchmarks run in registration order, case by case and size by size, so keeping only the
// current point set generates each one once and bounds the memory at n = 10^7.
PointSet& point_set(PointDistribution distribution, std::size_t size) {
  static std::unique_ptr<PointSet> current;
  if (!current || current->distribution != distribution || current->size != size) {
    current.reset();
    current = std::make_unique<PointSet>(distribution, size);
  }
  return *current;
}

bool same_ring(std::span<const Vec2> a, std::span<const Vec2> b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end());
}

bool same_vertex_set(std::vector<Vec2> a, std::vector<Vec2> b) {
  std::sort(a.begin(), a.end(), lex_less);
  std::sort(b.begin(), b.end(), lex_less);
  return same_ring(a, b);
}

std::string wrong_hull_label(std::size_t found, std::size_t expected) {
  return std::string(kWrongHullLabel) + ": " + std::to_string(found) + " vertices, exact hull " +
         std::to_string(expected);
}

void time_minkowski(benchmark::State& state, const Implementation& implementation,
                    const PointSet& set) {
  const HullOptions options{.prefilter = implementation.prefilter};
  std::optional<ConvexHull> hull;
  for (auto _ : state) {
    hull = build_hull(set.points, implementation.algorithm, options);
    benchmark::DoNotOptimize(hull->vertices().data());
  }
  state.counters["hull_vertices"] = static_cast<double>(hull->size());
  if (!same_ring(hull->vertices(), set.exact_hull)) {
    state.SetLabel(wrong_hull_label(hull->size(), set.exact_hull.size()));
  }
}

void time_cgal(benchmark::State& state, PointSet& set) {
  CgalHullBuilder& builder = set.cgal;
  std::size_t vertex_count = 0;
  for (auto _ : state) {
    vertex_count = builder.build();
    benchmark::DoNotOptimize(vertex_count);
  }
  state.counters["hull_vertices"] = static_cast<double>(vertex_count);
}

void time_qhull(benchmark::State& state, PointSet& set) {
  QhullHullBuilder& builder = set.qhull;
  std::size_t vertex_count = 0;
  for (auto _ : state) {
    vertex_count = builder.build();
    benchmark::DoNotOptimize(vertex_count);
  }
  state.counters["hull_vertices"] = static_cast<double>(vertex_count);
  // Qhull works in floating point and merges nearly collinear edges, so it may legitimately
  // drop vertices the exact hull keeps; say so rather than call it wrong.
  if (!same_vertex_set(builder.vertices(), set.exact_hull)) {
    state.SetLabel("differs from the exact hull (" + std::to_string(vertex_count) + " vs " +
                   std::to_string(set.exact_hull.size()) + " vertices)");
  }
}

void time_hull(benchmark::State& state, const Implementation& implementation,
               PointDistribution distribution, std::size_t size) {
  try {
    PointSet& set = point_set(distribution, size);
    switch (implementation.library) {
      case Library::minkowski:
        time_minkowski(state, implementation, set);
        break;
      case Library::cgal:
        time_cgal(state, set);
        break;
      case Library::qhull:
        time_qhull(state, set);
        break;
    }
  } catch (const std::exception& error) {
    state.SkipWithError(error.what());
  }
}

// Small sets: many builds per repetition and many repetitions, since each build is short and
// noisy. Large sets: few repetitions of single builds, to keep the whole run near ten minutes.
void set_repetitions(benchmark::internal::Benchmark* benchmark,
                     const Implementation& implementation, PointDistribution distribution,
                     std::size_t size) {
  benchmark->Unit(benchmark::kNanosecond);
  if (size >= 10'000'000) {
    // Qhull spends microseconds per hull vertex merging nearly collinear edges: with millions
    // of vertices (points on a circle) one build takes over a minute, so it runs once.
    const bool slow_qhull =
        implementation.library == Library::qhull && expected_hull_size(distribution, size) > 1e6;
    benchmark->MinTime(0.1)->Repetitions(slow_qhull ? 1 : 3);
  } else if (size >= 1'000'000) {
    benchmark->MinTime(0.1)->Repetitions(5);
  } else {
    benchmark->MinTime(0.05)->Repetitions(9);
  }
}

struct Options {
  std::string csv_path;
  std::size_t max_size = kLargestSize;
  std::vector<std::string> implementations;  // empty: all
};

std::vector<std::string> split_list(std::string_view text) {
  std::vector<std::string> items;
  while (!text.empty()) {
    const std::size_t comma = text.find(',');
    const std::string_view item = text.substr(0, comma);
    if (!item.empty()) items.emplace_back(item);
    if (comma == std::string_view::npos) break;
    text.remove_prefix(comma + 1);
  }
  return items;
}

// Removes this program's own flags from argv, leaving Google Benchmark's.
std::optional<Options> take_own_flags(int& argc, char** argv) {
  Options options;
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string_view argument = argv[i];
    auto value_of = [&](std::string_view flag) -> std::optional<std::string_view> {
      if (!argument.starts_with(flag)) return std::nullopt;
      return argument.substr(flag.size());
    };
    if (const auto path = value_of("--csv=")) {
      options.csv_path = std::string(*path);
    } else if (const auto size = value_of("--max-size=")) {
      const auto [end, error] =
          std::from_chars(size->data(), size->data() + size->size(), options.max_size);
      if (error != std::errc() || end != size->data() + size->size()) {
        std::fprintf(stderr, "mink_bench_hull: --max-size needs a number, got '%s'\n", argv[i]);
        return std::nullopt;
      }
    } else if (const auto list = value_of("--implementations=")) {
      options.implementations = split_list(*list);
    } else {
      argv[kept++] = argv[i];
    }
  }
  argc = kept;
  return options;
}

int run(int argc, char** argv) {
  const std::optional<Options> options = take_own_flags(argc, argv);
  if (!options) return 2;
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;

  std::vector<Implementation> implementations = all_implementations();
  for (const std::string& wanted : options->implementations) {
    const bool known = std::any_of(implementations.begin(), implementations.end(),
                                   [&](const Implementation& i) { return i.name == wanted; });
    if (!known) {
      std::fprintf(stderr, "mink_bench_hull: unknown implementation '%s'\n", wanted.c_str());
      return 2;
    }
  }
  if (!options->implementations.empty()) {
    std::erase_if(implementations, [&](const Implementation& i) {
      return std::find(options->implementations.begin(), options->implementations.end(), i.name) ==
             options->implementations.end();
    });
  }

  std::vector<std::string> case_names;
  for (PointDistribution distribution : kCases) case_names.emplace_back(to_string(distribution));
  std::vector<std::string> implementation_names;
  for (const Implementation& implementation : implementations) {
    implementation_names.push_back(implementation.name);
  }
  HullReporter reporter(case_names, implementation_names, options->csv_path);
  if (!reporter.csv_ok()) {
    std::fprintf(stderr, "mink_bench_hull: cannot write %s\n", options->csv_path.c_str());
    return 1;
  }

  for (PointDistribution distribution : kCases) {
    for (std::size_t size = kSmallestSize; size <= std::min(options->max_size, kLargestSize);
         size *= 10) {
      for (const Implementation& implementation : implementations) {
        if (!worth_measuring(implementation, distribution, size)) continue;
        const std::string name = "hull/" + std::string(to_string(distribution)) + "/" +
                                 std::to_string(size) + "/" + implementation.name;
        auto* benchmark = benchmark::RegisterBenchmark(
            name.c_str(), [implementation, distribution, size](benchmark::State& state) {
              time_hull(state, implementation, distribution, size);
            });
        set_repetitions(benchmark, implementation, distribution, size);
        reporter.add_benchmark(name,
                               {std::string(to_string(distribution)), size, implementation.name});
      }
    }
  }

  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  if (!reporter.csv_ok()) return 1;
  return reporter.problem_count() == 0 ? 0 : 3;
}

}  // namespace
}  // namespace mink::bench

int main(int argc, char** argv) {
  return mink::bench::run(argc, argv);
}
