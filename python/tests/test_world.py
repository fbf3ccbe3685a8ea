"""The module end to end: worlds, bodies, every shape and joint kind, filters, sensors,
events, queries and errors, checked against closed-form results where there are some."""

import math
import pathlib
import threading

import numpy
import pytest

import minkowski as mk

FAR_HINGE = str(pathlib.Path(__file__).resolve().parents[2] / "fuzz" / "corpus" / "scene_reader"
                / "far_hinge_300m.json")


def ground_world(**settings):
    world = mk.World(**settings)
    ground = world.create_body("static")
    ground.add_box(10, 0.5)
    return world, ground


def test_world_settings_are_the_scene_files_world_keys():
    world = mk.World(gravity=(0, -9.8), substeps=4, enable_sleep=False, workers=2)
    settings = world.settings
    assert settings["gravity"] == (0.0, -9.8)
    assert settings["substeps"] == 4
    assert settings["enable_sleep"] is False
    assert settings["workers"] == 2
    assert world.gravity == (0.0, -9.8)
    world.gravity = numpy.array([0.0, -1.0])
    assert world.gravity == (0.0, -1.0)
    assert world.time_step == pytest.approx(1 / 60)


def test_bad_world_settings_raise_with_the_engines_message():
    with pytest.raises(mk.SceneFileError) as raised:
        mk.World(substeps=0)
    assert str(raised.value) == "world.substeps: must be in 1..1000, got 0"
    assert raised.value.json_path == "world.substeps"
    assert isinstance(raised.value, mk.InvalidArgumentError)
    assert isinstance(raised.value, ValueError)
    assert isinstance(raised.value, mk.Error)
    with pytest.raises(TypeError, match="unexpected keyword argument 'gravty'"):
        mk.World(gravty=(0, -10))
    with pytest.raises(mk.InvalidArgumentError, match="workers must be in 1..256"):
        mk.World(workers=0)


def test_free_fall_matches_the_integrator_in_closed_form():
    # Semi-implicit Euler per substep: v += g h, then y += v h; after M substeps
    # y = y0 + g h^2 M (M + 1) / 2 and v = g M h.
    world = mk.World(gravity=(0, -10), substeps=4)
    ball = world.create_body("dynamic", position=(0, 100))
    ball.add_circle(0.5)
    world.step(30)
    h = world.time_step / 4
    m = 30 * 4
    # To the solver's single precision (velocities and a step's position change are floats;
    # the position itself is a double).
    assert ball.position[1] == pytest.approx(100 - 10 * h * h * m * (m + 1) / 2, abs=1e-5)
    assert ball.linear_velocity[1] == pytest.approx(-10 * m * h, rel=1e-6)
    assert world.step_count == 30
    assert world.time == pytest.approx(0.5)


def test_mass_properties_are_those_of_the_shapes():
    world = mk.World()
    disk = world.create_body("dynamic")
    disk.add_circle(0.5, density=2)
    assert disk.mass == pytest.approx(2 * math.pi * 0.25)
    assert disk.rotational_inertia == pytest.approx(disk.mass * 0.25 / 2)
    box = world.create_body("dynamic", position=(3, 0))
    box.add_box(1, 0.5)
    assert box.mass == pytest.approx(2.0)
    assert box.rotational_inertia == pytest.approx(2.0 * (4 + 1) / 12)
    assert box.world_center == pytest.approx((3, 0))
    box.mass_data = mk.MassData(mass=5, center=(0.1, 0), rotational_inertia=1)
    assert box.mass == 5 and box.local_center == pytest.approx((0.1, 0))


def test_every_shape_kind():
    world = mk.World()
    body = world.create_body("dynamic")
    circle = body.add_circle(0.5, center=(1, 0), friction=0.2)
    capsule = body.add_capsule((0, 0), (1, 0), 0.25)
    segment = body.add_segment((0, 0), (0, 1))
    polygon = body.add_polygon([(0, 0), (1, 0), (0, 1), (0.2, 0.2)], radius=0.1,
                               algorithm="graham")
    box = body.add_box(0.5, 0.25, center=(2, 0), angle=0.3)
    hexagon = body.add_regular_polygon(6, 1.0)
    chain = body.add_chain([(0, -2), (1, -2), (2, -1.5)])
    loop = body.add_chain([(0, 0), (1, 0), (1, 1), (0, 1)], loop=True)
    from_def = body.add_shape(mk.ShapeDef.capsule((0, 0), (0, 2), 0.1, restitution=0.5))
    assert [s.type for s in (circle, capsule, segment, polygon, box, hexagon)] == [
        "circle", "capsule", "segment", "polygon", "polygon", "polygon"]
    assert len(chain) == 2 and all(s.type == "chain" for s in chain)
    assert len(loop) == 4 and loop[0].chain == (1, True) and chain[0].chain == (0, False)
    assert circle.points.tolist() == [[1.0, 0.0]] and circle.radius == 0.5
    assert circle.friction == pytest.approx(0.2)
    assert capsule.points.tolist() == [[0.0, 0.0], [1.0, 0.0]]
    # The interior point is hulled away; the hull starts at the lowest x, then lowest y.
    assert polygon.points.tolist() == [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]
    assert polygon.radius == pytest.approx(0.1) and polygon.algorithm == "graham"
    assert hexagon.points.shape == (6, 2) and hexagon.points.dtype == numpy.float64
    assert from_def.restitution == pytest.approx(0.5)
    assert len(body.shapes) == 6 + 2 + 4 + 1 == world.shape_count
    assert world.shape(circle.index) == circle
    lower, upper = circle.aabb
    assert lower == pytest.approx((0.5, -0.5)) and upper == pytest.approx((1.5, 0.5))
    circle.destroy()
    assert not circle.valid and world.shape_count == 12


def test_body_properties_and_setters():
    world = mk.World(gravity=(0, 0))
    body = world.create_body(mk.BodyDef(type="dynamic", angle=0.5), position=(1, 2),
                             linear_velocity=(3, 0), user_data=7)
    body.add_box(0.5, 0.5)
    assert body.type == "dynamic" and body.position == (1.0, 2.0) and body.angle == 0.5
    assert body.user_data == 7 and body.awake and body.enabled
    body.position = (4, 5)
    body.angle = 1.0
    body.angular_velocity = 2.0
    assert body.position == pytest.approx((4, 5)) and body.angle == pytest.approx(1.0)
    world.step()
    assert body.angle == pytest.approx(1.0 + 2.0 / 60)
    body.apply_impulse((body.mass * 1.0, 0))
    assert body.linear_velocity[0] == pytest.approx(4.0)
    body.fixed_rotation = True
    assert body.angular_velocity == 0 and body.fixed_rotation
    body.type = "kinematic"
    assert body.type == "kinematic" and body.mass == 0
    assert world.body(body.index) == body
    assert body in world.bodies and len(world) == 1


def test_destroyed_bodies_raise_stale_id_errors():
    world = mk.World()
    body = world.create_body("dynamic")
    body.destroy()
    assert not body.valid
    with pytest.raises(mk.StaleIdError, match=r"BodyId\{index 0"):
        body.position
    with pytest.raises(LookupError):
        body.angle
    assert "destroyed" in repr(body)


def test_shape_errors_carry_the_engines_message():
    world = mk.World()
    body = world.create_body("dynamic")
    with pytest.raises(mk.DegenerateInputError):
        body.add_polygon([(0, 0), (1, 1), (2, 2)])
    with pytest.raises(mk.NonFiniteInputError) as raised:
        body.add_polygon([(0, 0), (math.nan, 0), (0, 1)])
    assert raised.value.index == 1
    assert str(raised.value) == "point 1 has a non-finite coordinate"
    with pytest.raises(mk.InvalidArgumentError):
        body.add_circle(-1)
    with pytest.raises(TypeError, match="add_box\\(\\) got an unexpected keyword argument 'mass'"):
        body.add_box(1, 1, mass=3)
    with pytest.raises(mk.InvalidArgumentError, match="body type 'dynamc'"):
        world.create_body("dynamc")
    with pytest.raises(mk.InvalidArgumentError):
        world.create_body("dynamic", position=(math.inf, 0))


def test_a_pendulum_keeps_its_length_and_swings_through_the_bottom():
    world = mk.World(gravity=(0, -10))
    pivot = world.create_body("static", position=(0, 10))
    bob = world.create_body("dynamic", position=(2, 10))
    bob.add_circle(0.1, density=10)
    joint = world.revolute_joint(pivot, bob, anchor=(0, 10))
    assert joint.type == "revolute" and joint.body_a == pivot and joint.body_b == bob
    lowest = 10.0
    for _ in range(120):
        world.step()
        x, y = bob.position
        assert math.hypot(x, y - 10) == pytest.approx(2.0, abs=2e-3)
        lowest = min(lowest, y)
    assert lowest == pytest.approx(8.0, abs=1e-2)
    assert joint.anchor_a == pytest.approx(joint.anchor_b, abs=2e-3)
    assert isinstance(joint.settings, mk.RevoluteJointDef)


def test_every_joint_kind_holds_its_constraint():
    world = mk.World(gravity=(0, -10), enable_sleep=False)
    ground = world.create_body("static")

    def box(x, y):
        body = world.create_body("dynamic", position=(x, y))
        body.add_box(0.25, 0.25)
        return body

    slider = box(0, 0)
    prismatic = world.prismatic_joint(ground, slider, anchor=(0, 0), axis=(1, 1),
                                      limit=mk.JointLimit(-5, 5))
    hanging = box(3, -2)
    distance = world.distance_joint(ground, hanging, anchor_a=(3, 0), anchor_b=(3, -2))
    welded = box(6, 0)
    weld = world.weld_joint(ground, welded, anchor=(6, 0))
    wheel_body = world.create_body("dynamic", position=(9, 0))
    wheel_body.add_circle(0.3)
    wheel = world.wheel_joint(ground, wheel_body, anchor=(9, 0), axis=(0, 1),
                              motor=mk.JointMotor(speed=5, max_force=50))
    driven = box(12, 0)
    motor = world.motor_joint(ground, driven, linear_offset=(12, 1), max_force=1000,
                              max_torque=1000)
    left = box(15, 0)
    right = box(17, 0)
    hinge_left = world.revolute_joint(ground, left, anchor=(15, 0))
    hinge_right = world.revolute_joint(ground, right, anchor=(17, 0))
    gear = world.gear_joint(hinge_left, hinge_right, ratio=2)
    left.angular_velocity = 1.0
    heavy = box(20, -2)
    light = box(22, -2)
    pulley = world.pulley_joint(heavy, light, ground_a=(20, 2), ground_b=(22, 2),
                                anchor_a=(20, -2), anchor_b=(22, -2), ratio=1)
    heavy.mass_data = mk.MassData(mass=3, rotational_inertia=1)
    light.mass_data = mk.MassData(mass=1, rotational_inertia=1)
    kinds = [j.type for j in world.joints]
    assert kinds == ["prismatic", "distance", "weld", "wheel", "motor", "revolute", "revolute",
                     "gear", "pulley"]
    gear_start = gear.coordinate
    pulley_start = pulley.coordinate
    world.step(60)
    x, y = slider.position
    assert x == pytest.approx(y, abs=1e-3)  # on the 45 degree axis
    assert slider.angle == pytest.approx(0, abs=1e-3)
    assert math.hypot(*numpy.subtract(hanging.position, (3, 0))) == pytest.approx(2, abs=1e-3)
    assert welded.position == pytest.approx((6, 0), abs=1e-2)
    assert wheel_body.position[0] == pytest.approx(9, abs=1e-3)
    assert wheel_body.angular_velocity == pytest.approx(5, rel=1e-2)
    assert driven.position == pytest.approx((12, 1), abs=1e-2)
    assert gear.coordinate == pytest.approx(gear_start, abs=1e-2)
    assert pulley.coordinate == pytest.approx(pulley_start, abs=2e-2)
    # Atwood's machine: a = g (m1 - m2) / (m1 + m2) = 5 m/s^2, so 2.5 m in the first second.
    assert heavy.position[1] == pytest.approx(-2 - 2.5, rel=0.02)
    assert light.position[1] == pytest.approx(-2 + 2.5, rel=0.02)
    assert wheel.motor.speed == 5 and prismatic.limit.upper == 5
    assert distance.settings.length == pytest.approx(2)
    assert weld.settings.linear_hertz == 0 and motor.settings.max_force == 1000
    hinge_left.destroy()
    assert not gear.valid  # a gear goes with either of its joints


def test_filters_let_shapes_pass_through():
    world, ground = ground_world()
    ground.shapes[0].filter = mk.Filter(category=0b01)
    ghost = world.create_body("dynamic", position=(0, 2))
    ghost.add_circle(0.5, filter=mk.Filter(category=0b10, mask=0b10))
    solid = world.create_body("dynamic", position=(3, 2))
    solid.add_circle(0.5)
    world.step(120)
    assert ghost.position[1] < -3
    assert solid.position[1] == pytest.approx(1.0, abs=2e-2)
    same_group = mk.Filter(group=-1)
    assert not same_group.collides_with(mk.Filter(group=-1))
    assert mk.Filter(category=1, mask=2).collides_with(mk.Filter(category=2, mask=1))
    assert ghost.shapes[0].filter == mk.Filter(category=2, mask=2)


def test_contact_hit_and_sensor_events_as_structured_arrays():
    world, ground = ground_world()
    world.create_body("static").add_box(1, 0.5, center=(0, 3), sensor=True)
    ball = world.create_body("dynamic", position=(0, 6))
    ball_shape = ball.add_circle(0.5, hit_events=True)
    begins, hits, sensor_begins, sensor_ends = [], [], [], []
    for _ in range(90):
        world.step()
        begins.extend(world.contact_begin_events().tolist())
        hits.extend(world.hit_events())
        sensor_begins.extend(world.sensor_begin_events())
        sensor_ends.extend(world.sensor_end_events())
    events = world.contact_begin_events()
    assert events.dtype.names == ("shape_a", "shape_b", "body_a", "body_b", "normal",
                                  "point_count", "points", "separations")
    assert events.dtype["points"].shape == (2, 2)
    assert len(begins) == 1
    shape_a, shape_b, body_a, body_b = begins[0][:4]
    assert {body_a, body_b} == {ground.index, ball.index}
    assert ball_shape.index in (shape_a, shape_b)
    assert len(hits) == 1
    # It fell 6 - 0.5 - 0.5 = 5 m before the step that met the ground.
    assert hits[0]["speed"] == pytest.approx(math.sqrt(2 * 10 * 5), rel=0.05)
    assert len(sensor_begins) == 1 and len(sensor_ends) == 1
    assert sensor_begins[0]["visitor_body"] == ball.index
    assert set(world.events()) == {"contact_begin", "contact_end", "hit", "sensor_begin",
                                   "sensor_end", "joint_break", "body_stopped"}


def test_joint_break_events_name_the_joint():
    world = mk.World(gravity=(0, -10))
    anchor = world.create_body("static", position=(0, 5))
    weight = world.create_body("dynamic", position=(0, 4))
    weight.add_circle(0.25, density=100)
    joint = world.distance_joint(anchor, weight, anchor_a=(0, 5), anchor_b=(0, 4),
                                 break_force=10, user_data=3)
    world.step()
    breaks = world.joint_break_events()
    assert len(breaks) == 1
    assert breaks[0]["joint"] == joint.index and breaks[0]["user_data"] == 3
    assert breaks[0]["body_b"] == weight.index
    assert breaks[0]["force"][1] == pytest.approx(weight.mass * 10, rel=0.05)
    assert world.body_move_events()["body"].tolist() == [weight.index]


def test_a_diverged_solve_stops_its_bodies_and_says_so():
    # Two capsules hinged together twice and to a 32 t circle 300 m away: the single-precision
    # solve runs away within a few steps; its bodies are put back where the step began, at rest.
    world = mk.parse_scene(open(FAR_HINGE).read())
    stopped_steps = 0
    for _ in range(60):
        world.step()
        states = world.states(list(range(3)))
        assert numpy.isfinite(states).all()
        stops = world.body_stopped_events()
        if len(stops):
            stopped_steps += 1
            assert sorted(stops["body"].tolist()) == [0, 1, 2]
            assert stops["diverged"].any()
            assert (states[:, 3:] == 0).all()
    assert stopped_steps > 0


def test_queries():
    world, ground = ground_world()
    box = world.create_body("dynamic", position=(3, 3))
    box.add_box(0.5, 0.5)
    hit = world.ray_cast((0, 5), (0, -15))
    assert hit.shape == ground.shapes[0]
    assert hit.fraction == pytest.approx(0.3) and hit.point == pytest.approx((0, 0.5))
    assert hit.normal == pytest.approx((0, 1))
    assert world.ray_cast((20, 5), (0, -10)) is None
    assert world.query_point((0, 0)) == ground.shapes
    assert world.query_point((3, 3)) == box.shapes
    assert world.query_aabb((2, 2), (4, 4)) == box.shapes
    assert world.query_aabb((-20, -20), (20, 20)) == world.shapes
    cast = world.cast_shape(mk.ShapeDef.circle(0.5), (0, -10), position=(0, 5))
    assert cast.shape == ground.shapes[0]
    assert cast.fraction == pytest.approx(0.4, abs=1e-3)
    passed = world.cast_shape(mk.ShapeDef.circle(0.5), (0, -10), position=(0, 5),
                              filter=mk.Filter(mask=0))
    assert passed is None
    origins = numpy.array([[0, 5], [3, 10], [20, 5]], dtype=float)
    rays = world.ray_casts(origins, numpy.tile([0.0, -15.0], (3, 1)))
    assert rays["hit"].tolist() == [True, True, False]
    assert rays["body"].tolist() == [ground.index, box.index, -1]
    assert rays["fraction"][:2] == pytest.approx([0.3, 6.5 / 15])
    assert mk.convex_hull([(0, 0), (2, 0), (1, 1), (2, 2), (0, 2), (1, 0)]).tolist() == [
        [0, 0], [2, 0], [2, 2], [0, 2]]


def test_batch_arrays_shapes_dtypes_selections_and_setters():
    world = mk.World(gravity=(0, 0))
    bodies = []
    for i in range(5):
        body = world.create_body("dynamic", position=(i, 2 * i), angle=0.1 * i)
        body.add_circle(0.25)
        bodies.append(body)
    positions = world.positions()
    assert positions.shape == (5, 2) and positions.dtype == numpy.float64
    assert positions.tolist() == [[i, 2 * i] for i in range(5)]
    assert world.angles().shape == (5,) and world.angles() == pytest.approx(
        [0.1 * i for i in range(5)])
    assert world.linear_velocities().shape == (5, 2)
    assert world.angular_velocities().dtype == numpy.float64
    assert world.states().shape == (5, 6)
    assert world.awake().dtype == numpy.bool_
    assert world.indices().tolist() == [b.index for b in world.bodies]
    selection = numpy.array([3, 1])
    assert world.positions(selection).tolist() == [[3, 6], [1, 2]]
    assert world.positions([bodies[4]]).tolist() == [[4, 8]]
    world.set_positions(numpy.zeros((2, 2)), bodies=selection)
    assert bodies[3].position == (0, 0) and bodies[1].position == (0, 0)
    world.set_linear_velocities(numpy.ones((5, 2)))
    world.set_angular_velocities(numpy.full(5, 2.0))
    grid = numpy.array([[2.0 * i, 0.0] for i in range(5)])
    world.set_transforms(grid, numpy.zeros(5))
    world.step()
    assert world.positions() == pytest.approx(grid + 1 / 60)
    # Rotations are integrated on the unit circle (normalised), not as angles.
    assert world.angles() == pytest.approx(numpy.full(5, 2 / 60), rel=1e-4)
    world.apply_impulses(numpy.tile([world.masses()[0], 0.0], (5, 1)))
    assert world.linear_velocities()[:, 0] == pytest.approx(numpy.full(5, 2.0))
    with pytest.raises(mk.InvalidArgumentError,
                       match=r"set_positions: expected an array of shape \(5, 2\).*got \(4, 2\)"):
        world.set_positions(numpy.zeros((4, 2)))
    with pytest.raises(mk.InvalidArgumentError, match="no live body has index 9"):
        world.positions([9])


def test_step_releases_the_gil_and_guards_the_world():
    world = mk.builtin_scene("pyramid", enable_sleep=False)
    done = threading.Event()
    errors = []

    def run():
        try:
            world.step(400)
        except Exception as error:  # reported below
            errors.append(error)
        finally:
            done.set()

    seen_stepping = False
    thread = threading.Thread(target=run)
    thread.start()
    while not done.is_set():
        try:
            world.body_count
        except RuntimeError as error:
            assert "stepping in another thread" in str(error)
            seen_stepping = True
            break
    thread.join()
    assert not errors
    # This thread ran Python while the step ran, and met the guard instead of a race.
    assert seen_stepping
    assert world.step_count == 400
