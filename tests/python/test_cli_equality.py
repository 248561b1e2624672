"""The module's outputs equal the CLI's for the same world, seed and arguments."""

import json

import matplotlib.image
import numpy as np
import pandas as pd
import pytest

import swarmagg as sa

SMALL = {"robots.count": 30, "run.duration": 40, "controller.p_leave": 0.01}


def set_arguments(values):
    return [a for key, value in values.items() for a in ("--set", f"{key}={value}")]


# Wall times differ from run to run; everything else of summary.json must be equal, the
# overrides and the model errors included.
NOT_COMPARED = {"wall_seconds"}


def without_wall_times(value):
    if isinstance(value, dict):
        return {k: without_wall_times(v) for k, v in value.items() if k not in NOT_COMPARED}
    if isinstance(value, list):
        return [without_wall_times(v) for v in value]
    return value


@pytest.mark.parametrize("engine", ["kinematic", "box2d"])
def test_run_equals_the_cli_run(cli, demo, tmp_path, engine):
    cli("run", demo, *set_arguments(SMALL), "--engine", engine, "--replicates", 3, "--seed", 5,
        "--threads", 2, "--out", tmp_path, "--quiet", "--no-plots")
    r = sa.run(sa.load_world(str(demo), set=SMALL), replicates=3, seed=5, threads=2,
               engine=engine)

    pd.testing.assert_frame_equal(r.timeseries(), pd.read_csv(tmp_path / "timeseries.csv"))
    pd.testing.assert_frame_equal(r.model(), pd.read_csv(tmp_path / "model.csv"))
    summary = json.loads((tmp_path / "summary.json").read_text())
    assert without_wall_times(r.summary()) == without_wall_times(summary)
    assert len({rep["final_state_hash"] for rep in summary["replicates"]}) == 3


class CountingOutput:
    """A run's outputs that count the calls of each text."""

    def __init__(self, output):
        self._output = output
        self.calls = {}

    def __getattr__(self, name):
        attribute = getattr(self._output, name)
        if not callable(attribute):
            return attribute

        def counted(*args):
            self.calls[name] = self.calls.get(name, 0) + 1
            return attribute(*args)
        return counted


def test_summary_and_model_run_the_models_once(demo):
    r = sa.run(sa.load_world(str(demo), set=SMALL), replicates=2, seed=5)
    r._output = CountingOutput(r._output)
    first = r.summary()
    first["model_errors"] = "changed by the caller"
    second = r.summary()
    assert second["model_errors"] != "changed by the caller"
    pd.testing.assert_frame_equal(r.model(), r.model())
    assert r._output.calls == {"summary_json": 1, "model_csv": 1}


@pytest.mark.parametrize("engine", ["kinematic", "box2d"])
def test_a_simulation_stepped_by_hand_ends_in_the_runs_final_state(cli, demo, tmp_path, engine):
    world = sa.load_world(str(demo), set=SMALL)
    summary = sa.run(world, replicates=2, seed=9, engine=engine).summary()
    for replicate in range(2):
        sim = sa.Simulation(world, seed=9, replicate=replicate, engine=engine)
        sim.step(world.steps)
        assert sim.state_hash() == summary["replicates"][replicate]["final_state_hash"]


def test_model_with_measured_rates_is_the_cli_model_csv_byte_for_byte(cli, demo, tmp_path):
    # run --rates writes the measured variants (expected and stochastic) too.
    cli("run", demo, *set_arguments(SMALL), "--replicates", 2, "--seed", 3, "--rates",
        "--out", tmp_path, "--quiet", "--no-plots")
    r = sa.run(sa.load_world(str(demo), set=SMALL), replicates=2, seed=3, rates=True)
    text = r._output.model_csv()
    assert "measured-stochastic" in text
    assert text == (tmp_path / "model.csv").read_text()


def test_rates_table_equals_rates_csv(cli, demo, tmp_path):
    cli("rates", demo, *set_arguments(SMALL), "--replicates", 2, "--seed", 3, "--out", tmp_path,
        "--quiet")
    table = sa.rates(sa.load_world(str(demo), set=SMALL), replicates=2, seed=3).table()
    pd.testing.assert_frame_equal(table, pd.read_csv(tmp_path / "rates.csv"))
    summary = sa.run(sa.load_world(str(demo), set=SMALL), replicates=2, seed=3, rates=True)
    pd.testing.assert_frame_equal(summary.rates().table(), table)


def test_render_png_draws_the_pixels_of_the_run_frames(cli, demo, tmp_path):
    cli("run", demo, *set_arguments(SMALL), "--replicates", 1, "--seed", 4, "--out", tmp_path,
        "--render-every", 100, "--render-size", "96x80", "--quiet", "--no-plots", "--no-model")
    sim = sa.Simulation(sa.load_world(str(demo), set=SMALL), seed=4)
    sim.step(100)
    sim.render_png(tmp_path / "python.png", size=(96, 80))
    drawn = matplotlib.image.imread(tmp_path / "python.png")
    recorded = matplotlib.image.imread(tmp_path / "frames" / "frame_000001.png")
    assert drawn.shape[:2] == (80, 96)
    np.testing.assert_array_equal(drawn, recorded)
    recorded_bytes = np.round(recorded[:, :, :3] * 255).astype(np.uint8)
    np.testing.assert_array_equal(sim.frame(size=(96, 80))[:, :, :3], recorded_bytes)
