#!/usr/bin/env python3
"""Encounters, looked at pair by pair: steps a world's replicates on both engines through the
Python module and counts, from the positions after each step, the pairs of agents that come
within the detection radius s (torus distances). Of those entries it reports how many are
between two waiting agents and how many re-enter within QUICK_TU of the pair last leaving s:
members of packed aggregates jostling across s rather than agents meeting. On Box2D these
entries are the engine's own encounter count; the kinematic engine counts a few more, as it
also sees pairs that enter and leave s within one step.

    PYTHONPATH=build/python /usr/bin/python3 examples/encounter-entries.py \\
        worlds/examples/compact.yaml --set robots.count=200 --replicates 4

Needs numpy; about two minutes for that command.
"""
import argparse
import re

import numpy as np

import swarmagg as sa

QUICK_TU = 1.0
ENGINES = ("kinematic", "box2d")


def resolved_number(world, section, key):
    """A number of the resolved world's YAML (`section:` then `  key: value`), without a YAML
    library."""
    match = re.search(rf"^{section}:\n(?:  .*\n)*?  {key}: ([^\n]+)", world.to_yaml(), re.M)
    if not match:
        raise SystemExit(f"{world.source}: no {section}.{key} in the resolved world")
    return float(match.group(1))


def typed(value):
    """A --set value as the CLI reads it: a whole number, a number, a boolean or text."""
    for kind in (int, float):
        try:
            return kind(value)
        except ValueError:
            pass
    return {"true": True, "false": False}.get(value, value)


def count_entries(world, engine, replicate):
    sim = sa.Simulation(world, replicate=replicate, engine=engine)
    s = resolved_number(world, "robots", "detection_radius")
    size = np.array([resolved_number(world, "arena", "width"),
                     resolved_number(world, "arena", "height")])
    torus = re.search(r"^  topology: torus$", world.to_yaml(), re.M) is not None
    quick_steps = round(QUICK_TU / world.dt)
    i, j = np.triu_indices(world.agents, 1)
    inside = np.zeros(len(i), dtype=bool)
    left_at = np.full(len(i), -10**9)
    entries = waiting = quick = quick_waiting = 0
    for step in range(1, world.steps + 1):
        sim.step()
        d = np.abs(sim.positions[i] - sim.positions[j])
        if torus:
            d = np.minimum(d, size - d)
        now = (d * d).sum(axis=1) <= s * s
        entered = now & ~inside
        if step > 1:  # the first step's pairs were placed there, not met
            both_wait = (sim.states[i] == sa.State.WAIT) & (sim.states[j] == sa.State.WAIT)
            again = step - left_at <= quick_steps
            entries += int(entered.sum())
            waiting += int((entered & both_wait).sum())
            quick += int((entered & again).sum())
            quick_waiting += int((entered & both_wait & again).sum())
        left_at[inside & ~now] = step
        inside = now
    return np.array([entries, waiting, quick, quick_waiting])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("world")
    parser.add_argument("--set", action="append", default=[], metavar="KEY=VALUE")
    parser.add_argument("--replicates", type=int, default=None)
    args = parser.parse_args()
    values = dict(assignment.partition("=")[::2] for assignment in args.set)
    try:
        world = sa.load_world(args.world, set={key: typed(value) for key, value in values.items()})
    except (ValueError, TypeError, OSError) as error:  # WorldError is a ValueError
        parser.exit(2, f"encounter-entries.py: {error}\n")
    replicates = args.replicates or world.replicates
    print(f"{world.name}: {world.agents} agents, {world.steps * world.dt:g} tu, {replicates} "
          f"replicate{'s' if replicates != 1 else ''}; per replicate, entries of pairs into s counted after each step:")
    for engine in ENGINES:
        total = sum(count_entries(world, engine, r) for r in range(replicates)) / replicates
        entries, waiting, quick, quick_waiting = total
        print(f"  {engine}: {entries:.1f} entries, {waiting:.1f} between two waiting agents, "
              f"{quick:.1f} within {QUICK_TU:g} tu of leaving s ({quick_waiting:.1f} of them "
              f"between two waiting agents); without those: {entries - quick_waiting:.1f}")


if __name__ == "__main__":
    main()
