"""Sweeps on Dask: variants of a scene or a factory, each in its own world on a cluster's
workers, as a DataFrame with one row per variant; `mink sweep` from the command line."""

import io
import json
import os
import shutil
import subprocess
import sys

import numpy
import pandas
import pytest

import minkowski as mk
from minkowski.sweeps import expand_parameters, set_scene_value

distributed = pytest.importorskip("dask.distributed")


@pytest.fixture(scope="module")
def cluster():
    """Two single-threaded worker processes, shared by the tests that bring their own client."""
    import logging
    local = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                     dashboard_address=None, silence_logs=logging.ERROR)
    yield local
    local.close()


@pytest.fixture(scope="module")
def client(cluster):
    with distributed.Client(cluster) as connected:
        yield connected


def weight_height(world):
    return {"y": world.positions([11])[0, 1], "gravity": world.gravity[1]}


def test_a_two_worker_local_cluster_sweep_of_50_variants_returns_50_rows(source_dir):
    scene = source_dir / "scenes" / "heavy_chain.json"
    gravities = [[0.0, -g] for g in numpy.linspace(2, 20, 10)]
    densities = [-1, 50, 100, 200, 300]  # -1 is refused by the scene reader
    table = mk.sweep(scene, {"world.gravity": gravities,
                             "bodies[11].shapes[0].density": densities},
                     weight_height, steps=30, workers=2, progress=False)
    assert isinstance(table, pandas.DataFrame)
    assert len(table) == 50
    assert list(table.columns) == ["world.gravity", "bodies[11].shapes[0].density", "y",
                                   "gravity", "error", "seconds"]
    # Grid order: the first parameter varies slowest.
    assert table["bodies[11].shapes[0].density"].tolist() == densities * 10
    failed = table[table["error"].notna()]
    assert len(failed) == 10
    assert (failed["bodies[11].shapes[0].density"] == -1).all()
    assert failed["error"].iloc[0] == (
        "SceneFileError: bodies[11].shapes[0].density: must be >= 0, got -1")
    assert failed["y"].isna().all()
    done = table[table["error"].isna()]
    assert done["gravity"].tolist() == [g[1] for g in gravities for _ in range(4)]
    # Each row is what the same variant gives when run here: a sweep changes nothing.
    row = done.iloc[5]
    local = json.loads(scene.read_text())
    local["bodies"][11]["shapes"][0]["density"] = int(row["bodies[11].shapes[0].density"])
    world = mk.parse_scene(json.dumps(local), gravity=row["world.gravity"])
    world.step(30)
    assert world.positions([11])[0, 1] == row["y"]


def test_a_factory_sweep_on_a_given_client(client):
    def drop(height, substeps):
        if height < 0:
            raise ValueError(f"no drop from {height} m")
        world = mk.World(gravity=(0, -10), substeps=substeps)
        world.create_body("dynamic", position=(0, height)).add_circle(0.5)
        return world

    table = mk.sweep(drop, [{"height": h, "substeps": s} for h in (10, -1, 30) for s in (1, 4)],
                     lambda world: world.positions()[0, 1], client=client, steps=60,
                     progress=False)
    assert len(table) == 6
    assert table["error"].tolist()[2:4] == ["ValueError: no drop from -1 m"] * 2
    for _, row in table[table["error"].isna()].iterrows():
        # Free fall in closed form (semi-implicit Euler over every substep).
        m = 60 * row["substeps"]
        h = (1 / 60) / row["substeps"]
        assert row["value"] == pytest.approx(row["height"] - 10 * h * h * m * (m + 1) / 2)


def test_measures_may_take_the_variant(client):
    table = mk.sweep("pyramid", {"world.substeps": [2, 3]},
                     lambda world, variant: {"substeps": world.settings["substeps"],
                                             "asked": variant["world.substeps"]},
                     client=client, progress=False)
    assert table["substeps"].tolist() == [2, 3] and table["asked"].tolist() == [2, 3]


def test_parameters_expand_and_scene_paths_resolve():
    assert expand_parameters({"a": [1, 2], "b": numpy.array([3.0, 4.0])}) == [
        {"a": 1, "b": 3.0}, {"a": 1, "b": 4.0}, {"a": 2, "b": 3.0}, {"a": 2, "b": 4.0}]
    frame = pandas.DataFrame({"a": [1, 2]})
    assert expand_parameters(frame) == [{"a": 1}, {"a": 2}]
    with pytest.raises(mk.InvalidArgumentError, match="expected a list of values"):
        expand_parameters({"a": 3})
    scene = {"world": {}, "bodies": [{"shapes": [{"friction": 1}]}]}
    set_scene_value(scene, "bodies[0].shapes[0].friction", 0.2)
    set_scene_value(scene, "world.substeps", 8)
    assert scene == {"world": {"substeps": 8}, "bodies": [{"shapes": [{"friction": 0.2}]}]}
    with pytest.raises(mk.InvalidArgumentError, match="no such value"):
        set_scene_value(scene, "bodies[3].angle", 1)
    with pytest.raises(mk.InvalidArgumentError, match="not a scene path"):
        set_scene_value(scene, "bodies.3", 1)


def mink():
    binary = os.environ.get("MINK_BINARY")
    if not binary or not os.path.exists(binary):
        pytest.skip("MINK_BINARY (the mink command) is not set")
    return binary


def test_mink_sweep_hands_over_to_python_on_a_scheduler(cluster, source_dir, tmp_path):
    out = tmp_path / "sweep.csv"
    run = subprocess.run(
        [mink(), "sweep", str(source_dir / "scenes" / "heavy_chain.json"),
         "--vary", "world.gravity=[0,-10],[0,-5]", "--vary", "world.substeps=2:8:4",
         "--steps", "20", "--track", "11", "--scheduler", cluster.scheduler_address,
         "--out", str(out), "--no-progress"],
        capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    assert "8 variants" in run.stderr and "0 failed" in run.stderr
    table = pandas.read_csv(out)
    assert len(table) == 8
    assert table["world.substeps"].tolist() == [2, 4, 6, 8] * 2
    assert {"kinetic_energy", "awake_bodies", "body11_x", "body11_w", "error"} <= set(table)
    assert table["steps"].tolist() == [20] * 8


def test_mink_sweep_errors_and_exit_codes(tmp_path, source_dir):
    binary = mink()
    scene = str(source_dir / "scenes" / "heavy_chain.json")
    usage = subprocess.run([binary, "sweep", scene, "--vary", "bodies[99].angle=0:1:2"],
                           capture_output=True, text=True, timeout=120)
    assert usage.returncode == 2
    assert "parameter 'bodies[99].angle" in usage.stderr
    no_python = subprocess.run([binary, "sweep", scene], capture_output=True, text=True,
                               env={**os.environ, "MINK_PYTHON": str(tmp_path / "python3")},
                               timeout=60)
    assert no_python.returncode == 4
    assert "sweep needs Python 3" in no_python.stderr
    # A copy of mink outside the build tree, with no PYTHONPATH, finds no module.
    lonely = tmp_path / "bin" / "mink"
    lonely.parent.mkdir()
    shutil.copy(binary, lonely)
    env = {key: value for key, value in os.environ.items() if key != "PYTHONPATH"}
    env["MINK_PYTHON"] = sys.executable
    no_module = subprocess.run([str(lonely), "sweep", scene], capture_output=True, text=True,
                               env=env, cwd=tmp_path, timeout=60)
    assert no_module.returncode == 4
    assert "needs the Python module minkowski" in no_module.stderr


def test_python_m_minkowski_help():
    run = subprocess.run([sys.executable, "-m", "minkowski", "sweep", "--help"],
                         capture_output=True, text=True, timeout=60)
    assert run.returncode == 0
    assert "--vary KEY=a:b:n" in run.stdout
    assert io.StringIO(run.stdout).readline().startswith("usage: python3 -m minkowski sweep")
