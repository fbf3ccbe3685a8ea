"""Random-policy rollouts of the example environments (no Gymnasium needed).

    python3 examples/python/rollout.py --env lander --episodes 1000
    python3 examples/python/rollout.py --env walker --episodes 5 --frame walker.png

Prints the episodes, steps, how the episodes ended and the mean return; --frame saves a frame
of the first episode (at --frame-step) as a PNG. --policy heuristic flies the lander with a
hand-written controller instead of at random.
"""

import argparse
import pathlib
import sys
import time

import numpy

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))

import minkowski  # noqa: E402
from lander import LunarLander  # noqa: E402
from walker import BipedalWalker  # noqa: E402

ENVIRONMENTS = {"lander": LunarLander, "walker": BipedalWalker}


def heuristic(observation):
    """A lander controller: lean towards the pad, hold a descent rate that shrinks near it."""
    x, y, vx, vy, angle, spin, left, right = observation
    angle_target = numpy.clip(x * 0.5 + vx * 1.0, -0.4, 0.4)
    hover_target = 0.55 * abs(x)
    angle_todo = (angle_target - angle) * 0.5 - spin * 1.0
    hover_todo = (hover_target - y) * 0.5 - vy * 0.5
    if left or right:
        angle_todo, hover_todo = 0.0, -vy * 0.5
    if hover_todo > abs(angle_todo) and hover_todo > 0.05:
        return 2
    if angle_todo < -0.05:
        return 3
    if angle_todo > 0.05:
        return 1
    return 0


def rollout(env_name, episodes, seed=0, policy="random", frame=None, frame_step=40,
            max_episode_steps=None):
    """Runs the episodes; returns a dict of counts, the mean return and the time taken."""
    settings = {"render_mode": "rgb_array"} if frame else {}
    if max_episode_steps:
        settings["max_episode_steps"] = max_episode_steps
    env = ENVIRONMENTS[env_name](**settings)
    env.action_space.seed(seed)
    endings = {"terminated": 0, "truncated": 0}
    returns = []
    steps = 0
    started = time.perf_counter()
    for episode in range(episodes):
        observation, _ = env.reset(seed=seed + episode)
        total, done, step = 0.0, False, 0
        while not done:
            if policy == "heuristic":
                action = heuristic(observation)
            else:
                action = env.action_space.sample()
            observation, reward, terminated, truncated, _ = env.step(action)
            if not env.observation_space.contains(observation):
                raise RuntimeError(f"episode {episode}: observation {observation} out of space")
            total += reward
            step += 1
            if frame and episode == 0 and step == frame_step:
                minkowski.save_png(frame, env.render())
            done = terminated or truncated
        endings["terminated" if terminated else "truncated"] += 1
        returns.append(total)
        steps += step
    env.close()
    return {"episodes": episodes, "steps": steps, **endings,
            "mean_return": float(numpy.mean(returns)) if returns else 0.0,
            "seconds": time.perf_counter() - started}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--env", choices=sorted(ENVIRONMENTS), default="lander")
    parser.add_argument("--episodes", type=int, default=10)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--policy", choices=["random", "heuristic"], default="random")
    parser.add_argument("--max-episode-steps", type=int, default=None)
    parser.add_argument("--frame", default=None, help="PNG of the first episode")
    parser.add_argument("--frame-step", type=int, default=40)
    options = parser.parse_args()
    if options.policy == "heuristic" and options.env != "lander":
        parser.error("--policy heuristic flies the lander only")
    result = rollout(options.env, options.episodes, options.seed, options.policy, options.frame,
                     options.frame_step, options.max_episode_steps)
    print(f"{options.env}: {result['episodes']} episodes, {result['steps']} steps "
          f"({result['terminated']} terminated, {result['truncated']} truncated), "
          f"mean return {result['mean_return']:.1f}, {result['seconds']:.1f} s")


if __name__ == "__main__":
    main()
