"""Parameter sweeps on a Dask cluster: every variant of a scene in its own world.

``sweep(scene_or_factory, parameters, measure)`` builds one world per variant on the workers of
a ``dask.distributed`` cluster (a ``LocalCluster`` on this machine unless a client or a
scheduler address is given), measures it, and returns a pandas DataFrame with one row per
variant in the order of ``parameters``. A variant that fails keeps its row: its ``error``
column holds the exception's type and message, its measured columns are missing (NaN).
"""

import copy
import inspect
import itertools
import json
import math
import os
import re
import sys
import time
import uuid
from collections.abc import Mapping
from pathlib import Path

import minkowski

__all__ = ["sweep", "expand_parameters", "set_scene_value"]

_PATH_PART = re.compile(r"([A-Za-z_][A-Za-z0-9_]*)|\[(\d+)\]")


def _path_parts(path):
    """'bodies[3].shapes[0].friction' -> ['bodies', 3, 'shapes', 0, 'friction']."""
    parts = []
    for piece in path.split("."):
        position = 0
        if not piece:
            raise minkowski.InvalidArgumentError(f"parameter '{path}': empty key")
        while position < len(piece):
            match = _PATH_PART.match(piece, position)
            if match is None or (match.group(1) and position != 0):
                raise minkowski.InvalidArgumentError(
                    f"parameter '{path}': not a scene path like bodies[3].shapes[0].friction")
            parts.append(match.group(1) if match.group(1) else int(match.group(2)))
            position = match.end()
    return parts


def set_scene_value(scene, path, value):
    """Sets the value at a scene-file path ('world.gravity', 'bodies[3].shapes[0].friction',
    'joints[0].motor.speed') in a scene parsed from JSON. Every step but the last must exist;
    the last key of an object may be new (a setting left at its default in the file)."""
    parts = _path_parts(path)
    node = scene
    for depth, part in enumerate(parts[:-1]):
        try:
            node = node[part]
        except (KeyError, IndexError, TypeError):
            where = path if depth == 0 else f"{path} (at {parts[depth]!r})"
            raise minkowski.InvalidArgumentError(
                f"parameter '{where}': the scene has no such value") from None
    last = parts[-1]
    if isinstance(last, int):
        if not isinstance(node, list) or last >= len(node):
            raise minkowski.InvalidArgumentError(f"parameter '{path}': the scene has no such value")
    elif not isinstance(node, dict):
        raise minkowski.InvalidArgumentError(f"parameter '{path}': the scene has no such value")
    node[last] = value


def expand_parameters(parameters):
    """The variants a parameters argument names, as a list of dicts:

    - a dict of name -> list of values: every combination (a grid), the first name varying
      slowest;
    - a list of dicts: those variants, as given;
    - a pandas DataFrame: one variant per row.
    """
    if hasattr(parameters, "to_dict") and hasattr(parameters, "columns"):
        return [dict(row) for row in parameters.to_dict("records")]
    if isinstance(parameters, Mapping):
        names = list(parameters)
        values = []
        for name in names:
            choices = parameters[name]
            if isinstance(choices, (str, bytes)) or not hasattr(choices, "__iter__"):
                raise minkowski.InvalidArgumentError(
                    f"parameter '{name}': expected a list of values, got {choices!r}")
            values.append([_plain(v) for v in choices])
        return [dict(zip(names, combination)) for combination in itertools.product(*values)]
    variants = [dict(variant) for variant in parameters]
    for i, variant in enumerate(variants):
        if not all(isinstance(key, str) for key in variant):
            raise minkowski.InvalidArgumentError(f"variant {i}: parameter names must be strings")
    return variants


def _plain(value):
    """numpy scalars and arrays as Python values (for JSON and the DataFrame)."""
    if hasattr(value, "tolist"):
        return value.tolist()
    return value


class _SceneSource:
    """Builds each variant from scene-file JSON: keys 'world.X' are world settings, other keys
    are scene paths. A built-in named without scene paths keeps its schedule."""

    def __init__(self, scene):
        self.builtin = None
        if isinstance(scene, (str, os.PathLike)) and str(scene) in minkowski.builtin_scene_names():
            self.builtin = str(scene)
            self.text = minkowski.builtin_scene_json(self.builtin)
        elif isinstance(scene, (str, os.PathLike)):
            path = Path(scene)
            if not path.is_file():
                raise minkowski.InvalidArgumentError(
                    f"'{scene}' is neither a built-in scene nor a scene file")
            self.text = path.read_text()
        else:
            raise minkowski.InvalidArgumentError(
                "sweep: scene_or_factory must be a scene file, a built-in scene's name or a "
                f"callable returning a World, got {scene!r}")
        self.scene = json.loads(self.text)

    def build(self, variant):
        settings = {}
        edits = {}
        for key, value in variant.items():
            parts = key.split(".")
            if len(parts) == 2 and parts[0] == "world" and "[" not in parts[1]:
                settings[parts[1]] = value
            else:
                edits[key] = value
        if not edits and self.builtin is not None:
            return minkowski.builtin_scene(self.builtin, **settings)
        if not edits:
            return minkowski.parse_scene(self.text, **settings)
        scene = copy.deepcopy(self.scene)
        for key, value in edits.items():
            set_scene_value(scene, key, _plain(value))
        return minkowski.parse_scene(json.dumps(scene), **settings)


class _FactorySource:
    """Builds each variant by calling factory(**variant)."""

    def __init__(self, factory):
        self.factory = factory

    def build(self, variant):
        world = self.factory(**variant)
        if not isinstance(world, minkowski.World):
            raise TypeError(f"the factory returned {type(world).__name__}, not a minkowski.World")
        return world


def _takes_variant(measure):
    """True when measure(world, variant) rather than measure(world)."""
    try:
        parameters = inspect.signature(measure).parameters.values()
    except (TypeError, ValueError):
        return False
    positional = [p for p in parameters
                  if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD, p.VAR_POSITIONAL)]
    return len(positional) >= 2 or any(p.kind == p.VAR_POSITIONAL for p in positional)


def _columns(result):
    if isinstance(result, Mapping):
        return {str(key): _plain(value) for key, value in result.items()}
    return {"value": _plain(result)}


def run_variant(source, variant, measure, steps):
    """One variant, on a worker: build, step, measure. Never raises: a failure is returned."""
    started = time.perf_counter()
    try:
        world = source.build(variant)
        if steps:
            world.step(steps)
        result = measure(world, variant) if _takes_variant(measure) else measure(world)
        return {"values": _columns(result), "error": None,
                "seconds": time.perf_counter() - started}
    except Exception as error:  # every failure belongs in its variant's row
        return {"values": {}, "error": f"{type(error).__name__}: {error}",
                "seconds": time.perf_counter() - started}


class _Progress:
    """tqdm's bar when tqdm is installed, else a line on stderr every tenth of the variants."""

    def __init__(self, total, enabled):
        self.total = total
        self.done = 0
        self.bar = None
        self.enabled = enabled and total > 0
        if self.enabled:
            try:
                from tqdm import tqdm
                self.bar = tqdm(total=total, desc="sweep", unit="variant", file=sys.stderr)
            except ImportError:
                pass

    def update(self):
        self.done += 1
        if not self.enabled:
            return
        if self.bar is not None:
            self.bar.update(1)
        elif self.done * 10 // self.total != (self.done - 1) * 10 // self.total:
            print(f"sweep: {self.done} of {self.total} variants", file=sys.stderr)

    def close(self):
        if self.bar is not None:
            self.bar.close()


def _open_client(client, workers):
    """(client, things to close): the given client, one for a scheduler address, or a
    LocalCluster of `workers` single-threaded processes on this machine."""
    try:
        from dask.distributed import Client, LocalCluster
    except ImportError as error:
        raise ImportError(
            "minkowski.sweep needs dask.distributed (Debian: sudo apt-get install "
            f"python3-distributed): {error}") from error
    if client is None:
        import logging
        cluster = LocalCluster(n_workers=workers or os.cpu_count() or 1, threads_per_worker=1,
                               processes=True, dashboard_address=None,
                               silence_logs=logging.ERROR)
        opened = Client(cluster)
        return opened, [opened, cluster]
    if isinstance(client, str):
        opened = Client(client)
        return opened, [opened]
    return client, []


def sweep(scene_or_factory, parameters, measure, client=None, *, steps=0, workers=None,
          progress=True):
    """Runs every variant in its own world on a Dask cluster; returns a pandas DataFrame.

    scene_or_factory: a scene file's path or a built-in scene's name, whose variants set
        scene values by path ('world.gravity', 'bodies[2].shapes[0].restitution',
        'joints[0].motor.speed'; keys 'world.X' are applied as World settings, so a built-in
        keeps its schedule), or a callable factory(**variant) returning a World.
    parameters: a dict of name -> values (every combination), a list of dicts (those
        variants) or a pandas DataFrame (one variant per row).
    measure: measure(world) or measure(world, variant), called after `steps` steps (it may
        step further itself); returns a dict of columns or one value (column 'value').
    client: None for a LocalCluster of `workers` processes (default: one per core) made and
        closed here; a scheduler address ('tcp://host:8786') to use a running cluster; or a
        dask.distributed.Client. Workers of a remote cluster need minkowski installed.
    progress: a progress bar (tqdm's, when installed) on stderr.

    The DataFrame has one row per variant, in the order given: the parameters, the measured
    columns, 'error' (None, or 'Type: message' for a variant that failed; its measured
    columns are NaN) and 'seconds' (the variant's time on its worker).
    """
    import pandas

    variants = expand_parameters(parameters)
    if callable(scene_or_factory) and not isinstance(scene_or_factory, (str, os.PathLike)):
        source = _FactorySource(scene_or_factory)
    else:
        source = _SceneSource(scene_or_factory)
    if not callable(measure):
        raise minkowski.InvalidArgumentError(f"sweep: measure must be callable, got {measure!r}")
    if int(steps) < 0:
        raise minkowski.InvalidArgumentError(f"sweep: steps must be >= 0, got {steps}")

    outcomes = [None] * len(variants)
    if variants:
        dask_client, to_close = _open_client(client, workers)
        bar = _Progress(len(variants), progress)
        try:
            from dask.distributed import as_completed
            shared_source = dask_client.scatter(source, broadcast=True, hash=False)
            token = uuid.uuid4().hex
            futures = []
            index_of = {}
            for i, variant in enumerate(variants):
                future = dask_client.submit(run_variant, shared_source, variant, measure,
                                            int(steps), key=f"minkowski-sweep-{token}-{i}",
                                            pure=False)
                futures.append(future)
                index_of[future.key] = i
            for future in as_completed(futures):
                i = index_of[future.key]
                try:
                    outcomes[i] = future.result()
                except Exception as error:  # a worker lost, a result that did not travel
                    outcomes[i] = {"values": {}, "error": f"{type(error).__name__}: {error}",
                                   "seconds": math.nan}
                bar.update()
        finally:
            bar.close()
            for thing in to_close:
                thing.close()

    measured = []
    for outcome in outcomes:
        for name in outcome["values"]:
            if name not in measured:
                measured.append(name)
    rows = []
    for variant, outcome in zip(variants, outcomes):
        row = dict(variant)
        for name in measured:
            row[name] = outcome["values"].get(name, math.nan)
        row["error"] = outcome["error"]
        row["seconds"] = outcome["seconds"]
        rows.append(row)
    names = list(dict.fromkeys(itertools.chain.from_iterable(variants)))
    return pandas.DataFrame(rows, columns=names + measured + ["error", "seconds"])

