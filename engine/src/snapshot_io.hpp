#pragma once

// How each engine record is written to a snapshot and read back: one io() per record, listing
// every field, for both directions (mink/byte_stream.hpp's archives). Derived data that is
// cheaper and safer to recompute (a polygon's prepared hull) is rebuilt on loading instead.

#include <string>

#include "body.hpp"
#include "contact.hpp"
#include "joint.hpp"
#include "mink/byte_stream.hpp"
#include "mink/engine/scene_schedule.hpp"
#include "sensor.hpp"
#include "shape.hpp"

namespace mink {

template <typename Archive>
void io(Archive& a, Rotation& r) {
  a(r.cos);
  a(r.sin);
}
template <typename Archive>
void io(Archive& a, Pose& p) {
  a(p.position);
  a(p.rotation);
}
template <typename Archive>
void io(Archive& a, ManifoldPoint& p) {
  a(p.point);
  a(p.separation);
  a(p.id);
}
template <typename Archive>
void io(Archive& a, Manifold& m) {
  a(m.normal);
  a(m.points);
  a(m.point_count);
  if constexpr (Archive::loading) {
    if (m.point_count < 0 || m.point_count > 2) a.in.fail("a manifold with a bad point count");
  }
}
template <typename Archive>
void io(Archive& a, Filter& f) {
  a(f.category);
  a(f.mask);
  a(f.group);
}
template <typename Archive>
void io(Archive& a, MassData& m) {
  a(m.mass);
  a(m.center);
  a(m.rotational_inertia);
}
// Ids are stored without their world: the world that loads them gives them its own.
template <typename Archive, typename Id>
void id_io(Archive& a, Id& id) {
  a(id.index);
  a(id.generation);
  if constexpr (Archive::loading) id.world = id.is_null() ? 0 : a.world;
}
template <typename Archive>
void io(Archive& a, BodyId& id) {
  id_io(a, id);
}
template <typename Archive>
void io(Archive& a, ShapeId& id) {
  id_io(a, id);
}
template <typename Archive>
void io(Archive& a, JointId& id) {
  id_io(a, id);
}
template <typename Archive>
void io(Archive& a, SceneIds& ids) {
  a(ids.bodies);
  a(ids.joints);
}
template <typename Archive>
void io(Archive& a, JointMotor& m) {
  a(m.enabled);
  a(m.speed);
  a(m.max_force);
}
template <typename Archive>
void io(Archive& a, JointSpring& s) {
  a(s.enabled);
  a(s.hertz);
  a(s.damping_ratio);
  a(s.target);
}
template <typename Archive>
void io(Archive& a, JointLimit& l) {
  a(l.enabled);
  a(l.lower);
  a(l.upper);
}
template <typename Archive>
void base_io(Archive& a, JointBase& b) {
  a(b.body_a);
  a(b.body_b);
  a(b.collide_connected);
  a(b.break_force);
  a(b.break_torque);
  a(b.user_data);
}
template <typename Archive>
void io(Archive& a, RevoluteJointDef& d) {
  base_io(a, d);
  a(d.local_anchor_a);
  a(d.local_anchor_b);
  a(d.reference_angle);
  a(d.limit);
  a(d.motor);
  a(d.spring);
}
template <typename Archive>
void io(Archive& a, PrismaticJointDef& d) {
  base_io(a, d);
  a(d.local_anchor_a);
  a(d.local_anchor_b);
  a(d.local_axis_a);
  a(d.reference_angle);
  a(d.limit);
  a(d.motor);
  a(d.spring);
}
template <typename Archive>
void io(Archive& a, DistanceJointDef& d) {
  base_io(a, d);
  a(d.local_anchor_a);
  a(d.local_anchor_b);
  a(d.length);
  a(d.limit);
  a(d.motor);
  a(d.spring);
}
template <typename Archive>
void io(Archive& a, WeldJointDef& d) {
  base_io(a, d);
  a(d.local_anchor_a);
  a(d.local_anchor_b);
  a(d.reference_angle);
  a(d.linear_hertz);
  a(d.linear_damping_ratio);
  a(d.angular_hertz);
  a(d.angular_damping_ratio);
}
template <typename Archive>
void io(Archive& a, WheelJointDef& d) {
  base_io(a, d);
  a(d.local_anchor_a);
  a(d.local_anchor_b);
  a(d.local_axis_a);
  a(d.spring);
  a(d.limit);
  a(d.motor);
}
template <typename Archive>
void io(Archive& a, MotorJointDef& d) {
  base_io(a, d);
  a(d.linear_offset);
  a(d.angular_offset);
  a(d.max_force);
  a(d.max_torque);
  a(d.correction_factor);
}
template <typename Archive>
void io(Archive& a, GearJointDef& d) {
  base_io(a, d);
  a(d.joint1);
  a(d.joint2);
  a(d.ratio);
}
template <typename Archive>
void io(Archive& a, PulleyJointDef& d) {
  base_io(a, d);
  a(d.ground_anchor_a);
  a(d.ground_anchor_b);
  a(d.local_anchor_a);
  a(d.local_anchor_b);
  a(d.length_a);
  a(d.length_b);
  a(d.ratio);
}
template <typename Archive>
void io(Archive& a, Circle& c) {
  a(c.center);
  a(c.radius);
}
template <typename Archive>
void io(Archive& a, Capsule& c) {
  a(c.center1);
  a(c.center2);
  a(c.radius);
}
template <typename Archive>
void io(Archive& a, Segment& s) {
  a(s.point1);
  a(s.point2);
}
template <typename Archive>
void io(Archive& a, ChainSegment& c) {
  a(c.ghost1);
  a(c.segment);
  a(c.ghost2);
}

template <typename Archive>
void io(Archive& a, BodyDef& d) {
  a(d.type);
  a(d.position);
  a(d.angle);
  a(d.linear_velocity);
  a(d.angular_velocity);
  a(d.linear_damping);
  a(d.angular_damping);
  a(d.gravity_scale);
  a(d.allow_sleep);
  a(d.awake);
  a(d.enabled);
  a(d.fixed_rotation);
  a(d.bullet);
  a(d.continuous_threshold);
  a(d.user_data);
}
template <typename Archive>
void io(Archive& a, ShapeDef& d) {
  a(d.type);
  a(d.points);
  a(d.radius);
  a(d.loop);
  a(d.algorithm);
  a(d.density);
  a(d.friction);
  a(d.restitution);
  bool scaled = d.scale.has_value();
  a(scaled);
  if (scaled) {
    if constexpr (Archive::loading) d.scale.emplace();
    a(d.scale->fixed_point);
    a(d.scale->factor);
  }
  a(d.filter);
  a(d.is_sensor);
  a(d.enable_contact_events);
  a(d.enable_sensor_events);
  a(d.enable_hit_events);
  a(d.user_data);
}

}  // namespace mink

namespace mink::detail {

// A polygon is stored as its hull's vertices and radius; the prepared tables (normals, face
// offsets, sorted angles) are rebuilt from them by the code that made them first.
template <typename Archive>
void geometry_io(Archive& a, ShapeGeometry& geometry) {
  std::uint32_t index = static_cast<std::uint32_t>(geometry.index());
  a(index);
  if constexpr (Archive::loading) {
    switch (index) {
      case 0:
        geometry = Circle{};
        break;
      case 1:
        geometry = Capsule{};
        break;
      case 2:
        geometry = Segment{};
        break;
      case 3:
        geometry = ChainSegment{};
        break;
      case 4: {
        std::vector<Vec2> vertices;
        a(vertices);
        Real radius = 0;
        a(radius);
        try {
          geometry = RoundedPolygon{PreparedHull(ConvexHull::from_ccw_vertices(vertices)), radius};
        } catch (const Error& e) {
          a.in.fail(std::string("a polygon that is not a hull: ") + e.what());
        }
        return;
      }
      default:
        a.in.fail("shape geometry kind " + std::to_string(index));
    }
  }
  std::visit(
      [&](auto& g) {
        using G = std::decay_t<decltype(g)>;
        if constexpr (std::is_same_v<G, RoundedPolygon>) {
          std::vector<Vec2> vertices(g.hull.vertices().begin(), g.hull.vertices().end());
          a(vertices);
          a(g.radius);
        } else {
          a(g);
        }
      },
      geometry);
}

template <typename Archive>
void io(Archive& a, Softness& s) {
  a(s.bias_rate);
  a(s.mass_scale);
  a(s.impulse_scale);
}
template <typename Archive>
void io(Archive& a, JointFrame& f) {
  for (std::size_t k = 0; k < f.bodies.size(); ++k) {
    a(f.bodies[k].solver);
    a(f.starts[k].center);
    a(f.starts[k].rotation);
    a(f.starts[k].local_center);
    a(f.bodies[k].inv_mass);
    a(f.bodies[k].inv_inertia);
  }
  a(f.anchor_a);
  a(f.anchor_b);
  a(f.delta_center);
  a(f.h);
  a(f.inv_h);
  a(f.soft);
  a(f.coordinate_a);
  a(f.coordinate_b);
}
template <typename Archive>
void io(Archive& a, JointReaction& r) {
  a(r.force);
  a(r.torque);
}
template <typename Archive>
void io(Archive& a, RevoluteJoint& j) {
  a(j.def);
  a(j.linear_impulse);
  a(j.spring_impulse);
  a(j.motor_impulse);
  a(j.lower_impulse);
  a(j.upper_impulse);
  a(j.angle);
  a(j.direct);
  a(j.axial_mass);
  a(j.spring_soft);
}
template <typename Archive>
void io(Archive& a, PrismaticJoint& j) {
  a(j.def);
  a(j.block_impulse);
  a(j.spring_impulse);
  a(j.motor_impulse);
  a(j.lower_impulse);
  a(j.upper_impulse);
  a(j.axis);
  a(j.angle_error);
  a(j.spring_soft);
}
template <typename Archive>
void io(Archive& a, DistanceJoint& j) {
  a(j.def);
  a(j.impulse);
  a(j.lower_impulse);
  a(j.upper_impulse);
  a(j.motor_impulse);
  a(j.spring_soft);
}
template <typename Archive>
void io(Archive& a, WeldJoint& j) {
  a(j.def);
  a(j.linear_impulse);
  a(j.angular_impulse);
  a(j.axial_mass);
  a(j.angle_error);
  a(j.linear_soft);
  a(j.angular_soft);
}
template <typename Archive>
void io(Archive& a, WheelJoint& j) {
  a(j.def);
  a(j.perp_impulse);
  a(j.spring_impulse);
  a(j.lower_impulse);
  a(j.upper_impulse);
  a(j.motor_impulse);
  a(j.axis);
  a(j.motor_mass);
  a(j.spring_soft);
}
template <typename Archive>
void io(Archive& a, MotorJoint& j) {
  a(j.def);
  a(j.linear_impulse);
  a(j.angular_impulse);
  a(j.axial_mass);
  a(j.angle_error);
}
template <typename Archive>
void io(Archive& a, GearedJoint& g) {
  a(g.prismatic);
  a(g.local_anchor_a);
  a(g.local_anchor_b);
  a(g.local_axis_a);
  a(g.created);
  a(g.anchor_a);
  a(g.anchor_b);
  a(g.axis);
  a(g.delta_center);
  a(g.start_translation);
}
template <typename Archive>
void io(Archive& a, GearJoint& j) {
  a(j.def);
  a(j.joints);
  a(j.impulse);
}
template <typename Archive>
void io(Archive& a, PulleyJoint& j) {
  a(j.def);
  a(j.impulse);
  a(j.axis_b);
}
template <typename Archive>
void io(Archive& a, Joint& j) {
  a(j.kind);
  a(j.body);
  a(j.body_count);
  a(j.gear_joints);
  a(j.gears);
  a(j.alive);
  a(j.generation);
  a(j.color);
  a(j.a_fixed);
  a(j.b_fixed);
  a(j.frame);
  a(j.reaction);
}
template <typename Archive>
void io(Archive& a, Body& b) {
  a(b.center);
  a(b.rotation);
  a(b.origin);
  a(b.velocity);
  a(b.angular_velocity);
  a(b.inv_mass);
  a(b.inv_inertia);
  a(b.extent);
  a(b.type);
  a(b.alive);
  a(b.awake);
  a(b.allow_sleep);
  a(b.enabled);
  a(b.fixed_rotation);
  a(b.bullet);
  a(b.mass_override);
  a(b.min_extent);
  a(b.continuous_threshold);
  a(b.override_mass);
  a(b.local_center);
  a(b.force);
  a(b.torque);
  a(b.mass);
  a(b.inertia);
  a(b.linear_damping);
  a(b.angular_damping);
  a(b.gravity_scale);
  a(b.sleep_time);
  a(b.user_data);
  a(b.shapes);
  a(b.generation);
  a(b.previous_origin);
  a(b.previous_rotation);
  a(b.moved_step);
  a(b.contacts);
  a(b.fixed_contacts);
  a(b.joints);
  a(b.in_awake_list);
}
template <typename Archive>
void io(Archive& a, Shape& s) {
  geometry_io(a, s.geometry);
  a(s.type);
  a(s.aabb);
  a(s.density);
  a(s.friction);
  a(s.restitution);
  a(s.filter);
  a(s.sensor);
  a(s.contact_events);
  a(s.sensor_events);
  a(s.hit_events);
  a(s.algorithm);
  a(s.proxy);
  a(s.body);
  a(s.chain);
  a(s.chain_loop);
  a(s.generation);
  a(s.alive);
  a(s.user_data);
  a(s.internal_edges);
}
template <typename Archive>
void io(Archive& a, ManifoldCache& c) {
  a(c.relative);
  a(c.normal);
  a(c.on_a[0]);
  a(c.on_a[1]);
  a(c.on_b[0]);
  a(c.on_b[1]);
  a(c.valid);
}
// A contact and its impulses, which live beside the records (contact.hpp), as one record.
template <typename Archive>
void contact_io(Archive& a, Contact& c, ContactImpulses& impulses) {
  a(c.manifold);
  a(c.body_a);
  a(c.body_b);
  a(impulses.normal[0]);
  a(impulses.normal[1]);
  a(impulses.tangent[0]);
  a(impulses.tangent[1]);
  a(c.friction);
  a(c.restitution);
  a(c.shape_a);
  a(c.shape_b);
  a(c.proxy_a);
  a(c.proxy_b);
  a(c.touching);
  a(c.events);
  a(c.hit_events);
  a(c.sharp_polygons);
  a(c.approach_speed);
  a(c.approach_point);
  a(c.color);
  a(c.a_fixed);
  a(c.b_fixed);
  a(c.cache);
}
template <typename Archive>
void io(Archive& a, SensorState& s) {
  a(s.shape);
  a(s.visitors);
}

}  // namespace mink::detail
