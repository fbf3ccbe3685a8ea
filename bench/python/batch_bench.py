"""Stepping 1,000 bodies and reading their states back: Python's batch arrays against the same
loop in C++ (mink_bench_python_twin), and the per-body Python loop beside them.

    python3 bench/python/batch_bench.py BUILD_DIR CSV [--rounds R] [--steps K]

Each round builds the scene afresh in each implementation and runs K steps, taking turns
(C++, Python batch, Python per body), so that a busy machine slows them alike; every step and
every read is timed in the thread's CPU time (CLOCK_THREAD_CPUTIME_ID; time.thread_time_ns),
which other processes do not inflate. The scene: 1,000 dynamic boxes in 40 stacks of 25 on a
ground box, sleep off, so that each step costs about the same. Writes case,size,
implementation,median_ns rows: step_and_read (a step plus the read), read_states (the read
alone), for cpp, python_batch and python_per_body.
"""

import argparse
import json
import pathlib
import statistics
import subprocess
import sys
import tempfile
import time


def scene_json():
    bodies = [{"type": "static", "position": [0, -0.5],
               "shapes": [{"box": {"half_extents": [30, 0.5]}}]}]
    for column in range(40):
        for row in range(25):
            bodies.append({"type": "dynamic",
                           "position": [-19.5 + column, 0.2 + 0.4 * row],
                           "shapes": [{"box": {"half_extents": [0.2, 0.2]}}]})
    return json.dumps({"format": "minkowski-scene", "version": 1,
                       "world": {"enable_sleep": False}, "bodies": bodies})


def read_batch(world):
    """Every state through the batch arrays."""
    return (world.positions(), world.angles(), world.linear_velocities(),
            world.angular_velocities())


def read_per_body(world):
    """Every state through a property per body and state."""
    return [(b.position, b.angle, b.linear_velocity, b.angular_velocity) for b in world.bodies]


def python_loop(minkowski, path, steps, read):
    """(step ns, read ns) of each step, in the thread's CPU time."""
    world = minkowski.load_scene(path)
    out = []
    for _ in range(steps):
        start = time.thread_time_ns()
        world.step()
        stepped = time.thread_time_ns()
        read(world)
        done = time.thread_time_ns()
        out.append((stepped - start, done - stepped))
    return out


def cpp(twin, path, steps):
    run = subprocess.run([str(twin), str(path), str(steps)], capture_output=True, text=True,
                         check=True)
    return [tuple(int(v) for v in line.split(",")) for line in run.stdout.split()]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("build_dir")
    parser.add_argument("csv")
    parser.add_argument("--rounds", type=int, default=10)
    parser.add_argument("--steps", type=int, default=200)
    options = parser.parse_args()
    build = pathlib.Path(options.build_dir).resolve()
    sys.path.insert(0, str(build / "python"))
    import minkowski

    twin = build / "bin" / "mink_bench_python_twin"
    times = {"cpp": [], "python_batch": [], "python_per_body": []}
    with tempfile.TemporaryDirectory() as scratch:
        path = pathlib.Path(scratch) / "boxes_1000.json"
        path.write_text(scene_json())
        assert minkowski.load_scene(path).body_count == 1001
        for round_index in range(options.rounds):
            times["cpp"] += cpp(twin, path, options.steps)
            times["python_batch"] += python_loop(minkowski, path, options.steps, read_batch)
            times["python_per_body"] += python_loop(minkowski, path, options.steps,
                                                    read_per_body)
            print(f"round {round_index + 1} of {options.rounds}", file=sys.stderr)
    rows = ["case,size,implementation,median_ns"]
    medians = {}
    for name, samples in times.items():
        both = statistics.median(step + read for step, read in samples)
        read = statistics.median(read for _, read in samples)
        medians[name] = (both, read)
        rows.append(f"step_and_read,1000,{name},{both:.0f}")
        rows.append(f"read_states,1000,{name},{read:.0f}")
    pathlib.Path(options.csv).write_text("\n".join(rows) + "\n")
    print(f"wrote {options.csv}")
    cpp_both, cpp_read = medians["cpp"]
    for name in ("python_batch", "python_per_body"):
        both, read = medians[name]
        print(f"{name} / cpp: step and read {both / cpp_both:.3f}, read alone {read / cpp_read:.2f} "
              f"({both / 1e3:.0f} us vs {cpp_both / 1e3:.0f} us a step; thread CPU time)")


if __name__ == "__main__":
    main()
