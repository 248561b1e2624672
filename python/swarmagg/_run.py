"""swarmagg.run() and swarmagg.rates(): a world's replicates, outputs as frames."""

import pandas as pd

from . import _core
from ._core import World
from ._tables import document, frame


class Rates:
    """Measured model terms of a run: each term as events over exposure, and what each model
    variant says it is."""

    def __init__(self, output: _core.RunOutput):
        self._output = output

    def table(self) -> pd.DataFrame:
        """The rows of rates.csv: term, size, events, exposure, rate, ci_low, ci_high, model,
        variant, model_rate (rates per tu)."""
        return frame(self._output.rates_csv())

    def summary(self) -> dict:
        """rates.json: every term with its interval and the ratio to each model variant."""
        return document(self._output.rates_json())


class Run:
    """The outputs of run(): what `swarmagg run` writes, as frames and dicts."""

    def __init__(self, output: _core.RunOutput):
        self._output = output
        # summary.json's model errors and model.csv run the models: each text is made once.
        self._texts: dict[str, str] = {}

    def _text(self, name: str) -> str:
        if name not in self._texts:
            self._texts[name] = getattr(self._output, name)()
        return self._texts[name]

    @property
    def world(self) -> World:
        """The world as run, with the call's replicates, seed, threads and engine applied."""
        return self._output.world

    def timeseries(self) -> pd.DataFrame:
        """timeseries.csv: replicate, step, time, noa, searching, waiting, leaving,
        approaching, largest, then cumulative creations, growths, dissipations, shrinks,
        encounters; one row per replicate and recorded step."""
        return frame(self._output.timeseries_csv())

    def summary(self) -> dict:
        """summary.json: final values over replicates, per replicate finals, events and
        final_state_hash."""
        return document(self._text("summary_json"))

    def model(self) -> pd.DataFrame:
        """model.csv: every model variant's predictions, tidy (model, variant, step, time,
        quantity, value); the `measured` variants too when run with rates=True. No rows (the
        header only, as the CLI's model.csv) when no model describes the world; ValueError
        when the world's model cannot be computed (a partition model of more than 30
        agents)."""
        return frame(self._text("model_csv"))

    def partitions(self) -> pd.DataFrame:
        """partitions.csv (Soysal worlds): replicate, partition, time_fraction."""
        return frame(self._output.partitions_csv())

    def rates(self) -> Rates:
        """The measured terms; the run must have been made with rates=True."""
        if not self._output.measured:
            raise ValueError("rates: this run measured no rates; run it with rates=True")
        return Rates(self._output)


def run(
    world: World,
    replicates: int | None = None,
    seed: int | None = None,
    threads: int | None = None,
    engine: str | None = None,
    rates: bool = False,
) -> Run:
    """Runs the world's replicates, as `swarmagg run WORLD --replicates .. --seed .. --threads
    .. --engine ..` does, and returns the outputs in memory.

    Arguments left None keep the world's run.replicates, run.seed, run.threads (0: all
    cores) and engine.type ('kinematic' or 'box2d'). rates=True also measures every model
    term, as --rates. Runs without the GIL; Ctrl-C raises KeyboardInterrupt soon after. A
    bad value raises ValueError.
    """
    return Run(_core.run(world, replicates, seed, threads, engine, rates))


def rates(
    world: World,
    replicates: int | None = None,
    seed: int | None = None,
    threads: int | None = None,
    engine: str | None = None,
) -> Rates:
    """Measures every model term of the world by simulation, as `swarmagg rates` does.
    Arguments as for run()."""
    return Rates(_core.run(world, replicates, seed, threads, engine, True))
