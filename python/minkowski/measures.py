"""Ready-made measures for sweeps (and anyone): whole-world figures from the batch arrays."""

import numpy

__all__ = ["kinetic_energy", "summary", "track", "combine"]


def kinetic_energy(world):
    """Translation of every centre of mass plus rotation about it, J (static and kinematic
    bodies have no mass and count nothing)."""
    masses = world.masses()
    speeds = world.linear_velocities()
    spins = world.angular_velocities()
    return float(0.5 * numpy.sum(masses * numpy.sum(speeds * speeds, axis=1))
                 + 0.5 * numpy.sum(world.rotational_inertias() * spins * spins))


def summary(world):
    """time, steps, bodies, kinetic_energy, and the last step's awake bodies and touching
    contacts."""
    counters = world.counters
    return {
        "time": world.time,
        "steps": world.step_count,
        "bodies": world.body_count,
        "kinetic_energy": kinetic_energy(world),
        "awake_bodies": counters["awake_bodies"],
        "touching_contacts": counters["touching_contacts"],
    }


def track(*indices):
    """A measure of the given bodies' states (by Body.index): body{i}_x, _y, _angle, _vx, _vy
    and _w for each (velocities of the centre of mass)."""
    selection = numpy.asarray(indices, dtype=numpy.int64)

    def measure(world):
        states = world.states(selection)
        out = {}
        for index, row in zip(indices, states):
            for name, value in zip(("x", "y", "angle", "vx", "vy", "w"), row):
                out[f"body{index}_{name}"] = float(value)
        return out

    return measure


def combine(*measures):
    """One measure whose columns are those of each measure in turn."""

    def measure(world):
        out = {}
        for each in measures:
            result = each(world)
            out.update(result if isinstance(result, dict) else {"value": result})
        return out

    return measure
