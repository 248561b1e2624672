"""Objects made without __init__, copies and pickles: a clear exception or a working copy,
never a crash (docs/python.md, "Copies and pickles"). What could crash runs in a new
interpreter, so that a crash fails its test and not the test run."""

import copy
import os
import pickle
import shutil
import subprocess
import sys
import textwrap

import pytest

import swarmagg as sa
from swarmagg import _core
from conftest import DEMO, ROOT

BOUND_CLASSES = ["RunOutput", "Simulation", "World"]
PROTOCOLS = range(pickle.HIGHEST_PROTOCOL + 1)
PRELUDE = f"""
import copy, pickle
import swarmagg as sa
from swarmagg import _core
world = sa.load_world({str(DEMO)!r}, set={{"run.duration": 1, "robots.count": 12}})
"""


def python(code: str) -> subprocess.CompletedProcess:
    """Runs PRELUDE then `code` in a new interpreter; fails the test when it crashed."""
    ran = subprocess.run([sys.executable, "-c", PRELUDE + textwrap.dedent(code)], cwd=ROOT,
                         capture_output=True, text=True, timeout=120)
    assert ran.returncode == 0, f"exit {ran.returncode}\n{ran.stdout}\n{ran.stderr}"
    return ran


def refusals(code: str) -> list[str]:
    """The message of the TypeError each statement (a line) of `code` raises, or 'no error'."""
    statements = [line.strip() for line in code.splitlines() if line.strip()]
    return python("\n".join(f"""
try:
    {statement}
    print("no error")
except TypeError as error:
    print(str(error).replace("\\n", " "))""" for statement in statements)).stdout.splitlines()


@pytest.fixture(scope="module")
def world():
    return sa.load_world(str(DEMO), set={"run.duration": 1, "robots.count": 12})


def test_the_bound_classes_are_those_tested():
    bound = sorted(name for name, value in vars(_core).items()
                   if isinstance(value, type) and type(value).__name__ == "pybind11_type")
    assert bound == BOUND_CLASSES


@pytest.mark.parametrize("name", BOUND_CLASSES)
def test_every_member_of_an_object_made_without_init_is_a_type_error(name):
    cls = getattr(_core, name)
    members = sorted(n for n in dir(cls) if not n.startswith("_"))
    arguments = {"render_png": "'never.png'"}

    def use(member: str) -> str:  # a property is read, a method called
        if not callable(getattr(cls, member)):
            return f"obj.{member}"
        return f"obj.{member}({arguments.get(member, '')})"

    made = f"obj = _core.{name}.__new__(_core.{name})"
    messages = refusals("\n".join([made, *map(use, members)]))
    assert len(messages) == len(members) + 1 and messages[0] == "no error"  # __new__ itself
    for member, message in zip(members, messages[1:]):
        assert f"swarmagg._core.{name} object is not initialised" in message, member
        assert "__new__() without __init__()" in message, member
    representation = refusals(f"repr(_core.{name}.__new__(_core.{name}))")  # a text or refused
    assert representation in (["no error"], [messages[1]])


def test_a_world_made_without_init_is_refused_as_an_argument_too():
    messages = refusals("""
        sa.run(sa.World.__new__(sa.World), replicates=1)
        sa.rates(sa.World.__new__(sa.World), replicates=1)
        sa.Simulation(sa.World.__new__(sa.World))
        pickle.dumps(sa.World.__new__(sa.World))
        sa.Run(_core.RunOutput.__new__(_core.RunOutput)).timeseries()
        """)
    assert all("object is not initialised" in m for m in messages), messages


def test_a_subclass_made_without_init_is_refused():
    messages = refusals("""
        class Mine(sa.Simulation): pass
        Mine.__new__(Mine).step()
        """)
    assert messages[-1].startswith("swarmagg._core.Simulation object is not initialised")


@pytest.mark.parametrize("cls", [sa.Run, sa.Rates, sa.Sweep])
def test_the_python_classes_made_without_init_raise(cls):
    obj = cls.__new__(cls)
    with pytest.raises(AttributeError):
        getattr(obj, {sa.Sweep: "results"}.get(cls, "summary"))()


def test_a_world_is_immutable_so_its_copies_are_itself(world):
    assert copy.copy(world) is world
    assert copy.deepcopy(world) is world
    held = copy.deepcopy({"worlds": [world]})
    assert held["worlds"][0] is world


def test_a_world_pickles_at_every_protocol_as_the_same_world(world):
    for protocol in PROTOCOLS[2:]:
        back = pickle.loads(pickle.dumps(world, protocol))
        assert back is not world
        assert (back.to_yaml(), back.source, back.name) == (world.to_yaml(), world.source,
                                                            world.name)
    simulations = [sa.Simulation(w, seed=5) for w in (world, back)]
    for simulation in simulations:
        simulation.step(20)
    assert simulations[0].state_hash() == simulations[1].state_hash()
    # What `set` changed is kept: a run names it as summary.json's overrides.
    overrides = [sa.run(w, replicates=1).summary()["overrides"] for w in (world, back)]
    assert overrides[0] == overrides[1]
    assert overrides[0][:2] == ["run.duration=1", "robots.count=12"]
    # By default, protocols 0 and 1 call pybind11_object(world), which aborts.
    python(f"""
        for protocol in {list(PROTOCOLS)}:
            assert pickle.loads(pickle.dumps(world, protocol)).to_yaml() == world.to_yaml()
            assert world.__reduce__()[0] is world.__reduce_ex__(protocol)[0]
        """)


def test_a_simulation_is_neither_copied_nor_pickled():
    messages = refusals("""
        copy.copy(sa.Simulation(world))
        copy.deepcopy(sa.Simulation(world))
        sa.Simulation(world).__reduce__()
        """ + "".join(f"pickle.dumps(sa.Simulation(world), {p})\n" for p in PROTOCOLS))
    assert len(messages) == 3 + len(PROTOCOLS)
    assert all(m.startswith("swarmagg.Simulation cannot be copied or pickled") for m in messages)


def test_what_the_simulation_refusal_offers_instead_is_the_same_state(world):
    simulation = sa.Simulation(world, seed=7, replicate=2, engine="box2d")
    simulation.step(30)
    again = sa.Simulation(simulation.world, replicate=2)
    again.step(simulation.step_count)
    assert again.state_hash() == simulation.state_hash()


def test_a_run_is_copied_as_its_outputs_and_not_pickled(world):
    run = sa.run(world, replicates=1, rates=True)
    for copied in (copy.copy(run), copy.deepcopy(run)):
        assert copied.timeseries().equals(run.timeseries())
        assert copied.summary() == run.summary()
        assert copied.rates().table().equals(run.rates().table())
    rates = copy.deepcopy(run.rates())
    assert rates.summary() == run.rates().summary()
    messages = refusals("""
        run = sa.run(world, replicates=1, rates=True)
        """ + "".join(f"pickle.dumps(run, {p})\npickle.dumps(run.rates(), {p})\n"
                      for p in PROTOCOLS))
    assert messages[0] == "no error"
    assert all(m.startswith("swarmagg.Run and swarmagg.Rates cannot be pickled")
               for m in messages[1:])


def test_the_python_only_values_copy_and_pickle(tmp_path):
    sweep = sa.Sweep({"name": "s", "out": str(tmp_path), "runs": 1, "already_complete": 0,
                      "ran": 1, "threads": 1, "wall_seconds": 0.5})
    for back in (pickle.loads(pickle.dumps(sweep)), copy.deepcopy(sweep)):
        assert (back.out, back.report) == (sweep.out, sweep.report)
    assert pickle.loads(pickle.dumps(sa.State.WAIT)) is sa.State.WAIT
    error = pickle.loads(pickle.dumps(sa.WorldError("w.yaml:3: robots.count")))
    assert isinstance(error, sa.WorldError) and str(error) == "w.yaml:3: robots.count"


def test_a_world_run_again_names_every_change_once_with_the_value_used(world):
    """A run's or a simulation's world run again is the world file with every change so far,
    a key changed twice naming its last value, as summary.json names the CLI's --set,
    --engine, --seed and --replicates."""
    first = sa.run(world, replicates=2, seed=5, engine="box2d", threads=1)
    assert first.summary()["overrides"] == ["run.duration=1", "robots.count=12",
                                            "engine.type=box2d", "run.replicates=2", "run.seed=5"]
    again = sa.run(first.world, replicates=3, threads=1).summary()["overrides"]
    assert again == ["run.duration=1", "robots.count=12", "engine.type=box2d",
                     "run.replicates=3", "run.seed=5"]
    simulated = sa.Simulation(world, seed=9, engine="box2d").world
    assert sa.run(simulated, replicates=1).summary()["overrides"] == [
        "run.duration=1", "robots.count=12", "engine.type=box2d", "run.seed=9",
        "run.replicates=1"]
    # And the summary is the one of the run it names: the same command line's.
    assert sa.run(simulated, replicates=1).summary()["seed"] == 9


def test_a_world_from_a_path_that_is_not_utf8_names_it_and_pickles(tmp_path):
    folder = os.fsencode(tmp_path) + b"/d\xff"
    os.makedirs(folder)
    path = folder + b"/w.yaml"
    shutil.copy(DEMO, path)
    world = sa.load_world(path, set={"run.duration": 1})
    assert world.source == os.fsdecode(path)
    back = pickle.loads(pickle.dumps(world))
    assert (back.source, back.to_yaml()) == (world.source, world.to_yaml())
