#include "paper_figures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "mink/geometry/chan.hpp"
#include "mink/geometry/divide_conquer.hpp"
#include "mink/geometry/hull_trace.hpp"
#include "mink/geometry/point_sets.hpp"
#include "mink/geometry/polygon.hpp"
#include "mink/geometry/transform.hpp"
#include "mink/narrowphase/gjk_distance.hpp"
#include "mink/narrowphase/minkowski_difference.hpp"
#include "mink/render/bitmap_font.hpp"
#include "text_wrap.hpp"

namespace mink::cli {

namespace {

// The paper's canvas: points in [0, 400]^2.
const Vec2 kCanvasLower(0, 0);
const Vec2 kCanvasUpper(400, 400);

constexpr Color kBackground{1, 1, 1, 1};
constexpr Color kInk{0.08f, 0.08f, 0.1f, 1};
constexpr Color kFaint{0.55f, 0.55f, 0.6f, 1};
constexpr Color kNone{0, 0, 0, 0};
constexpr Color kSetA{0.13f, 0.4f, 0.8f, 1};
constexpr Color kSetB{0.85f, 0.4f, 0.05f, 1};
constexpr Color kUpper{0.8f, 0.1f, 0.45f, 1};
constexpr Color kLower{0.1f, 0.6f, 0.3f, 1};
constexpr Color kSimplex{0.1f, 0.55f, 0.2f, 1};

// Room for four title lines at text scale 2.
constexpr Real kTitleHeight = 84;
// Room around the canvas for labels just outside it.
constexpr Real kCanvasMargin = 40;

Color with_alpha(Color c, float a) {
  c.a = a;
  return c;
}

// A distinct, darkish colour per group: hues a golden angle apart.
Color group_color(std::size_t index) {
  const double hue = std::fmod(index * 0.618033988749895, 1.0) * 6;
  const double x = 1 - std::abs(std::fmod(hue, 2.0) - 1);
  double r = 0, g = 0, b = 0;
  switch (static_cast<int>(hue)) {
    case 0:
      r = 1, g = x;
      break;
    case 1:
      r = x, g = 1;
      break;
    case 2:
      g = 1, b = x;
      break;
    case 3:
      g = x, b = 1;
      break;
    case 4:
      r = x, b = 1;
      break;
    default:
      r = 1, b = x;
      break;
  }
  const auto shade = [](double v) { return static_cast<float>(0.15 + 0.7 * v); };
  return Color{shade(r), shade(g), shade(b), 1};
}

// Splits the frame into `count` side-by-side panels, each with a title line on top, and
// points the camera at the world box [lower, upper] inside panel `index`.
void panel_of(Renderer& r, int count, int index, const std::string& title, const Vec2& lower,
              const Vec2& upper, Real margin = kCanvasMargin) {
  const Real width = static_cast<Real>(r.width()) / count;
  const Vec2 top_left(width * index, 0);
  const Vec2 bottom_right(width * (index + 1), r.height());
  r.camera().fit_region(lower, upper, top_left + Vec2(0, kTitleHeight), bottom_right, margin);
  const auto columns =
      static_cast<std::size_t>((width - 24) / (BitmapFont::advance * r.options().text_scale));
  r.draw_screen_text(top_left + Vec2(16, 10), wrap(title, columns), kInk);
}

// A panel showing the paper's 400 x 400 canvas, with its border.
void panel(Renderer& r, int count, int index, const std::string& title) {
  panel_of(r, count, index, title, kCanvasLower, kCanvasUpper);
  const Vec2 canvas[] = {{0, 0}, {400, 0}, {400, 400}, {0, 400}};
  r.draw_polygon(canvas, kNone, kFaint);
}

void points(Renderer& r, std::span<const Vec2> set, Color color, float size = 5) {
  for (const Vec2& p : set) r.draw_point(p, size, color);
}

void outline(Renderer& r, std::span<const Vec2> ring, Color color) {
  if (ring.size() >= 3) {
    r.draw_polygon(ring, kNone, color);
  } else if (ring.size() == 2) {
    r.draw_segment(ring[0], ring[1], color);
  }
}

std::string count_text(std::size_t n, const char* noun, const char* plural = nullptr) {
  return std::to_string(n) + " " +
         (n == 1              ? std::string(noun)
          : plural != nullptr ? plural
                              : std::string(noun) + "s");
}

// A label on a white backing so it reads over points and lines; `world` is the middle of its
// left end.
void label(Renderer& r, const Vec2& world, const std::string& text, Color color) {
  const int scale = r.options().text_scale;
  const Vec2 anchor = r.camera().world_to_pixel(world);
  const Vec2 top_left = anchor - Vec2(0, BitmapFont::glyph_height * scale / 2.0);
  const Vec2 size(BitmapFont::text_width(text) * scale, BitmapFont::glyph_height * scale);
  r.draw_screen_rect(top_left - Vec2(3, 3), top_left + size + Vec2(3, 3), Color{1, 1, 1, 0.85f});
  r.draw_screen_text(top_left, text, color);
}

void figure_8(Renderer& r, const PaperSettings& settings) {
  const auto [set_a, set_b] = paper_point_sets(settings.seed, settings.count);
  panel(r, 2, 0,
        "Fig. 8a  set A, hulled by Chan\n" + count_text(set_a.size(), "point") +
            " in the 400 x 400 canvas, seed " + std::to_string(settings.seed));
  points(r, set_a, kSetA);
  panel(r, 2, 1,
        "Fig. 8b  set B, hulled by divide and conquer\n" + count_text(set_b.size(), "point") +
            " in the 400 x 400 canvas, seed " + std::to_string(settings.seed));
  points(r, set_b, kSetB);
}

void figure_9(Renderer& r, const PaperSettings& settings) {
  const auto [set_a, set_b] = paper_point_sets(settings.seed, settings.count);
  const ChanTrace trace = chan_trace(set_a);
  const int count = static_cast<int>(trace.rounds.size());
  for (int i = 0; i < count; ++i) {
    const ChanRound& round = trace.rounds[static_cast<std::size_t>(i)];
    std::size_t in_play = 0;
    for (const auto& group : round.groups.points) in_play += group.size();
    std::string verdict =
        "the wrap closes: hull of " + count_text(trace.hull.size(), "vertex", "vertices");
    if (!round.closed) {
      std::size_t survivors = 0;
      for (const auto& ring : round.groups.hulls) survivors += ring.size();
      verdict = "no closure in " + std::to_string(round.groups.group_size) + " wrap steps: the " +
                std::to_string(survivors) + " group hull vertices go on to round " +
                std::to_string(round.t + 1);
    }
    panel(r, count, i,
          "Fig. 9" + std::string(1, static_cast<char>('a' + i)) + "  Chan, round t = " +
              std::to_string(round.t) + ", m = " + std::to_string(round.groups.group_size) + ": " +
              count_text(round.groups.hulls.size(), "group") + " of " +
              count_text(in_play, "point") + ", a Graham hull each; " + verdict);
    for (std::size_t g = 0; g < round.groups.hulls.size(); ++g) {
      const Color color = group_color(g);
      const auto& ring = round.groups.hulls[g];
      if (ring.size() >= 3)
        r.draw_polygon(ring, with_alpha(color, 0.12f), with_alpha(color, 0.8f));
      else
        outline(r, ring, color);
      points(r, round.groups.points[g], color, 4);
    }
    if (round.closed) {
      r.draw_polygon(trace.hull.vertices(), kNone, kInk);
      points(r, trace.hull.vertices(), kInk, 8);
    }
  }
}

void figure_10(Renderer& r, const PaperSettings& settings) {
  const auto [set_a, set_b] = paper_point_sets(settings.seed, settings.count);
  const DivideConquerTrace trace = divide_conquer_trace(set_b);
  panel(r, 1, 0,
        "Fig. 10  divide and conquer: halves by x, Melkman hull of each (" +
            count_text(trace.left_hull.size(), "vertex", "vertices") + " | " +
            count_text(trace.right_hull.size(), "vertex", "vertices") + "),\n" +
            "merged by the upper and lower common tangents into " +
            count_text(trace.hull.size(), "vertex", "vertices"));
  // The split between the halves.
  const Real split = (trace.left_points.back().x() + trace.right_points.front().x()) / 2;
  for (Real y = 0; y < 400; y += 16) {
    r.draw_segment(Vec2(split, y), Vec2(split, std::min<Real>(y + 8, 400)), kFaint);
  }
  r.draw_polygon(trace.hull.vertices(), with_alpha(kInk, 0.05f), kNone);
  r.draw_polygon(trace.left_hull, with_alpha(kSetA, 0.1f), kSetA);
  r.draw_polygon(trace.right_hull, with_alpha(kSetB, 0.1f), kSetB);
  points(r, trace.left_points, kSetA, 4);
  points(r, trace.right_points, kSetB, 4);
  const Vec2& upper_left = trace.left_hull[trace.upper_left];
  const Vec2& upper_right = trace.right_hull[trace.upper_right];
  const Vec2& lower_left = trace.left_hull[trace.lower_left];
  const Vec2& lower_right = trace.right_hull[trace.lower_right];
  for (int k = -1; k <= 1; ++k) {  // a thicker stroke: three offset passes
    const Vec2 d(0, k * 1.2 / r.camera().pixels_per_unit());
    r.draw_segment(upper_left + d, upper_right + d, kUpper);
    r.draw_segment(lower_left + d, lower_right + d, kLower);
  }
  for (const Vec2& p : {upper_left, upper_right}) r.draw_point(p, 10, kUpper);
  for (const Vec2& p : {lower_left, lower_right}) r.draw_point(p, 10, kLower);
  // Labels beside the tangents' right ends, above the upper and below the lower one.
  const Real lift = 14 / r.camera().pixels_per_unit();
  const Real gap = 10 / r.camera().pixels_per_unit();
  label(r,
        Vec2(std::max(upper_left.x(), upper_right.x()) + gap,
             std::max<Real>(upper_left.y(), upper_right.y()) + lift),
        "upper tangent", kUpper);
  label(r,
        Vec2(std::max(lower_left.x(), lower_right.x()) + gap,
             std::min<Real>(lower_left.y(), lower_right.y()) - lift),
        "lower tangent", kLower);
  label(r, Vec2(split + gap, 200), "split", kFaint);
}

std::string fixed(Real value, int decimals = 1) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

std::string vec_text(const Vec2& v) {
  char text[80];
  std::snprintf(text, sizeof text, "(%.2f, %.2f)", v.x(), v.y());
  return text;
}

std::string verdict_text(const GjkPicture& picture) {
  std::string text = picture.gjk.overlap ? "GJK: INTERSECT" : "GJK: SEPARATE";
  text += " after " + count_text(static_cast<std::size_t>(picture.gjk.iterations), "support point");
  if (!picture.gjk.overlap) text += ", distance " + fixed(picture.distance);
  return text;
}

void figure_12(Renderer& r, const PaperSettings& settings) {
  for (int i = 0; i < 2; ++i) {
    const GjkPicture picture = gjk_picture(settings, i == 1);
    panel(r, 2, i,
          "Fig. 12" + std::string(1, static_cast<char>('a' + i)) + "  " +
              (picture.apart ? "moved apart" : "overlapping") + ": A scaled by " +
              vec_text(picture.scale_a) + " about its centroid (eq. 6), moved by " +
              vec_text(picture.offset_a) + " (eq. 5); B scaled by " + vec_text(picture.scale_b) +
              ", moved by " + vec_text(picture.offset_b) + "\n" + verdict_text(picture));
    // The hulls before the transforms, faint, for comparison.
    r.draw_polygon(picture.original_a, kNone, with_alpha(kSetA, 0.3f));
    r.draw_polygon(picture.original_b, kNone, with_alpha(kSetB, 0.3f));
    r.draw_polygon(picture.hull_a, with_alpha(kSetA, 0.18f), kSetA);
    r.draw_polygon(picture.hull_b, with_alpha(kSetB, 0.18f), kSetB);
    points(r, picture.hull_a, kSetA, 5);
    points(r, picture.hull_b, kSetB, 5);
    const Real gap = 8 / r.camera().pixels_per_unit();
    label(r, area_properties(picture.hull_a).centroid - Vec2(6 * gap, 0), "A", kSetA);
    label(r, area_properties(picture.hull_b).centroid, "B", kSetB);
    label(r, Vec2(10, 385), picture.gjk.overlap ? "GJK: intersect" : "GJK: separate",
          picture.gjk.overlap ? kUpper : kLower);
  }
}

void figure_13(Renderer& r, const PaperSettings& settings) {
  for (int i = 0; i < 2; ++i) draw_difference_panel(r, 2, i, gjk_picture(settings, i == 1));
}

}  // namespace

GjkPicture gjk_picture(const PaperSettings& settings, bool apart) {
  const auto [set_a, set_b] = paper_point_sets(settings.seed, settings.count);
  GjkPicture picture;
  picture.apart = apart;
  // Unequal factors per axis show that eq. 6 scales x and y separately.
  picture.scale_a = Vec2(0.45, 0.55);
  picture.scale_b = Vec2(0.5, 0.4);
  const ConvexHull original_a = chan_hull(set_a);
  const ConvexHull original_b = divide_conquer_hull(set_b);
  picture.original_a.assign(original_a.vertices().begin(), original_a.vertices().end());
  picture.original_b.assign(original_b.vertices().begin(), original_b.vertices().end());
  const std::vector<Vec2> scaled_a = scale_about(
      original_a.vertices(), area_properties(original_a.vertices()).centroid, picture.scale_a);
  const std::vector<Vec2> scaled_b = scale_about(
      original_b.vertices(), area_properties(original_b.vertices()).centroid, picture.scale_b);
  // Side by side around x = 200 with both centroids at y = 200: A's right end and B's left
  // end 60 units into each other, or 40 units apart so a vertical line separates them.
  const auto extent_x = [](const std::vector<Vec2>& ring, bool right) {
    Real x = ring.front().x();
    for (const Vec2& p : ring) x = right ? std::max(x, p.x()) : std::min(x, p.x());
    return x;
  };
  const Real half = apart ? -20 : 30;
  picture.offset_a =
      Vec2(200 + half - extent_x(scaled_a, true), 200 - area_properties(scaled_a).centroid.y());
  picture.offset_b =
      Vec2(200 - half - extent_x(scaled_b, false), 200 - area_properties(scaled_b).centroid.y());
  // Hulled again, by the same algorithms: rounding in the transforms may leave a vertex
  // collinear, and the hull of an affinely mapped set is the mapped hull.
  const ConvexHull hull_a = chan_hull(translate(scaled_a, picture.offset_a));
  const ConvexHull hull_b = divide_conquer_hull(translate(scaled_b, picture.offset_b));
  picture.hull_a.assign(hull_a.vertices().begin(), hull_a.vertices().end());
  picture.hull_b.assign(hull_b.vertices().begin(), hull_b.vertices().end());
  const PreparedHull prepared_a(hull_a);
  const PreparedHull prepared_b(hull_b);
  picture.gjk = gjk_overlap(prepared_a, Pose{}, prepared_b, Pose{});
  picture.distance = gjk_distance(prepared_a, Pose{}, prepared_b, Pose{}).distance;
  picture.simplex = world_simplex(picture.gjk.simplex, prepared_a, Pose{}, prepared_b, Pose{});
  picture.difference = minkowski_difference(picture.hull_a, picture.hull_b);
  return picture;
}

void draw_difference_panel(Renderer& r, int count, int index, const GjkPicture& picture) {
  Vec2 lower(0, 0);  // the box shown holds the difference and the origin
  Vec2 upper(0, 0);
  for (const Vec2& p : picture.difference) {
    lower = lower.cwiseMin(p);
    upper = upper.cwiseMax(p);
  }
  const int n = picture.simplex.count;
  const std::string simplex_text =
      n == 3   ? "GJK's final simplex (a triangle)"
      : n == 2 ? "GJK's final simplex (a segment)"
      : n == 1 ? "GJK's final simplex (a point)"
               : "no simplex: the first support point w along d already fails to pass the "
                 "origin (w.d < 0), so the line w.d = const separates";
  // Room beside the picture for the vertex labels.
  panel_of(
      r, count, index,
      "Fig. 13" + std::string(1, static_cast<char>('a' + index)) + "  " +
          (picture.apart ? "moved apart" : "overlapping") + ": A - B (" +
          count_text(picture.difference.size(), "vertex", "vertices") + "), " + simplex_text +
          " and the origin, which is " +
          (picture.gjk.overlap ? "inside: the hulls intersect" : "outside: the hulls are separate"),
      lower, upper, std::min<Real>(110, 0.15 * r.width() / count));
  // Axes through the origin.
  const Vec2 span = upper - lower;
  r.draw_segment(Vec2(lower.x() - 0.05 * span.x(), 0), Vec2(upper.x() + 0.05 * span.x(), 0),
                 kFaint);
  r.draw_segment(Vec2(0, lower.y() - 0.05 * span.y()), Vec2(0, upper.y() + 0.05 * span.y()),
                 kFaint);
  r.draw_polygon(picture.difference, kDifferenceFill, kInk);
  std::vector<Vec2> simplex;
  for (int i = 0; i < n; ++i)
    simplex.push_back(picture.simplex.vertices[static_cast<std::size_t>(i)].point);
  outline(r, simplex, kSimplex);
  points(r, simplex, kSimplex, 9);
  const Real unit = 1 / r.camera().pixels_per_unit();
  for (int i = 0; i < n; ++i) {
    const SimplexVertex& v = picture.simplex.vertices[static_cast<std::size_t>(i)];
    char text[64];
    std::snprintf(text, sizeof text, "w%d = a%u - b%u", i, static_cast<unsigned>(v.index_a),
                  static_cast<unsigned>(v.index_b));
    label(r, v.point + Vec2(10 * unit, -12 * unit), text, kSimplex);
  }
  if (!picture.gjk.overlap) {
    // The separating direction from the origin, and the supporting line of A - B across it.
    const Vec2 d = picture.gjk.separating_direction.normalized();
    Real support = -std::numeric_limits<Real>::infinity();
    for (const Vec2& p : picture.difference) support = std::max(support, p.dot(d));
    const Vec2 along(-d.y(), d.x());
    const Real reach = 0.5 * span.maxCoeff();
    for (Real t = -reach; t < reach; t += 0.04 * reach) {
      r.draw_segment(support * d + t * along, support * d + (t + 0.02 * reach) * along, kLower);
    }
    const Vec2 tip = 0.15 * span.norm() * d;
    r.draw_segment(Vec2(0, 0), tip, kLower);
    r.draw_point(tip, 8, kLower);
    label(r, tip + Vec2(-30 * unit, 16 * unit), "d", kLower);
  }
  r.draw_point(Vec2(0, 0), kOriginMarkerPixels, kOriginMarker);
  // Below right of the marker, clear of the ring just around it.
  label(r, Vec2(12 * unit, -26 * unit), "origin", kOriginMarker);
}

std::vector<PaperFigure> paper_figures() {
  return {
      {"fig08_point_sets.png", "the two random point sets", figure_8},
      {"fig09_chan.png", "Chan's groups and final hull", figure_9},
      {"fig10_divide_conquer.png", "divide-and-conquer halves with the upper and lower tangents",
       figure_10},
      {"fig12_gjk_verdict.png", "hulls after translate/scale with the GJK verdict", figure_12},
      {"fig13_minkowski_difference.png",
       "the Minkowski difference with the final simplex and the origin", figure_13},
  };
}

}  // namespace mink::cli
