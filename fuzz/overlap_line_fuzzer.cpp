// The line reader of `mink overlap` on any bytes: overlap_line never throws (bad lines become
// {"error": ...} lines) and always prints one JSON object. An answer is self-consistent
// (overlap with distance 0, separation with depth 0, a unit normal, finite numbers), and
// swapping the two point sets gives the same verdict.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "overlap_query.hpp"

namespace {

[[noreturn]] void fail(const char* what, const std::string& line) {
  std::fprintf(stderr, "fuzz_overlap_line: %s\n  output: %s\n", what, line.c_str());
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 8192) return 0;
  const std::string_view line(reinterpret_cast<const char*>(data), size);
  bool ok = false;
  const std::string output = mink::cli::overlap_line(line, 1, ok);
  const nlohmann::json answer = nlohmann::json::parse(output, nullptr, false);
  if (answer.is_discarded() || !answer.is_object()) fail("output is not a JSON object", output);
  if (!ok) {
    if (!answer.contains("error") || !answer["error"].is_string()) fail("no error text", output);
    return 0;
  }
  const bool overlap = answer.at("overlap").get<bool>();
  const double distance = answer.at("distance").get<double>();
  const double depth = answer.at("depth").get<double>();
  const double nx = answer.at("normal").at(0).get<double>();
  const double ny = answer.at("normal").at(1).get<double>();
  if (!std::isfinite(distance) || !std::isfinite(depth) || !std::isfinite(nx) ||
      !std::isfinite(ny)) {
    fail("a non-finite number", output);
  }
  if (distance < 0 || depth < 0) fail("a negative distance or depth", output);
  if (overlap && distance != 0) fail("overlapping at a positive distance", output);
  if (!overlap && depth != 0) fail("apart with a positive depth", output);
  const double normal_length = std::hypot(nx, ny);
  if ((distance > 0 || depth > 0) && std::abs(normal_length - 1) > 1e-9) {
    fail("the normal is not a unit vector", output);
  }
  if (answer.at("iterations").get<int>() < 0) fail("negative iterations", output);

  // The same query with a and b swapped: the verdict is exact, so it must not change.
  const nlohmann::json query = nlohmann::json::parse(line);
  nlohmann::json swapped = nlohmann::json::object();
  swapped["a"] = query.at("b");
  swapped["b"] = query.at("a");
  bool swapped_ok = false;
  const std::string swapped_output = mink::cli::overlap_line(swapped.dump(), 1, swapped_ok);
  if (!swapped_ok) fail("the swapped query failed", swapped_output);
  const nlohmann::json swapped_answer = nlohmann::json::parse(swapped_output);
  if (swapped_answer.at("overlap").get<bool>() != overlap) {
    fail("the swapped query gives another verdict", output + " vs " + swapped_output);
  }
  return 0;
}
