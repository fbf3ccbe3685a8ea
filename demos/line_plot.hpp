#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "mink/engine/debug_draw.hpp"
#include "mink/render/gl_backend.hpp"

namespace mink::cli {

// One series over the steps of a run: values[i] belongs to step first_step + i.
struct PlotLine {
  std::string name;
  Color color;
  bool dashed = false;  // drawn over a solid line of equal values, it leaves that one visible
  std::vector<double> values;
};

// One plot: its lines share the axes, x the step from 0, y from 0 up past the largest value.
struct PlotPanel {
  std::string title;
  std::vector<PlotLine> lines;
  long long first_step = 1;
  bool whole_numbers = false;  // counts: whole tick values
};

// Draws the panels one above the other (1000 x 520 pixels each) with the render layer and
// writes them to `file` as a PNG.
void write_line_plot(const std::vector<PlotPanel>& panels, GlBackend backend,
                     const std::filesystem::path& file);

}  // namespace mink::cli
