"""swarmagg.sweep(): a sweep file run and merged as `swarmagg sweep` does."""

import json
import os
from pathlib import Path

import pandas as pd

from . import _core


class Sweep:
    """A finished sweep's folder and its merged, tidy files."""

    def __init__(self, report: dict):
        self._report = report
        # Absolute, so that the frames still load after the caller changes folder.
        self.out = Path(report["out"]).absolute()

    @property
    def report(self) -> dict:
        """name, out, runs, already_complete, ran, threads, wall_seconds, removed (the earlier
        merge's plots and tables in `out` that this merge outdated and removed, as paths)."""
        return dict(self._report)

    def results(self) -> pd.DataFrame:
        """sweep_timeseries.csv: the swept parameters' columns, then timeseries.csv's, one row
        per run and recorded step (`replicate` is the sweep's replicate index)."""
        return pd.read_csv(self.out / "sweep_timeseries.csv")

    def summary(self) -> pd.DataFrame:
        """sweep_summary.csv: per point and observable, statistics of the final values."""
        return pd.read_csv(self.out / "sweep_summary.csv")

    def partitions(self) -> pd.DataFrame:
        """sweep_partitions.csv (Soysal worlds); ValueError when the sweep's worlds record no
        partitions."""
        path = self.out / "sweep_partitions.csv"
        if not path.exists():
            raise ValueError(
                f"partitions: {path} does not exist; the sweep's controller records no "
                "partitions (Soysal worlds do)"
            )
        return pd.read_csv(path)

    def manifest(self) -> dict:
        """sweep.json: the sweep as run (base world, parameters, replicates, seed)."""
        return json.loads((self.out / "sweep.json").read_text())


def sweep(
    path: str | os.PathLike,
    out: str | os.PathLike | None = None,
    threads: int = 0,
    force: bool = False,
) -> Sweep:
    """Runs the sweep file's runs that are not complete yet into `out` (default
    runs/<sweep name>, as the CLI), then merges them, as `swarmagg sweep SWEEP --out OUT
    --threads T --no-plots`. Resumable: complete runs are kept. threads=0 uses every core.
    Runs whose folders hold results of another world (the sweep's base world, seed or values
    changed since) raise ValueError unless force=True replaces them (--force); so does an
    `out` that holds files but is not a sweep's folder.
    Runs without the GIL; Ctrl-C raises KeyboardInterrupt, and runs in progress leave
    nothing behind. A bad sweep file raises WorldError.
    """
    return Sweep(
        _core.sweep(os.fspath(path), None if out is None else os.fspath(out), threads, force)
    )
