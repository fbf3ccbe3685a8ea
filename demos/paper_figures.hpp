#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "mink/render/gl_backend.hpp"
#include "mink/render/renderer.hpp"

namespace mink::cli {

struct PaperSettings {
  std::uint64_t seed = 2013;  // the paper's point sets, as `mink demo` uses
  std::size_t count = 500;
  int width = 1200;
  int height = 700;
  GlBackend backend = GlBackend::osmesa;
};

// One of the paper's figures: its file name, a caption, and how to draw it (null while the
// layer it needs is not built yet, with `missing` saying which).
struct PaperFigure {
  std::string file;
  std::string caption;
  std::function<void(Renderer&, const PaperSettings&)> draw;
  std::string missing;
};

// Figures 8-13 in order.
std::vector<PaperFigure> paper_figures();

}  // namespace mink::cli
