"""Errors arrive as exceptions: WorldError with the CLI's message, ValueError for arguments."""

import pytest

import swarmagg as sa


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
