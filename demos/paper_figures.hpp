#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "mink/narrowphase/gjk_overlap.hpp"
#include "mink/narrowphase/simplex.hpp"
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

// One of the paper's figures: its file name, a caption, and how to draw it.
struct PaperFigure {
  std::string file;
  std::string caption;
  std::function<void(Renderer&, const PaperSettings&)> draw;
};

// Figures 8-13 in order.
std::vector<PaperFigure> paper_figures();

// The pair of hulls figures 12 and 13 show: hull A (Chan) and hull B (divide and conquer) of
// the paper's point sets, each scaled about its own centroid (eq. 6) and then translated
// (eq. 5) so that they overlap or, when `apart`, lie on either side of a vertical gap.
struct GjkPicture {
  bool apart = false;
  Vec2 scale_a{1, 1};
  Vec2 scale_b{1, 1};
  Vec2 offset_a{0, 0};
  Vec2 offset_b{0, 0};
  std::vector<Vec2> original_a;  // the hulls before scale and translate, counter-clockwise
  std::vector<Vec2> original_b;
  std::vector<Vec2> hull_a;  // world, counter-clockwise, after scale and translate
  std::vector<Vec2> hull_b;
  OverlapResult gjk;             // the paper's boolean GJK
  Real distance = 0;             // between hull_a and hull_b by GJK distance, 0 when overlapping
  Simplex simplex;               // its final simplex, world points of A - B
  std::vector<Vec2> difference;  // A - B, built explicitly
};
GjkPicture gjk_picture(const PaperSettings& settings, bool apart);

// Figure 13's panel `index` of `count` for one picture: A - B filled with
// kDifferenceFill, the final simplex, and the origin as a kOriginMarker dot of
// kOriginMarkerPixels diameter.
inline constexpr Color kDifferenceFill{0.82f, 0.88f, 0.97f, 1};
inline constexpr Color kOriginMarker{0.85f, 0.05f, 0.1f, 1};
inline constexpr float kOriginMarkerPixels = 11;
void draw_difference_panel(Renderer& r, int count, int index, const GjkPicture& picture);

}  // namespace mink::cli
