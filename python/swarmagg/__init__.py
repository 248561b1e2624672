"""swarmagg from Python: the simulator, models and sweeps of the `swarmagg` CLI.

The same library as the CLI, bound with pybind11: the same world and seed give exactly the
CLI's outputs. Long calls (run, rates, sweep) run without the GIL in the CLI's thread pool
and stop soon after Ctrl-C with KeyboardInterrupt. The reference is docs/python.md.

    import swarmagg as sa
    w = sa.load_world("worlds/examples/demo.yaml", set={"robots.count": 80})
    r = sa.run(w, replicates=4, seed=1, threads=2)
    r.timeseries()          # pandas DataFrame, the rows of timeseries.csv
"""

import os

# llvmpipe (Mesa) draws a frame on threads it starts at a process's first frame, which a forked
# process (multiprocessing's fork) does not have: a worker forked after its parent drew a frame
# waited for them for ever. Single-threaded it draws the same pixels. Set before the first
# frame, in os.environ so that Python and the processes it starts see what Mesa sees; a number
# the user chose (LP_NUM_THREADS) stays.
os.environ.setdefault("LP_NUM_THREADS", "0")

from ._core import World, WorldError, Simulation, load_world, __version__  # noqa: E402
from ._run import Rates, Run, rates, run
from ._state import State
from ._sweep import Sweep, sweep

__all__ = [
    "World",
    "WorldError",
    "Simulation",
    "State",
    "Run",
    "Rates",
    "Sweep",
    "load_world",
    "run",
    "rates",
    "sweep",
    "__version__",
]
