// A box resting on the ground, drawn headless through World::draw with the contact layer on:
// the contact marker's colour is at the pixel of each contact point, as the narrowphase
// computes the points from the bodies' poses; with the layer off it is not.

#include <gtest/gtest.h>

#include <vector>

#include "mink/engine/scene.hpp"
#include "mink/narrowphase/manifold.hpp"
#include "mink/narrowphase/prepared_hull.hpp"
#include "render_test_support.hpp"

namespace {

using mink::Vec2;
using mink_test::Headless;
using mink_test::Rgba;

// World::draw's contact point colour, (1, 0.2, 0.2).
const Rgba kContactMarker{255, 51, 51, 255};

class ContactMarker : public testing::TestWithParam<mink::GlBackend> {};

TEST_P(ContactMarker, AtEachContactPointWhenTheLayerIsOn) {
  mink::SceneDef scene;
  mink::SceneBody ground;
  ground.body.position = Vec2(0, -0.5);
  ground.shapes.push_back(mink::ShapeDef::box(4, 0.5));
  mink::SceneBody box;
  box.body.type = mink::BodyType::dynamic;
  box.body.position = Vec2(0.3, 0.5);
  box.shapes.push_back(mink::ShapeDef::box(0.5, 0.5));
  scene.bodies = {ground, box};
  mink::World world = mink::build_world(scene);
  for (int i = 0; i < 60; ++i) world.step();  // settle onto the ground
  ASSERT_GT(world.counters().touching_contacts, 0u);

  const std::vector<mink::BodyId> bodies = world.bodies();
  ASSERT_EQ(bodies.size(), 2u);
  const mink::PreparedHull ground_hull(world.shape_hull(world.body_shapes(bodies[0]).front()));
  const mink::PreparedHull box_hull(world.shape_hull(world.body_shapes(bodies[1]).front()));
  const mink::Manifold manifold =
      mink::collide_hulls(ground_hull, world.pose(bodies[0]), box_hull, world.pose(bodies[1]), 0.1);
  ASSERT_EQ(manifold.point_count, 2);

  Headless frame(GetParam(), 400, 300);
  mink::Renderer& r = *frame.renderer;
  r.camera().fit(Vec2(-2, -1), Vec2(2, 2), 8);
  for (const bool on : {true, false}) {
    r.layers = mink::draw_shapes | (on ? mink::draw_contact_points : 0u);
    r.begin_frame({0.1f, 0.1f, 0.1f, 1});
    world.draw(r);
    r.end_frame();
    const mink::Image image = r.read_pixels();
    for (int j = 0; j < manifold.point_count; ++j) {
      const Vec2 pixel =
          r.camera().world_to_pixel(manifold.points[static_cast<std::size_t>(j)].point);
      const Rgba seen = image.at(static_cast<int>(pixel.x()), static_cast<int>(pixel.y()));
      if (on) {
        EXPECT_EQ(seen, kContactMarker) << "point " << j;
      } else {
        EXPECT_NE(seen, kContactMarker) << "point " << j;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, ContactMarker,
                         testing::Values(mink::GlBackend::osmesa, mink::GlBackend::egl),
                         mink_test::backend_name);

}  // namespace
