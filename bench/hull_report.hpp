#pragma once

#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace mink::bench {

// A benchmark labelled with this prefix returned a hull that differs from the exact one.
inline constexpr std::string_view kWrongHullLabel = "WRONG HULL";

struct HullBenchmarkKey {
  std::string case_name;
  std::size_t size = 0;
  std::string implementation;
};

// Takes Google Benchmark's results for the hull benchmarks: prints a line per finished
// benchmark, appends its median to the CSV at once (so an interrupted run keeps what it
// measured), and at the end prints, per case, the median times and their ratios to CGAL.
class HullReporter : public benchmark::BenchmarkReporter {
 public:
  // Cases and implementations in the order the tables list them. An empty csv_path writes no
  // CSV.
  HullReporter(std::vector<std::string> case_names, std::vector<std::string> implementations,
               const std::string& csv_path);

  void add_benchmark(const std::string& benchmark_name, HullBenchmarkKey key);

  bool ReportContext(const Context& context) override;
  void ReportRuns(const std::vector<Run>& runs) override;
  void Finalize() override;

  // Benchmarks that failed or built a wrong hull.
  std::size_t problem_count() const { return problems_.size(); }
  bool csv_ok() const { return csv_ok_; }

 private:
  void record_median(const HullBenchmarkKey& key, const Run& run, std::int64_t builds);
  void print_case_tables(std::ostream& out, const std::string& case_name) const;

  std::vector<std::string> case_names_;
  std::vector<std::string> implementations_;
  std::map<std::string, HullBenchmarkKey> keys_;
  // (case, size) -> implementation -> median nanoseconds.
  std::map<std::pair<std::string, std::size_t>, std::map<std::string, double>> medians_;
  std::vector<std::string> problems_;
  // Google Benchmark reports the repetitions and their aggregates in separate calls; these carry
  // what the first call learnt over to the second, by benchmark name.
  std::map<std::string, std::int64_t> builds_;
  std::set<std::string> failed_;
  std::string csv_path_;
  std::ofstream csv_;
  bool csv_ok_ = true;
};

}  // namespace mink::bench
