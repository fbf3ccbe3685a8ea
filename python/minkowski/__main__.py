"""python3 -m minkowski sweep SCENE --vary KEY=a:b:n ... (what `mink sweep` runs).

Exit codes as the mink command's: 0 success (failed variants are reported in their rows and
counted on stderr), 2 bad input or usage, 4 the environment failed (dask missing, no
scheduler, an output that cannot be written).
"""

import argparse
import importlib
import json
import os
import sys
import tempfile

EXIT_BAD_INPUT = 2
EXIT_RUNTIME_FAILURE = 4
EXIT_OUTPUT_FAILURE = 5


class UsageError(Exception):
    pass


def parse_vary(text):
    """KEY=a:b:n (n values from a to b, evenly; integers when a and b are) or KEY=v1,v2,...
    (JSON values) -> (KEY, values)."""
    key, equals, values = text.partition("=")
    if not equals or not key or not values:
        raise UsageError(f"--vary takes KEY=a:b:n or KEY=v1,v2,..., got '{text}'")
    parts = values.split(":")
    if len(parts) == 3:
        try:
            first, last = json.loads(parts[0]), json.loads(parts[1])
            count = int(parts[2])
        except ValueError:
            raise UsageError(f"--vary {key}: a:b:n needs two numbers and a count, got '{values}'")
        if isinstance(first, bool) or isinstance(last, bool) or \
                not all(isinstance(v, (int, float)) for v in (first, last)) or count < 1:
            raise UsageError(f"--vary {key}: a:b:n needs two numbers and a count >= 1, "
                             f"got '{values}'")
        if count == 1:
            points = [first]
        else:
            points = [first + (last - first) * i / (count - 1) for i in range(count)]
        if isinstance(first, int) and isinstance(last, int) and \
                all(float(p).is_integer() for p in points):
            points = [int(p) for p in points]
        return key, points
    try:
        return key, json.loads("[" + values + "]")
    except ValueError:
        raise UsageError(f"--vary {key}: each of v1,v2,... must be a JSON value (2, 0.5, true, "
                         f"[0,-9.8]), got '{values}'")


def load_measure(name):
    """'module:function' -> that function."""
    module, colon, function = name.partition(":")
    if not colon or not module or not function:
        raise UsageError(f"--measure takes MODULE:FUNCTION, got '{name}'")
    try:
        return getattr(importlib.import_module(module), function)
    except (ImportError, AttributeError) as error:
        raise UsageError(f"--measure {name}: {error}")


def sweep_command(arguments, prog):
    parser = argparse.ArgumentParser(
        prog=prog,
        description="Runs every variant of a scene in its own world on a Dask cluster and "
                    "writes one CSV row per variant: the varied values, the measured columns "
                    "(time, steps, bodies, kinetic_energy, awake_bodies, touching_contacts, and "
                    "each --track body's x, y, angle, vx, vy, w), error and seconds.")
    parser.add_argument("scene", help="a scene file or a built-in scene's name")
    parser.add_argument("--vary", action="append", default=[], metavar="KEY=a:b:n",
                        help="a scene value by path (world.gravity, bodies[3].shapes[0].friction, "
                             "joints[0].motor.speed): n values from a to b, or KEY=v1,v2,... "
                             "(JSON values); several --vary make every combination")
    parser.add_argument("--workers", type=int, default=None,
                        help="processes of the local cluster (default: one per core)")
    parser.add_argument("--scheduler", default=None, metavar="ADDRESS",
                        help="a running Dask scheduler (tcp://host:8786) instead of a local "
                             "cluster")
    parser.add_argument("--steps", type=int, default=600, help="steps per variant (600)")
    parser.add_argument("--track", type=int, action="append", default=[], metavar="BODY",
                        help="also record this body's final state (its index in bodies)")
    parser.add_argument("--measure", default=None, metavar="MODULE:FUNCTION",
                        help="measure with this function of the world instead")
    parser.add_argument("--out", default="-", help="CSV file (default: standard output)")
    parser.add_argument("--no-progress", action="store_true", help="no progress bar")
    options = parser.parse_args(arguments)
    if options.workers is not None and options.workers < 1:
        raise UsageError("--workers must be at least 1")
    if options.steps < 0:
        raise UsageError("--steps must be >= 0")
    if not options.vary:
        raise UsageError("give at least one --vary KEY=a:b:n")

    import minkowski
    from minkowski import measures
    from minkowski.sweeps import expand_parameters, sweep, _SceneSource

    parameters = dict(parse_vary(text) for text in options.vary)
    if options.measure:
        measure = load_measure(options.measure)
    else:
        measure = measures.combine(measures.summary, measures.track(*options.track))
    # The scene and the first variant are checked here, so a typo is a usage error rather
    # than a row of failures.
    source = _SceneSource(options.scene)
    variants = expand_parameters(parameters)
    world = source.build(variants[0])
    for body in options.track:
        world.body(body)
    try:
        import dask.distributed  # noqa: F401
    except ImportError as error:
        print(f"{prog}: needs dask.distributed (Debian: sudo apt-get install python3-distributed "
              f"python3-pandas): {error}", file=sys.stderr)
        return EXIT_RUNTIME_FAILURE
    try:
        table = sweep(options.scene, variants, measure, client=options.scheduler,
                      steps=options.steps, workers=options.workers,
                      progress=not options.no_progress)
    except (OSError, TimeoutError) as error:
        print(f"{prog}: the cluster failed: {error}", file=sys.stderr)
        return EXIT_RUNTIME_FAILURE
    try:
        if options.out == "-":
            table.to_csv(sys.stdout, index=False)
        else:
            _write_complete(options.out, lambda file: table.to_csv(file, index=False))
    except OSError as error:
        print(f"{prog}: cannot write {options.out}: {error}", file=sys.stderr)
        return EXIT_OUTPUT_FAILURE
    failed = int(table["error"].notna().sum())
    where = "" if options.out == "-" else f" into {options.out}"
    print(f"{prog}: {len(table)} variants{where}, {failed} failed", file=sys.stderr)
    return 0


def _write_complete(path, write):
    """Writes through `write(file)` to a temporary file beside `path`, synced and renamed over
    it only when complete (as the C++ commands do): an interrupted run leaves the earlier file.
    A path that exists and is not a regular file (/dev/stdout) is written in place."""
    if os.path.exists(path) and not os.path.isfile(path) and not os.path.isdir(path):
        with open(path, "w", newline="") as file:
            write(file)
        return
    directory, name = os.path.split(os.path.abspath(path))
    descriptor, temporary = tempfile.mkstemp(prefix=f".{name}.", suffix=".partial.csv",
                                             dir=directory)
    try:
        with os.fdopen(descriptor, "w", newline="") as file:
            write(file)
            file.flush()
            os.fsync(file.fileno())
        os.replace(temporary, path)
    except BaseException:
        os.unlink(temporary)
        raise


def main(arguments=None, prog="python3 -m minkowski"):
    arguments = sys.argv[1:] if arguments is None else list(arguments)
    if not arguments or arguments[0] in ("-h", "--help"):
        print(f"usage: {prog} sweep SCENE --vary KEY=a:b:n ... [--workers N] "
              "(see: sweep --help)")
        return 0 if arguments else EXIT_BAD_INPUT
    command, rest = arguments[0], arguments[1:]
    if command != "sweep":
        print(f"{prog}: unknown command '{command}' (known: sweep)", file=sys.stderr)
        return EXIT_BAD_INPUT
    sweep_prog = prog if prog.endswith("sweep") else f"{prog} sweep"
    try:
        return sweep_command(rest, sweep_prog)
    except UsageError as error:
        print(f"{sweep_prog}: {error}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except SystemExit as exit:  # argparse: --help (0) or a usage error (2)
        return exit.code if isinstance(exit.code, int) else EXIT_BAD_INPUT
    except Exception as error:
        import minkowski
        if isinstance(error, minkowski.OutputError) or isinstance(error, minkowski.GlContextError):
            print(f"{sweep_prog}: {error}", file=sys.stderr)
            return EXIT_RUNTIME_FAILURE
        if isinstance(error, minkowski.Error):
            print(f"{sweep_prog}: {error}", file=sys.stderr)
            return EXIT_BAD_INPUT
        raise


if __name__ == "__main__":
    sys.exit(main())
