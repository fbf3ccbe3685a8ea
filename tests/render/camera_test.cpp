#include "mink/render/camera.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "mink/error.hpp"

namespace {

using mink::Camera;
using mink::Vec2;

TEST(Camera, FitShowsTheWholeBoxCentredWithTheMarginOnTheTightSide) {
  Camera camera(200, 100);
  camera.fit(Vec2(0, 0), Vec2(10, 2), 10);
  // Width decides: 180 pixels for 10 units.
  EXPECT_DOUBLE_EQ(camera.pixels_per_unit(), 18);
  EXPECT_TRUE(camera.world_to_pixel(Vec2(0, 1)).isApprox(Vec2(10, 50)));
  EXPECT_TRUE(camera.world_to_pixel(Vec2(10, 1)).isApprox(Vec2(190, 50)));
  // World y up is pixel y down.
  EXPECT_LT(camera.world_to_pixel(Vec2(5, 2)).y(), camera.world_to_pixel(Vec2(5, 0)).y());

  camera.fit(Vec2(-1, -5), Vec2(1, 5), 10);  // height decides: 80 pixels for 10 units
  EXPECT_DOUBLE_EQ(camera.pixels_per_unit(), 8);
  EXPECT_TRUE(camera.world_to_pixel(Vec2(0, 5)).isApprox(Vec2(100, 10)));
  EXPECT_TRUE(camera.world_to_pixel(Vec2(0, -5)).isApprox(Vec2(100, 90)));
}

TEST(Camera, FitRegionPlacesTheBoxInAPanel) {
  Camera camera(400, 200);
  // The right half of the frame, 10 pixels of margin: 180 pixels for 4 units.
  camera.fit_region(Vec2(0, 0), Vec2(4, 4), Vec2(200, 0), Vec2(400, 200), 10);
  EXPECT_DOUBLE_EQ(camera.pixels_per_unit(), 45);
  EXPECT_TRUE(camera.world_to_pixel(Vec2(2, 2)).isApprox(Vec2(300, 100)));
  EXPECT_TRUE(camera.world_to_pixel(Vec2(0, 4)).isApprox(Vec2(210, 10)));
  EXPECT_THROW(camera.fit_region(Vec2(0, 0), Vec2(1, 1), Vec2(10, 10), Vec2(5, 50)),
               mink::InvalidArgumentError);
  // Following recentres on the frame.
  camera.follow(Vec2(1, 1), 2);
  EXPECT_TRUE(camera.world_to_pixel(Vec2(1, 1)).isApprox(Vec2(200, 100)));
}

TEST(Camera, PixelToWorldUndoesWorldToPixel) {
  Camera camera(640, 480);
  camera.follow(Vec2(3.5, -2), 37.5);
  EXPECT_TRUE(camera.world_to_pixel(Vec2(3.5, -2)).isApprox(Vec2(320, 240)));
  for (const Vec2& p : {Vec2(0, 0), Vec2(-7.25, 1e3), Vec2(12, -0.5)}) {
    EXPECT_TRUE(camera.pixel_to_world(camera.world_to_pixel(p)).isApprox(p, 1e-12));
  }
}

TEST(Camera, DegenerateBoxesUseTheOtherSideOrUnitZoom) {
  Camera camera(100, 100);
  camera.fit(Vec2(0, 3), Vec2(8, 3), 10);  // a horizontal segment
  EXPECT_DOUBLE_EQ(camera.pixels_per_unit(), 10);
  camera.fit(Vec2(2, 2), Vec2(2, 2), 10);  // a point
  EXPECT_DOUBLE_EQ(camera.pixels_per_unit(), 1);
  EXPECT_TRUE(camera.world_to_pixel(Vec2(2, 2)).isApprox(Vec2(50, 50)));
}

TEST(Camera, RejectsBadBoxesMarginsAndZooms) {
  Camera camera(100, 100);
  EXPECT_THROW(camera.fit(Vec2(1, 0), Vec2(0, 1)), mink::InvalidArgumentError);
  EXPECT_THROW(camera.fit(Vec2(0, 0), Vec2(NAN, 1)), mink::InvalidArgumentError);
  EXPECT_THROW(camera.fit(Vec2(0, 0), Vec2(1, 1), 50), mink::InvalidArgumentError);
  EXPECT_THROW(camera.fit(Vec2(0, 0), Vec2(1, 1), -1), mink::InvalidArgumentError);
  EXPECT_THROW(camera.follow(Vec2(0, 0), 0), mink::InvalidArgumentError);
  EXPECT_THROW(camera.follow(Vec2(INFINITY, 0), 1), mink::InvalidArgumentError);
  EXPECT_THROW(Camera(0, 10), mink::InvalidArgumentError);
}

}  // namespace
