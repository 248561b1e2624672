"""The return fraction of `rates` against an independent estimate from trajectories.h5.

A Soysal world whose agents leave often runs with every step stored. From the stored states
and aggregate ids alone, this test follows every LEAVE attempt (a WAIT agent of an aggregate
that goes LEAVE) to the agent's next step in an aggregate, and counts a return when that
aggregate holds a member of the one it left that kept waiting all the while (one that searched
again in between is in a new aggregate), within the return window. Attempts whose window had
not closed when the run ended are left out (they could yet return). The attempts and the
returns must match rates.csv's `return` rows exactly.
"""
import csv
import os
import re
import subprocess

import pytest

h5py = pytest.importorskip("h5py")
np = pytest.importorskip("numpy")

WAIT, LEAVE = 1, 2
WORLD = """name: returns-check
arena: {width: 120, height: 120, topology: torus}
robots: {count: 10}
controller: {type: soysal, approach_radius: 12.0, p0: 0.0005, leave_timeout: 10}
run: {duration: 3000, replicates: 2, seed: 5, record_every: 100}
"""


def returns_from_trajectories(path):
    """(returns, attempts) over every replicate, from the stored states and aggregates."""
    returns = attempts = 0
    with h5py.File(path, "r") as f:
        every = int(f.attrs["every"])
        assert every == 1, "the estimate needs every step"
        world = f.attrs["world"]
        world = world.decode() if isinstance(world, bytes) else world
        window_tu = float(re.search(r"return_window:\s*([0-9.eE+-]+)", world).group(1))
        for name in f:
            group = f[name]
            dt = float(group["time"][1] - group["time"][0])
            window = round(window_tu / dt)
            state = group["state"][()]
            aggregate = group["aggregate"][()]
            rows, agents = state.shape
            for agent in range(agents):
                starts = np.nonzero((state[:-1, agent] == WAIT) & (state[1:, agent] == LEAVE)
                                    & (aggregate[:-1, agent] >= 0))[0] + 1
                for t in starts:
                    # The decision of step t started the attempt; its window closes by the
                    # run's last decision (rows - 1) when t + window + 2 < rows.
                    if t + window + 2 >= rows:
                        continue
                    left = aggregate[t - 1, agent]
                    former = [j for j in range(agents) if j != agent and aggregate[t - 1, j] == left]
                    attempts += 1
                    later = np.nonzero(aggregate[t + 1:, agent] >= 0)[0]
                    if later.size == 0:
                        continue
                    back = t + 1 + later[0]
                    joined = aggregate[back, agent]
                    if back - t <= window and any(aggregate[back, j] == joined
                                                  and np.all(state[t:back, j] == WAIT)
                                                  for j in former):
                        returns += 1
    return returns, attempts


def returns_from_rates(path):
    returns = attempts = 0
    seen = set()
    with open(path) as f:
        for row in csv.DictReader(f):
            if row["term"] != "return" or row["size"] in seen:
                continue
            seen.add(row["size"])
            returns += int(row["events"])
            attempts += int(float(row["exposure"]))
    return returns, attempts


def test_rates_return_fraction_matches_trajectories(tmp_path):
    binary = os.environ["SWARMAGG_BINARY"]
    world = tmp_path / "world.yaml"
    world.write_text(WORLD)
    out = tmp_path / "run"
    subprocess.run([binary, "run", str(world), "--trajectories", "1", "--rates", "--no-model",
                    "--no-plots", "--quiet", "--threads", "1", "--out", str(out)], check=True)
    h5_returns, h5_attempts = returns_from_trajectories(out / "trajectories.h5")
    rate_returns, rate_attempts = returns_from_rates(out / "rates.csv")
    assert h5_attempts >= 100, "too few attempts for the comparison to mean anything"
    assert rate_attempts == h5_attempts
    assert rate_returns == h5_returns
