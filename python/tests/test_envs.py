"""The example environments (examples/python): the Gymnasium interface without Gymnasium,
seeding, rendering, and the lander through 1,000 random episodes."""

import sys

import numpy
import pytest

import minkowski as mk
from minkowski.envs import HAVE_GYMNASIUM, spaces


@pytest.fixture(scope="module")
def examples(request):
    from conftest import SOURCE_DIR
    sys.path.insert(0, str(SOURCE_DIR / "examples" / "python"))
    import lander
    import rollout
    import walker
    yield lander, walker, rollout
    sys.path.remove(str(SOURCE_DIR / "examples" / "python"))


def trajectory(env, seed, steps):
    observation, info = env.reset(seed=seed)
    env.action_space.seed(seed)
    out = [observation]
    for _ in range(steps):
        observation, reward, terminated, truncated, info = env.step(env.action_space.sample())
        out.append(observation)
        if terminated or truncated:
            break
    return numpy.array(out)


def test_the_lander_has_the_gymnasium_interface(examples):
    lander, _, _ = examples
    env = lander.LunarLander(render_mode="rgb_array")
    observation, info = env.reset(seed=1)
    assert observation.shape == (8,) and observation.dtype == numpy.float32
    assert info == {}
    assert env.observation_space.contains(observation)
    assert isinstance(env.action_space, spaces.Discrete) and env.action_space.n == 4
    result = env.step(2)
    assert len(result) == 5
    observation, reward, terminated, truncated, info = result
    assert isinstance(reward, float)
    assert isinstance(terminated, bool) and isinstance(truncated, bool)
    frame = env.render()
    assert frame.shape == (400, 600, 3) and frame.dtype == numpy.uint8
    with pytest.raises(mk.InvalidArgumentError):
        env.step(7)
    # The same seed gives the same episode.
    numpy.testing.assert_array_equal(trajectory(env, 5, 60), trajectory(env, 5, 60))
    assert not numpy.array_equal(trajectory(env, 5, 60), trajectory(env, 6, 60))
    continuous = lander.LunarLander(continuous=True)
    continuous.reset(seed=0)
    assert continuous.action_space.shape == (2,)
    continuous.step(numpy.array([1.0, -1.0], dtype=numpy.float32))
    assert HAVE_GYMNASIUM or not hasattr(env, "spec") or env.spec is None


def test_the_heuristic_lands_the_lander(examples):
    _, _, rollout = examples
    result = rollout.rollout("lander", 10, seed=0, policy="heuristic")
    # Landing earns: the controller's mean return is far above a crash's -100.
    assert result["mean_return"] > 0


def test_the_lander_runs_1000_random_episodes(examples):
    _, _, rollout = examples
    result = rollout.rollout("lander", 1000, seed=0)
    assert result["episodes"] == 1000
    assert result["terminated"] + result["truncated"] == 1000
    assert result["steps"] > 1000


def test_the_walker_walks_randomly_without_error(examples, tmp_path):
    _, walker, rollout = examples
    env = walker.BipedalWalker(render_mode="rgb_array", max_episode_steps=150)
    observation, _ = env.reset(seed=0)
    assert observation.shape == (24,)
    assert numpy.all((observation[14:] > 0) & (observation[14:] <= 1))  # lidar fractions
    frame = env.render()
    assert frame.shape == (400, 600, 3)
    result = rollout.rollout("walker", 3, seed=0, frame=tmp_path / "walker.png", frame_step=20,
                             max_episode_steps=150)
    assert result["episodes"] == 3 and (tmp_path / "walker.png").exists()
