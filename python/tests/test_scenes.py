"""Scene files and built-ins: bodies in the file's order, a world built from Python equal to
the same scene loaded from its file, JSON round trips, schedules."""

import json

import numpy
import pytest

import minkowski as mk


def every_kind_from_python():
    """python/tests/data/every_kind.json, built call by call."""
    world = mk.World(gravity=(0, -9.8), substeps=4, enable_sleep=False)
    ground = world.create_body("static")
    ground.add_box(20, 0.5, friction=0.8)
    ground.add_chain([(20, 0.5), (15, 1.5), (10, 0.5)])
    ground.add_box(1, 1, center=(-12, 3), sensor=True)
    ball = world.create_body("dynamic", position=(-6, 3))
    ball.add_circle(0.4, restitution=0.5, hit_events=True)
    capsule = world.create_body("dynamic", position=(-4, 3), angle=0.3)
    capsule.add_capsule((-0.5, 0), (0.5, 0), 0.2, density=2)
    wedge = world.create_body("dynamic", position=(-2, 3))
    wedge.add_polygon([(0, 0), (1, 0), (0.5, 0.8)], radius=0.05)
    wedge.add_segment((0, -0.2), (1, -0.2))
    plank = world.create_body("dynamic", position=(0, 3))
    plank.add_box(0.5, 0.25, angle=0.1, filter=mk.Filter(category=2, mask=0xFFFF, group=-1))
    pentagon = world.create_body("dynamic", position=(2, 3))
    pentagon.add_regular_polygon(5, 0.4, friction=0.3)
    paddle = world.create_body("kinematic", position=(6, 4), angular_velocity=1.5)
    paddle.add_box(1, 0.1)
    bob = world.create_body("dynamic", position=(-8, 6))
    bob.add_circle(0.2)
    slider = world.create_body("dynamic", position=(-10, 6))
    slider.add_box(0.3, 0.3)
    wheel = world.create_body("dynamic", position=(8, 2))
    wheel.add_circle(0.3)
    driven = world.create_body("dynamic", position=(12, 6))
    driven.add_box(0.2, 0.2)
    heavy = world.create_body("dynamic", position=(-15, 4))
    heavy.add_box(0.3, 0.3, density=3)
    light = world.create_body("dynamic", position=(-17, 4))
    light.add_box(0.3, 0.3)

    hinge = world.revolute_joint(ground, bob, anchor=(-8, 8), limit=mk.JointLimit(-1, 1))
    rail = world.prismatic_joint(ground, slider, anchor=(-10, 6), axis=(1, 1),
                                 motor=mk.JointMotor(speed=0.5, max_force=100))
    world.distance_joint(bob, ball, anchor_a=(-8, 6), anchor_b=(-6, 3),
                         spring=mk.JointSpring(hertz=2, damping_ratio=0.5))
    world.weld_joint(plank, pentagon, anchor=(1, 3), angular_hertz=5)
    world.wheel_joint(ground, wheel, anchor=(8, 2), axis=(0, 1),
                      motor=mk.JointMotor(speed=-3, max_force=20))
    world.motor_joint(ground, driven, linear_offset=(12, 5), max_force=50)
    world.gear_joint(hinge, rail, ratio=2)
    world.pulley_joint(heavy, light, ground_a=(-15, 8), ground_b=(-17, 8), anchor_a=(-15, 4),
                       anchor_b=(-17, 4), ratio=1.5, break_force=40)
    return world


def test_load_scene_keeps_the_files_body_order(source_dir):
    path = source_dir / "scenes" / "heavy_chain.json"
    world = mk.load_scene(path)
    bodies = json.loads(path.read_text())["bodies"]
    assert world.body_count == len(bodies)
    expected = [body.get("position", [0, 0]) for body in bodies]
    assert world.positions().tolist() == expected
    assert [b.index for b in world.bodies] == list(range(len(bodies)))
    assert world.scene_bodies == world.bodies
    assert world.settings["enable_sleep"] is False
    assert mk.load_scene(str(path), substeps=2).settings["substeps"] == 2


def test_a_world_built_from_python_equals_the_scene_file(data_dir):
    from_file = mk.load_scene(data_dir / "every_kind.json")
    from_python = every_kind_from_python()
    assert from_python.settings == from_file.settings
    assert [s.type for s in from_python.shapes] == [s.type for s in from_file.shapes]
    assert [j.type for j in from_python.joints] == [j.type for j in from_file.joints]
    assert from_python.state_hash == from_file.state_hash
    # The same bodies, shapes and joints made in the same order step bitwise alike.
    for _ in range(4):
        from_file.step(30)
        from_python.step(30)
        for array in ("positions", "angles", "linear_velocities", "angular_velocities"):
            numpy.testing.assert_array_equal(getattr(from_python, array)(),
                                             getattr(from_file, array)())
    assert [j.coordinate for j in from_python.joints] == [j.coordinate for j in from_file.joints]
    assert from_python.to_json() == from_file.to_json()
    assert from_python.state_hash == from_file.state_hash


def test_to_json_and_parse_scene_round_trip(tmp_path):
    world = every_kind_from_python()
    world.step(20)
    text = world.to_json()
    again = mk.parse_scene(text)
    numpy.testing.assert_array_equal(again.positions(), world.positions())
    numpy.testing.assert_array_equal(again.linear_velocities(), world.linear_velocities())
    path = tmp_path / "saved" / "scene.json"
    world.save(path)
    assert mk.load_scene(path).to_json() == text


def test_scene_file_errors_name_the_json_path(tmp_path):
    path = tmp_path / "bad.json"
    path.write_text('{"bodies": [{"type": "dynamic", "shapes": [{"circle": {"radius": -1}}]}]}')
    with pytest.raises(mk.SceneFileError) as raised:
        mk.load_scene(path)
    assert raised.value.json_path == "bodies[0].shapes[0].circle.radius"
    assert str(raised.value).startswith("bodies[0].shapes[0].circle.radius: must be > 0")
    with pytest.raises(mk.InvalidArgumentError, match="missing.json"):
        mk.load_scene(tmp_path / "missing.json")


def test_builtin_scenes_keep_their_schedules():
    assert "rain" in mk.builtin_scene_names() and "pyramid" in mk.builtin_scene_names()
    rain = mk.builtin_scene("rain")
    before = rain.body_count
    rain.step(9)  # the schedule drops 25 ragdolls every eighth step
    assert rain.body_count > before
    exported = json.loads(mk.builtin_scene_json("pyramid"))
    assert len(exported["bodies"]) == mk.builtin_scene("pyramid").body_count
    with pytest.raises(mk.InvalidArgumentError, match="nosuch"):
        mk.builtin_scene("nosuch")
