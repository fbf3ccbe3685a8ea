#include "mink/render/camera.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "mink/error.hpp"
#include "mink/render/gl_context.hpp"

namespace mink {

Camera::Camera(int width_pixels, int height_pixels)
    : width_(width_pixels),
      height_(height_pixels),
      center_pixel_(width_pixels / 2.0, height_pixels / 2.0) {
  detail::require_frame_size(width_pixels, height_pixels);
}

void Camera::resize(int width_pixels, int height_pixels) {
  detail::require_frame_size(width_pixels, height_pixels);
  width_ = width_pixels;
  height_ = height_pixels;
  center_pixel_ = Vec2(width_pixels / 2.0, height_pixels / 2.0);
}

void Camera::fit(const Vec2& lower, const Vec2& upper, Real margin_pixels) {
  fit_region(lower, upper, Vec2(0, 0), Vec2(width_, height_), margin_pixels);
}

void Camera::fit_region(const Vec2& lower, const Vec2& upper, const Vec2& region_min,
                        const Vec2& region_max, Real margin_pixels) {
  if (!lower.allFinite() || !upper.allFinite() || lower.x() > upper.x() || lower.y() > upper.y()) {
    std::ostringstream message;
    message << "camera box [(" << lower.x() << ", " << lower.y() << "), (" << upper.x() << ", "
            << upper.y() << ")] must be finite with lower <= upper";
    throw InvalidArgumentError(message.str());
  }
  const Vec2 region = region_max - region_min;
  const Real room_x = region.x() - 2 * margin_pixels;
  const Real room_y = region.y() - 2 * margin_pixels;
  if (!region_min.allFinite() || !region_max.allFinite() || !std::isfinite(margin_pixels) ||
      margin_pixels < 0 || !(room_x > 0) || !(room_y > 0)) {
    std::ostringstream message;
    message << "camera margin " << margin_pixels << " leaves no room in a " << region.x() << " x "
            << region.y() << " pixel region";
    throw InvalidArgumentError(message.str());
  }
  const Vec2 extent = upper - lower;
  // The tighter axis decides; an axis of zero extent does not constrain the scale.
  Real scale = std::numeric_limits<Real>::infinity();
  if (extent.x() > 0) scale = room_x / extent.x();
  if (extent.y() > 0) scale = std::min(scale, room_y / extent.y());
  if (!std::isfinite(scale) || scale <= 0) scale = 1;  // a single point: unit zoom
  center_ = (lower + upper) / 2;
  center_pixel_ = (region_min + region_max) / 2;
  scale_ = scale;
}

void Camera::follow(const Vec2& point, Real pixels_per_unit) {
  if (!point.allFinite()) {
    throw InvalidArgumentError("camera cannot follow a non-finite point");
  }
  if (!std::isfinite(pixels_per_unit) || pixels_per_unit <= 0) {
    std::ostringstream message;
    message << "camera zoom " << pixels_per_unit << " pixels per unit must be finite and positive";
    throw InvalidArgumentError(message.str());
  }
  center_ = point;
  center_pixel_ = Vec2(width_ / 2.0, height_ / 2.0);
  scale_ = pixels_per_unit;
}

}  // namespace mink
