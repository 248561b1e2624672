"""Errors arrive as exceptions: WorldError with the CLI's message, ValueError for arguments."""

import os
import stat

import numpy as np
import pytest

import swarmagg as sa
from conftest import ROOT


def test_a_bad_world_raises_world_error_naming_file_line_and_key(tmp_path):
    path = tmp_path / "bad.yaml"
    path.write_text("name: bad\nrobots:\n  count: many\n")
    with pytest.raises(sa.WorldError) as error:
        sa.load_world(path)  # a str or any os.PathLike
    message = str(error.value)
    assert str(path) in message
    assert "robots.count" in message
    assert ":3" in message  # the line of the bad value
    assert isinstance(error.value, ValueError)


def test_a_missing_world_file_raises_world_error(tmp_path):
    with pytest.raises(sa.WorldError, match="nowhere.yaml"):
        sa.load_world(str(tmp_path / "nowhere.yaml"))


def test_a_misspelt_set_key_suggests_the_key(demo):
    with pytest.raises(sa.WorldError, match=r"did you mean 'robots\.count'"):
        sa.load_world(str(demo), set={"robots.cont": 10})


def test_a_set_value_of_the_wrong_kind_names_the_key(demo):
    with pytest.raises(sa.WorldError, match="robots.count"):
        sa.load_world(str(demo), set={"robots.count": "lots"})
    with pytest.raises(TypeError, match="robots.count"):
        sa.load_world(str(demo), set={"robots.count": object()})


def test_a_set_key_the_controller_does_not_read_is_refused(demo):
    # The run would ignore it, while the world's changes list it.
    with pytest.raises(sa.WorldError, match=r"controller\.approach_radius: the world's "
                                            r"controller type 'bayindir' \(.*\) does not read"):
        sa.load_world(str(demo), set={"controller.approach_radius": 12})


def test_set_takes_numpy_arrays_as_lists(tmp_path):
    path = tmp_path / "cockroach.yaml"
    path.write_text("name: c\nrobots: {count: 5}\ncontroller: {type: cockroach}\n"
                    "run: {duration: 1, replicates: 1}\n")
    world = sa.load_world(path, set={"controller.stop_probability": np.array([0.1, 0.4])})
    assert "stop_probability: [0.1, 0.4]" in world.to_yaml()
    overrides = sa.run(world, threads=1).summary()["overrides"]
    assert overrides == ["controller.stop_probability=[0.1, 0.4]"]


def test_set_takes_python_values(demo):
    world = sa.load_world(str(demo), set={"robots.count": 12, "controller.join": False,
                                          "engine.type": "box2d", "run.duration": 2.5})
    assert (world.agents, world.engine, world.steps) == (12, "box2d", 25)
    assert "join: false" in world.to_yaml()


@pytest.mark.parametrize("arguments", [{"replicates": 0}, {"seed": -1}, {"engine": "warp"},
                                       {"threads": -2}])
def test_a_bad_argument_raises_value_error(demo, arguments):
    world = sa.load_world(str(demo), set={"run.duration": 1})
    with pytest.raises(ValueError) as error:
        sa.run(world, **arguments)
    assert not isinstance(error.value, sa.WorldError)
    assert next(iter(arguments)) in str(error.value)


@pytest.mark.parametrize("arguments", [{"replicates": True}, {"threads": False},
                                       {"replicates": 2.0}])
def test_a_bool_or_float_for_a_whole_number_is_a_type_error(demo, arguments):
    world = sa.load_world(str(demo), set={"run.duration": 1})
    with pytest.raises(TypeError):
        sa.run(world, **arguments)


def test_a_simulations_replicate_and_steps_are_whole_numbers(demo):
    world = sa.load_world(str(demo))
    for bad in (True, 1.0):  # True ran replicate 1, step(True) one step
        with pytest.raises(TypeError):
            sa.Simulation(world, replicate=bad)
        with pytest.raises(TypeError):
            sa.Simulation(world).step(bad)
    for out_of_range in (-1, 2**31, 2**70):
        with pytest.raises(ValueError, match="replicate: "):
            sa.Simulation(world, replicate=out_of_range)
    with pytest.raises(ValueError, match="steps: expected a whole number from 0"):
        sa.Simulation(world).step(-1)
    simulation = sa.Simulation(world, replicate=np.int64(2))
    simulation.step(np.int32(3))
    assert simulation.step_count == 3


def test_a_number_beyond_64_bits_is_a_value_error_naming_the_argument(demo):
    world = sa.load_world(str(demo), set={"run.duration": 1})
    with pytest.raises(ValueError, match="replicates"):
        sa.run(world, replicates=2**70)


def test_a_run_of_a_world_asking_for_frames_or_trajectories_warns(demo):
    """At the caller's line, so that each call site warns once under Python's filters."""
    world = sa.load_world(str(demo), set={"run.duration": 1, "run.trajectories": 5})
    for call in (sa.run, sa.rates):
        with pytest.warns(UserWarning, match="store no trajectories and draw no frames") as w:
            call(world, replicates=1)
        assert w[0].filename == __file__, w[0].filename


def test_an_empty_set_key_suggests_nothing(demo):
    with pytest.raises(sa.WorldError, match="an empty key") as error:
        sa.load_world(str(demo), set={"": 5})
    assert "did you mean" not in str(error.value)


def test_simulation_arguments_are_checked(demo):
    world = sa.load_world(str(demo))
    with pytest.raises(ValueError, match="replicate"):
        sa.Simulation(world, replicate=-1)
    with pytest.raises(ValueError, match="engine"):
        sa.Simulation(world, engine="warp")
    with pytest.raises(ValueError, match="size|render|width"):
        sa.Simulation(world).frame(size=(4, 4))


def test_rates_of_a_run_without_them_is_a_value_error(demo):
    run = sa.run(sa.load_world(str(demo), set={"run.duration": 1}), replicates=1)
    with pytest.raises(ValueError, match="rates=True"):
        run.rates()
    with pytest.raises(ValueError, match="partitions"):
        run.partitions()


def test_set_values_nested_too_deep_or_holding_themselves_are_world_errors(demo):
    deep = []
    inner = deep
    for _ in range(20000):
        inner.append([])
        inner = inner[0]
    with pytest.raises(sa.WorldError, match=r"robots\.placement.*nested more than 499"):
        sa.load_world(str(demo), set={"robots.placement": deep})
    itself = []
    itself.append(itself)
    with pytest.raises(sa.WorldError, match="nested more than"):
        sa.load_world(str(demo), set={"robots.placement": itself})
    array_holding_itself = np.empty((), object)
    array_holding_itself[()] = array_holding_itself
    with pytest.raises(sa.WorldError, match="nested more than"):
        sa.load_world(str(demo), set={"arena.width": array_holding_itself})


def test_set_values_are_read_as_a_world_file_writes_them(demo):
    # A float is never a whole number, as 80.0 in a file is not; a str is a quoted scalar.
    with pytest.raises(sa.WorldError, match=r"robots\.count.*80\.0"):
        sa.load_world(str(demo), set={"robots.count": 80.0})
    assert sa.load_world(str(demo), set={"robots.count": "80"}).agents == 80
    assert sa.load_world(str(demo), set={"run.duration": 2.0}).steps == 20
    with pytest.raises(sa.WorldError, match=r"robots\.count.*does not fit in 64 bits"):
        sa.load_world(str(demo), set={"robots.count": 2**70})


def test_seeds_take_all_64_bits(demo, cli, tmp_path):
    largest = 2**64 - 1
    world = sa.load_world(str(demo), set={"run.duration": 1, "run.seed": largest})
    assert world.seed == largest
    run = sa.run(world, replicates=1, seed=largest)
    assert "run.seed=18446744073709551615" in run.summary()["overrides"]
    cli("run", demo, "--set", "run.duration=1", "--replicates", "1", "--seed", str(largest),
        "--out", tmp_path / "cli", "--no-plots", "--no-model", "--quiet")
    hashes = (tmp_path / "cli" / "summary.json").read_text()
    assert run.summary()["replicates"][0]["final_state_hash"] in hashes
    assert sa.Simulation(world, seed=largest).state_hash()
    # Any integer with __index__ (numpy's) is a seed; a bool or a float is not.
    assert "run.seed=3" in sa.run(world, replicates=1, seed=np.int64(3)).summary()["overrides"]
    for not_a_seed in (True, 1.5):
        with pytest.raises(TypeError):
            sa.run(world, seed=not_a_seed)
    for too_large in (sa.run, sa.Simulation):
        with pytest.raises(ValueError, match="seed.*does not fit in 64 bits"):
            too_large(world, seed=2**64)


def test_a_file_the_system_refuses_is_an_os_error_and_leaves_nothing(demo, tmp_path):
    folder = tmp_path / "frame.png"
    folder.mkdir()
    with pytest.raises(IsADirectoryError, match="frame.png"):
        sa.Simulation(sa.load_world(str(demo))).render_png(folder)
    assert [p.name for p in tmp_path.iterdir()] == ["frame.png"]  # no temporary left


def test_a_pipe_or_device_is_never_replaced_by_an_output(demo, tmp_path):
    # Outputs are renamed into place: over a pipe, or /dev/null as root, that made the node a
    # regular file.
    pipe = tmp_path / "frame.png"
    os.mkfifo(pipe)
    with pytest.raises(OSError, match="device, pipe or socket"):
        sa.Simulation(sa.load_world(str(demo))).render_png(pipe, size=(32, 32))
    assert stat.S_ISFIFO(os.stat(pipe).st_mode)
    assert [p.name for p in tmp_path.iterdir()] == ["frame.png"]  # no temporary left


def test_bytes_that_are_not_utf8_in_a_message_are_shown_escaped(tmp_path):
    path = tmp_path / "latin1.yaml"
    path.write_bytes(b"name: caf\xe9\n")
    with pytest.raises(sa.WorldError, match=r"latin1\.yaml:1:7: name: .*caf\\xe9"):
        sa.load_world(path)


def test_texts_that_utf8_cannot_hold_are_value_errors_naming_the_key(demo):
    """os.fsdecode gives surrogates for bytes that are not UTF-8; no world key can hold them."""
    undecodable = os.fsdecode(b"frames\xff")
    with pytest.raises(sa.WorldError, match=r"set\['render.dir'\]: expected text that UTF-8"):
        sa.load_world(str(demo), set={"render.dir": undecodable})
    with pytest.raises(sa.WorldError, match="set: a key: expected text that UTF-8"):
        sa.load_world(str(demo), set={"robots.c\udcffount": 5})


def test_numpy_long_doubles_are_read_as_floats_and_complex_ones_refused(demo):
    world = sa.load_world(str(demo), set={"controller.p_leave": np.longdouble(0.5)})
    assert "p_leave: 0.5" in world.to_yaml()
    with pytest.raises(TypeError, match="numpy complex"):
        sa.load_world(str(demo), set={"controller.p_leave": np.clongdouble(0.5)})


def test_sweep_threads_are_checked_as_run_threads_are(tmp_path):
    with pytest.raises(TypeError, match="threads: expected an integer, got a bool"):
        sa.sweep(ROOT / "examples" / "sweeps" / "p-leave-vs-count.yaml", tmp_path / "s",
                 threads=True)
    with pytest.raises(ValueError, match="threads: expected 0 .all cores. to 1024, got 1099511627776"):
        sa.sweep(ROOT / "examples" / "sweeps" / "p-leave-vs-count.yaml", tmp_path / "s",
                 threads=2**40)


def test_a_frame_size_beyond_an_int_is_a_value_error_naming_it(demo):
    sim = sa.Simulation(sa.load_world(str(demo), set={"run.duration": 1}))
    with pytest.raises(ValueError, match="size: expected a whole number"):
        sim.frame((2**31, 64))
    with pytest.raises(ValueError, match="each side must be between"):
        sim.frame((100000, 64))
    with pytest.raises(TypeError, match="size: expected an integer, got a bool"):
        sim.frame((True, 64))
