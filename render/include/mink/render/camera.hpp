#pragma once

#include "mink/geometry/types.hpp"

namespace mink {

/// Maps world coordinates (y up) to pixels (x right, y down, origin at the top-left corner
/// of the frame, pixel (i, j) covering [i, i + 1) x [j, j + 1)). The scale is the same on both
/// axes, so shapes keep their proportions.
class Camera {
 public:
  /// @brief A camera for a frame of that size, world origin at its centre, 1 pixel per unit.
  /// @throws InvalidArgumentError for a size outside 1..16384.
  Camera(int width_pixels, int height_pixels);

  /// @brief Shows the world box [lower, upper] whole and centred, with `margin_pixels` free on the
  /// tightest side.
  /// @throws InvalidArgumentError for a non-finite or inverted box, or a margin that leaves no
  /// room.
  /// A box of zero width or height is shown at the scale of its other side.
  void fit(const Vec2& lower, const Vec2& upper, Real margin_pixels = 16);
  /// @brief The same into the pixel rectangle [region_min, region_max] of the frame (a panel of a
  /// figure); the rectangle may reach outside the frame.
  void fit_region(const Vec2& lower, const Vec2& upper, const Vec2& region_min,
                  const Vec2& region_max, Real margin_pixels = 16);
  /// @brief Centres `point` at `pixels_per_unit` zoom (a camera following a body calls this per
  /// frame).
  /// @throws InvalidArgumentError for a non-finite point or a zoom that is not positive.
  void follow(const Vec2& point, Real pixels_per_unit);
  /// @brief Same centre, new frame size (a window was resized).
  /// @throws InvalidArgumentError for a size outside 1..16384.
  void resize(int width_pixels, int height_pixels);

  /// @brief A world point (y up) in pixel coordinates (y down).
  Vec2 world_to_pixel(const Vec2& world) const {
    return {center_pixel_.x() + (world.x() - center_.x()) * scale_,
            center_pixel_.y() - (world.y() - center_.y()) * scale_};
  }
  /// @brief A pixel position back in world coordinates.
  Vec2 pixel_to_world(const Vec2& pixel) const {
    return {center_.x() + (pixel.x() - center_pixel_.x()) / scale_,
            center_.y() - (pixel.y() - center_pixel_.y()) / scale_};
  }
  /// @brief Zoom: pixels per world unit, the same on both axes.
  Real pixels_per_unit() const { return scale_; }
  /// @brief The world point shown at the frame's (or region's) centre.
  const Vec2& center() const { return center_; }
  /// @brief Frame width in pixels.
  int width() const { return width_; }
  /// @brief Frame height in pixels.
  int height() const { return height_; }

 private:
  int width_;
  int height_;
  Vec2 center_pixel_;
  Vec2 center_{0, 0};
  Real scale_ = 1;
};

}  // namespace mink
