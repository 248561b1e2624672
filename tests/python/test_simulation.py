"""Simulation: zero-copy read-only views that follow the steps, on both engines."""

import subprocess
import sys
import textwrap

import numpy as np
import pytest

import swarmagg as sa

ENGINES = ["kinematic", "box2d"]


@pytest.fixture(scope="module")
def world(demo):
    return sa.load_world(str(demo), set={"robots.count": 40, "run.duration": 20})


@pytest.mark.parametrize("engine", ENGINES)
def test_views_have_the_documented_shape_dtype_and_are_read_only(world, engine):
    sim = sa.Simulation(world, seed=1, engine=engine)
    n = world.agents
    expected = {"positions": ((n, 2), np.float64), "headings": ((n, 2), np.float64),
                "states": ((n,), np.int8), "aggregates": ((n,), np.int32)}
    for name, (shape, dtype) in expected.items():
        view = getattr(sim, name)
        assert view.shape == shape, name
        assert view.dtype == dtype, name
        assert not view.flags.writeable, name
        with pytest.raises(ValueError):
            view[0] = 0


@pytest.mark.parametrize("engine", ENGINES)
def test_views_are_the_simulations_memory_and_change_after_step(world, engine):
    sim = sa.Simulation(world, seed=2, engine=engine)
    first, again = sim.positions, sim.positions
    assert np.shares_memory(first, again)
    before = sim.positions.copy()
    sim.step()
    assert sim.step_count == 1
    assert sim.time == pytest.approx(world.dt)
    moved = np.any(sim.positions != before, axis=1)
    assert moved.sum() > world.agents // 2
    # The view taken before the step shows the state after it: a view, not a copy.
    np.testing.assert_array_equal(first, sim.positions)


@pytest.mark.parametrize("engine", ENGINES)
def test_states_aggregates_and_noa_agree(world, engine):
    sim = sa.Simulation(world, seed=3, engine=engine)
    sim.step(150)
    states = sim.states
    assert set(np.unique(states)) <= {int(s) for s in sa.State}
    aggregated = sim.aggregates >= 0
    assert np.all(states[aggregated] == sa.State.WAIT)
    assert sim.noa == len(np.unique(sim.aggregates[aggregated]))
    assert sim.noa > 0
    np.testing.assert_allclose(np.hypot(*sim.headings.T), 1.0)
    assert np.all((sim.positions >= 0) & (sim.positions < 120))


def test_state_names_are_the_librarys():
    assert [s.name for s in sa.State] == ["GO", "WAIT", "LEAVE", "APPROACH"]
    assert sa.State(1) is sa.State.WAIT


def test_seed_and_replicate_choose_the_generator(world):
    def start(**kwargs):
        return sa.Simulation(world, **kwargs).positions.copy()

    np.testing.assert_array_equal(start(seed=5), start(seed=5))
    assert not np.array_equal(start(seed=5), start(seed=6))
    assert not np.array_equal(start(seed=5, replicate=0), start(seed=5, replicate=1))


def test_frame_is_an_rgba_copy(world):
    sim = sa.Simulation(world, seed=1)
    frame = sim.frame(size=(64, 48))
    assert frame.shape == (48, 64, 4) and frame.dtype == np.uint8
    assert frame.flags.writeable
    assert len(np.unique(frame.reshape(-1, 4), axis=0)) > 2


def test_a_step_that_failed_fails_again_and_the_state_stays_as_it_failed(demo):
    # A repulsion push faster than Box2D's substeps allow stops the run (the CLI exits 1).
    # The failed step left bodies moved but the step uncounted, and the next step from there
    # went through: stepping on reached states no run reaches. Every later step() now raises
    # the same error and changes nothing.
    world = sa.load_world(str(demo), set={
        "robots.count": 80, "arena.width": 40, "arena.height": 40, "engine.type": "box2d",
        "engine.box2d.repulsion_gain": 7000, "controller.p_leave": 0.01, "run.duration": 300})
    sim = sa.Simulation(world)
    with pytest.raises(RuntimeError, match=r"moving from step (\d+) to") as failed:
        sim.step(3000)
    stopped_at, state = sim.step_count, sim.state_hash()
    assert f"moving from step {stopped_at} to" in str(failed.value)
    for _ in range(2):
        with pytest.raises(RuntimeError) as again:
            sim.step(1)
        assert str(again.value) == str(failed.value)
    assert (sim.step_count, sim.state_hash()) == (stopped_at, state)


def test_a_worker_forked_after_a_frame_draws_frames_too(demo):
    # llvmpipe's drawing threads, started by the parent's first frame, are not in a forked
    # child: its first frame waited for them for ever (multiprocessing forks on Linux).
    script = f"""
        import multiprocessing as mp
        import numpy as np
        import swarmagg as sa
        world = sa.load_world({str(demo)!r}, set={{"robots.count": 10}})
        def frame(_):
            return sa.Simulation(world, seed=2).frame(size=(64, 64))
        if __name__ == "__main__":
            mine = frame(0)
            with mp.get_context("fork").Pool(1) as pool:
                theirs = pool.map_async(frame, [0]).get(timeout=60)[0]
            print("same" if np.array_equal(mine, theirs) else "differ")
    """
    done = subprocess.run([sys.executable, "-c", textwrap.dedent(script)], capture_output=True,
                          text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "same"
