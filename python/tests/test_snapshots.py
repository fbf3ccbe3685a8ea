"""Snapshots, rollback and pickling: a world restored or unpickled continues bitwise as the
one it came from; bad snapshots raise SnapshotError and leave the world as it was."""

import pickle

import numpy
import pytest

import minkowski as mk


def state(world):
    return [getattr(world, array)().copy()
            for array in ("positions", "angles", "linear_velocities", "angular_velocities")]


def assert_same_state(a, b):
    assert a.state_hash == b.state_hash
    for x, y in zip(state(a), state(b)):
        numpy.testing.assert_array_equal(x, y)


def tumbling_world():
    world = mk.World(gravity=(0, -9.8))
    ground = world.create_body("static")
    ground.add_box(10, 0.5)
    for i in range(12):
        body = world.create_body("dynamic", position=(0.3 * (i % 3), 1 + 0.9 * i), angle=0.2 * i)
        if i % 3 == 0:
            body.add_circle(0.35)
        elif i % 3 == 1:
            body.add_box(0.4, 0.3, friction=0.4)
        else:
            body.add_capsule((-0.3, 0), (0.3, 0), 0.15)
    return world


def test_restore_rolls_back_in_place_and_repeats_the_run():
    world = tumbling_world()
    world.step(40)  # bodies in flight and landing: contacts with warm-start impulses
    snapshot = world.snapshot()
    hash_then = world.state_hash
    world.step(60)
    after = state(world)
    hash_after = world.state_hash
    made_later = world.create_body("dynamic", position=(3, 3))
    world.restore(snapshot)
    assert world.state_hash == hash_then
    with pytest.raises(mk.StaleIdError):
        made_later.position
    world.step(60)
    assert world.state_hash == hash_after
    for x, y in zip(state(world), after):
        numpy.testing.assert_array_equal(x, y)


def test_a_pickled_world_continues_bitwise():
    world = tumbling_world()
    world.step(45)
    copy = pickle.loads(pickle.dumps(world))
    assert_same_state(copy, world)
    world.step(80)
    copy.step(80)
    assert_same_state(copy, world)


def test_a_pickled_scheduled_scene_keeps_its_schedule():
    # rain makes and removes ragdolls as it runs: the copy must go on doing so alike.
    world = mk.builtin_scene("rain", workers=2)
    world.step(30)
    copy = pickle.loads(pickle.dumps(world))
    for _ in range(3):
        world.step(20)
        copy.step(20)
        assert world.body_count == copy.body_count
        assert_same_state(copy, world)


def test_bad_snapshots_raise_and_leave_the_world_as_it_was():
    world = tumbling_world()
    world.step(30)
    snapshot = world.snapshot()
    world.step(10)
    before = world.state_hash
    with pytest.raises(mk.SnapshotError, match="truncated"):
        world.restore(snapshot[: len(snapshot) // 2])
    flipped = bytearray(snapshot)
    flipped[len(flipped) // 3] ^= 0x10
    with pytest.raises(mk.SnapshotError):
        world.restore(bytes(flipped))
    fmt, scene, workers, _ = world.__getstate__()
    with pytest.raises(mk.SnapshotError, match="truncated"):
        mk.World.__new__(mk.World).__setstate__((fmt, scene, workers, snapshot[:100]))
    with pytest.raises(mk.SnapshotError, match="pickled World"):
        mk.World.__new__(mk.World).__setstate__((fmt + 1, scene, workers, snapshot))
    assert world.state_hash == before
