"""sweep(): the CLI's sweep, merged, as tidy frames."""

import os

import pandas as pd
import pytest

import swarmagg as sa


def write_sweep(folder, demo):
    path = folder / "small.yaml"
    path.write_text(f"name: small\nbase: {demo}\nparameters:\n"
                    "  controller.p_leave: [0.001, 0.01]\n  run.duration: [15]\n"
                    "replicates: 2\nseed: 11\n")
    return path


def test_sweep_results_equal_the_cli_sweep(cli, demo, tmp_path):
    path = write_sweep(tmp_path, demo)
    cli("sweep", path, "--out", tmp_path / "cli", "--quiet", "--no-plots", "--threads", 2)
    done = sa.sweep(path, out=tmp_path / "python", threads=2)
    assert done.report["runs"] == 4 and done.report["ran"] == 4
    results = done.results()
    pd.testing.assert_frame_equal(results, pd.read_csv(tmp_path / "cli" / "sweep_timeseries.csv"))
    pd.testing.assert_frame_equal(done.summary(),
                                  pd.read_csv(tmp_path / "cli" / "sweep_summary.csv"))
    assert list(results.columns[:2]) == ["controller.p_leave", "run.duration"]
    assert set(results["controller.p_leave"]) == {0.001, 0.01}
    assert done.manifest()["name"] == "small"


def test_a_sweep_run_again_keeps_its_complete_runs(demo, tmp_path):
    path = write_sweep(tmp_path, demo)
    first = sa.sweep(path, out=tmp_path / "out")
    assert first.report["removed"] == []
    # The demo's controller records no partitions: a sweep_partitions.csv is an earlier
    # merge's, outdated, and the report names it as `swarmagg merge` does.
    (tmp_path / "out" / "sweep_partitions.csv").write_text("earlier\n")
    again = sa.sweep(path, out=tmp_path / "out")
    assert (again.report["already_complete"], again.report["ran"]) == (4, 0)
    assert again.report["removed"] == [str(tmp_path / "out" / "sweep_partitions.csv")]
    pd.testing.assert_frame_equal(first.results(), again.results())


def test_a_changed_sweep_replaces_earlier_runs_only_with_force(demo, tmp_path):
    path = write_sweep(tmp_path, demo)
    sa.sweep(path, out=tmp_path / "out")
    path.write_text(path.read_text().replace("seed: 11", "seed: 12"))
    try:
        sa.sweep(path, out=tmp_path / "out")
        raise AssertionError("replaced the earlier runs without force")
    except ValueError as error:
        assert "4 runs hold results of another world" in str(error)
    assert sa.sweep(path, out=tmp_path / "out", force=True).report["ran"] == 4


def test_an_empty_out_is_refused_before_anything_runs(demo, tmp_path, monkeypatch):
    path = write_sweep(tmp_path, demo)
    work = tmp_path / "work"
    work.mkdir()
    monkeypatch.chdir(work)
    try:
        sa.sweep(path, out="")
        raise AssertionError("ran a sweep into the working folder")
    except ValueError as error:
        assert "out: expected a path, got ''" in str(error)
    assert list(work.iterdir()) == []


def test_a_sweeps_frames_load_after_the_caller_changes_folder(demo, tmp_path, monkeypatch):
    path = write_sweep(tmp_path, demo)
    monkeypatch.chdir(tmp_path)
    done = sa.sweep(path, out="relative")
    monkeypatch.chdir("/")
    assert done.out == tmp_path / "relative"
    assert len(done.summary()) > 0


def test_an_out_that_is_a_file_is_refused_by_name(demo, tmp_path):
    path = write_sweep(tmp_path, demo)
    (tmp_path / "afile").write_text("mine\n")
    with pytest.raises(ValueError, match="out .*afile: is a file, not a folder"):
        sa.sweep(path, out=tmp_path / "afile")
    assert (tmp_path / "afile").read_text() == "mine\n"


def test_paths_that_are_not_utf8_are_paths_too(demo, tmp_path):
    # Taken as UTF-8 text, such a sweep file was refused as an argument of the wrong type, and
    # such an `out` failed after every run and the merge were written.
    folder = tmp_path / os.fsdecode(b"sweeps-\xe9")
    folder.mkdir()
    path = write_sweep(folder, demo)
    out = os.fsencode(tmp_path) + b"/out-\xff"
    done = sa.sweep(path, out=out, threads=1)
    assert done.report["out"] == os.fsdecode(out)
    assert done.out == tmp_path / os.fsdecode(b"out-\xff")
    assert len(done.results()) > 0
    again = sa.sweep(os.fsencode(path), out=os.fsdecode(out), threads=1)
    assert again.report["ran"] == 0
