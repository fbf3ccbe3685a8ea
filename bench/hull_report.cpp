#include "hull_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <ostream>
#include <set>

namespace mink::bench {

namespace {

constexpr int kNameWidth = 26;
constexpr int kColumnWidth = 11;

std::string format_duration(double nanoseconds) {
  struct Unit {
    double scale;
    const char* suffix;
  };
  constexpr Unit kUnits[] = {{1e9, "s"}, {1e6, "ms"}, {1e3, "us"}, {1, "ns"}};
  for (const Unit& unit : kUnits) {
    // Compared with the scale less half a unit in the third digit, so 999.6 us prints as 1 ms.
    if (nanoseconds >= unit.scale * 0.9995 || unit.scale == 1) {
      char text[32];
      std::snprintf(text, sizeof text, "%.3g %s", nanoseconds / unit.scale, unit.suffix);
      return text;
    }
  }
  return {};
}

std::string format_size(std::size_t size) {
  // Powers of ten read better as 10^k than as long digit strings.
  int exponent = 0;
  std::size_t rest = size;
  while (rest >= 10 && rest % 10 == 0) {
    rest /= 10;
    ++exponent;
  }
  if (rest == 1 && exponent >= 2) return "10^" + std::to_string(exponent);
  return std::to_string(size);
}

}  // namespace

HullReporter::HullReporter(std::vector<std::string> case_names,
                           std::vector<std::string> implementations, const std::string& csv_path)
    : case_names_(std::move(case_names)),
      implementations_(std::move(implementations)),
      csv_path_(csv_path) {
  if (csv_path.empty()) return;
  const std::filesystem::path parent = std::filesystem::path(csv_path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
  csv_.open(csv_path, std::ios::trunc);
  csv_ << "case,size,implementation,median_ns\n" << std::flush;
  csv_ok_ = static_cast<bool>(csv_);
}

void HullReporter::add_benchmark(const std::string& benchmark_name, HullBenchmarkKey key) {
  keys_.emplace(benchmark_name, std::move(key));
}

bool HullReporter::ReportContext(const Context& context) {
  std::ostream& out = GetOutputStream();
  PrintBasicContext(&out, context);
  out << "Median CPU time of one whole hull build over the repetitions; points generated "
         "outside the timed region.\n\n";
  return true;
}

void HullReporter::ReportRuns(const std::vector<Run>& runs) {
  if (runs.empty()) return;
  const std::string& name = runs.front().run_name.function_name;
  const auto found = keys_.find(name);
  if (found == keys_.end()) return;
  const HullBenchmarkKey& key = found->second;

  for (const Run& run : runs) {
    if (run.run_type == Run::RT_Iteration) {
      // A benchmark that failed in any repetition gets no row: a median of the survivors
      // would not be the time of this implementation on this input.
      if (run.error_occurred && failed_.insert(name).second) {
        GetOutputStream() << std::left << std::setw(16) << key.case_name << std::right
                          << std::setw(9) << format_size(key.size) << "  " << std::left
                          << std::setw(kNameWidth) << key.implementation
                          << "not measured: " << run.error_message << '\n'
                          << std::flush;
        problems_.push_back(name + ": " + run.error_message);
      }
      builds_[name] += run.iterations;
      // A single repetition gets no aggregates; its time is its own median.
      if (run.repetitions == 1 && !run.error_occurred) record_median(key, run, builds_[name]);
    } else if (run.aggregate_name == "median" && !failed_.contains(name)) {
      record_median(key, run, builds_[name]);
    }
  }
}

void HullReporter::record_median(const HullBenchmarkKey& key, const Run& run, std::int64_t builds) {
  // The runs are reported in nanoseconds (the default unit), per iteration, i.e. per build.
  const double median_ns = run.GetAdjustedCPUTime();
  medians_[{key.case_name, key.size}][key.implementation] = median_ns;
  if (csv_.is_open()) {
    csv_ << key.case_name << ',' << key.size << ',' << key.implementation << ','
         << std::llround(median_ns) << '\n'
         << std::flush;
    csv_ok_ = csv_ok_ && static_cast<bool>(csv_);
  }

  std::ostream& out = GetOutputStream();
  out << std::left << std::setw(16) << key.case_name << std::right << std::setw(9)
      << format_size(key.size) << "  " << std::left << std::setw(kNameWidth) << key.implementation
      << std::right << std::setw(10) << format_duration(median_ns);
  const auto hull_vertices = run.counters.find("hull_vertices");
  if (hull_vertices != run.counters.end()) {
    out << "  hull " << std::setw(8) << std::llround(hull_vertices->second.value);
  }
  out << "  (" << run.repetitions << (run.repetitions == 1 ? " repetition, " : " repetitions, ")
      << builds << (builds == 1 ? " build)" : " builds)");
  if (!run.report_label.empty()) out << "  " << run.report_label;
  out << '\n' << std::flush;
  if (run.report_label.starts_with(kWrongHullLabel)) {
    problems_.push_back(run.run_name.function_name + ": " + run.report_label);
  }
}

void HullReporter::print_case_tables(std::ostream& out, const std::string& case_name) const {
  std::vector<std::size_t> sizes;
  std::set<std::string> measured;
  for (const auto& [case_and_size, by_implementation] : medians_) {
    if (case_and_size.first != case_name) continue;
    sizes.push_back(case_and_size.second);
    for (const auto& entry : by_implementation) measured.insert(entry.first);
  }
  if (sizes.empty()) return;

  auto print_header = [&](const std::string& title) {
    out << std::left << std::setw(kNameWidth) << title << std::right;
    for (std::size_t size : sizes) out << std::setw(kColumnWidth) << format_size(size);
    out << '\n';
  };
  auto median_of = [&](std::size_t size, const std::string& implementation) -> const double* {
    const auto& by_implementation = medians_.at({case_name, size});
    const auto found = by_implementation.find(implementation);
    return found == by_implementation.end() ? nullptr : &found->second;
  };

  print_header(case_name + ": median time");
  for (const std::string& implementation : implementations_) {
    if (!measured.contains(implementation)) continue;
    out << "  " << std::left << std::setw(kNameWidth - 2) << implementation << std::right;
    for (std::size_t size : sizes) {
      const double* median = median_of(size, implementation);
      out << std::setw(kColumnWidth) << (median ? format_duration(*median) : "-");
    }
    out << '\n';
  }

  print_header(case_name + ": time / cgal");
  for (const std::string& implementation : implementations_) {
    if (!measured.contains(implementation)) continue;
    out << "  " << std::left << std::setw(kNameWidth - 2) << implementation << std::right;
    for (std::size_t size : sizes) {
      const double* median = median_of(size, implementation);
      const double* cgal = median_of(size, "cgal");
      if (median && cgal && *cgal > 0) {
        out << std::setw(kColumnWidth) << std::fixed << std::setprecision(2) << *median / *cgal;
        out.unsetf(std::ios::floatfield);
      } else {
        out << std::setw(kColumnWidth) << "-";
      }
    }
    out << '\n';
  }
  out << '\n';
}

void HullReporter::Finalize() {
  std::ostream& out = GetOutputStream();
  out << "\nSummary (\"-\": not measured; ratios above 1 are slower than CGAL)\n\n";
  for (const std::string& case_name : case_names_) print_case_tables(out, case_name);
  if (!problems_.empty()) {
    out << "Problems:\n";
    for (const std::string& problem : problems_) out << "  " << problem << '\n';
  }
  if (csv_.is_open()) {
    csv_.close();
    out << (csv_ok_ ? "Wrote " : "FAILED to write ") << csv_path_ << '\n';
  }
  out << std::flush;
}

}  // namespace mink::bench
