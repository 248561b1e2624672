"""Ctrl-C in a long call raises KeyboardInterrupt soon after and leaves nothing half-written."""

import os
import signal
import subprocess
import sys
import textwrap
import time

# Long enough never to end by itself within the tests' patience (10^7 steps per replicate).
FOREVER = {"run.duration": 1e6}
PATIENCE = 60  # s; a child still running then is a hang, not slowness


def interrupt_child(script: str, ready=lambda: True) -> subprocess.CompletedProcess:
    """Starts `script` in a fresh interpreter, sends SIGINT once it says it is about to make
    its long call and `ready()` holds, and returns how it ended."""
    child = subprocess.Popen([sys.executable, "-c", textwrap.dedent(script)], stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True, env=os.environ.copy())
    assert child.stdout.readline().strip() == "calling"
    time.sleep(1.0)  # let the call get into its loop
    deadline = time.monotonic() + PATIENCE
    while not ready():
        assert time.monotonic() < deadline, "the call never got where it should be interrupted"
        time.sleep(0.1)
    child.send_signal(signal.SIGINT)
    try:
        out, err = child.communicate(timeout=PATIENCE)
    except subprocess.TimeoutExpired:
        child.kill()
        raise AssertionError("the call went on after Ctrl-C")
    return subprocess.CompletedProcess(child.args, child.returncode, out, err)


def test_ctrl_c_stops_a_run_with_keyboard_interrupt(demo):
    ended = interrupt_child(f"""
        import swarmagg as sa
        world = sa.load_world({str(demo)!r}, set={FOREVER!r})
        print("calling", flush=True)
        try:
            sa.run(world, replicates=2, threads=2)
        except KeyboardInterrupt:
            print("interrupted", flush=True)
            sa.run(sa.load_world({str(demo)!r}, set={{"run.duration": 1}}), replicates=1)
            print("runs again", flush=True)
    """)
    assert ended.returncode == 0, ended.stderr
    assert ended.stdout.splitlines() == ["interrupted", "runs again"]


def test_ctrl_c_stops_a_sweep_and_leaves_only_complete_runs(demo, tmp_path):
    sweep_file = tmp_path / "long.yaml"
    sweep_file.write_text(f"name: long\nbase: {demo}\nparameters:\n  run.duration: [1, 1000000]\n"
                          "replicates: 2\nseed: 3\n")
    out = tmp_path / "out"
    short_runs_done = lambda: len(list(out.glob("runs/run.duration=1/rep-*/world.resolved.yaml"))) == 2
    ended = interrupt_child(f"""
        import swarmagg as sa
        print("calling", flush=True)
        try:
            sa.sweep({str(sweep_file)!r}, out={str(out)!r}, threads=2)
        except KeyboardInterrupt:
            print("interrupted", flush=True)
    """, ready=short_runs_done)
    assert ended.returncode == 0, ended.stderr
    assert ended.stdout.splitlines() == ["interrupted"]
    runs = [p for p in (out / "runs").glob("*/rep-*")]
    # The short point's runs finished; the long ones left no folder at all.
    assert sorted(p.parent.name for p in runs) == ["run.duration=1"] * 2
    assert all((p / "world.resolved.yaml").is_file() for p in runs)
    assert not [p for p in out.rglob("*") if p.name.endswith(".tmp")]
    assert not (out / "sweep_timeseries.csv").exists()


def test_ctrl_c_stops_only_the_call_it_interrupted(demo):
    # A run another Python thread has in flight goes on and returns its results.
    ended = interrupt_child(f"""
        import threading
        import swarmagg as sa
        result = {{}}
        def other_run():
            try:
                run = sa.run(sa.load_world({str(demo)!r}, set={{"run.duration": 1.5e5}}),
                             replicates=1, threads=1)
                result["other"] = len(run.timeseries())
            except BaseException as error:
                result["other"] = type(error).__name__
        other = threading.Thread(target=other_run)
        other.start()
        print("calling", flush=True)
        try:
            sa.run(sa.load_world({str(demo)!r}, set={FOREVER!r}), replicates=1, threads=1)
        except KeyboardInterrupt:
            print("interrupted", "while the other ran" if other.is_alive() else "too late",
                  flush=True)
        other.join()
        print(result["other"], flush=True)
    """)
    assert ended.returncode == 0, ended.stderr
    assert ended.stdout.splitlines() == ["interrupted while the other ran", "150001"]


def test_an_interpreter_exits_cleanly_while_a_daemon_thread_is_in_a_long_call(demo):
    # Python ends a daemon thread that takes the GIL back during its shutdown (pthread_exit);
    # a long call's wait took it back in a destructor, which turned that into std::terminate
    # (exit 134, "terminate called without an active exception").
    script = f"""
        import threading, time
        import swarmagg as sa
        world = sa.load_world({str(demo)!r}, set={FOREVER!r})
        for _ in range(2):
            threading.Thread(target=lambda: sa.run(world, replicates=1, threads=1),
                             daemon=True).start()
        time.sleep(1.0)
        print("main exits")
    """
    done = subprocess.run([sys.executable, "-c", textwrap.dedent(script)], capture_output=True,
                          text=True, env=os.environ.copy(), timeout=PATIENCE)
    assert done.returncode == 0, done.stderr
    assert "terminate" not in done.stderr
    assert done.stdout.strip() == "main exits"
