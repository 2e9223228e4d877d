"""Ctrl-C stops a long run cleanly: KeyboardInterrupt, the world left usable at its last event."""

import os
import signal
import threading

import exact2d
import pytest
from conftest import gas_scene


@pytest.fixture(autouse=True)
def sigint_raises_keyboard_interrupt():
    """Python's own Ctrl-C handler for the test, whatever the process inherited: a shell's
    background job starts with SIGINT ignored, and Python then never installs it (these tests
    failed under `bash -c '... &'` with "DID NOT RAISE")."""
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    yield
    signal.signal(signal.SIGINT, previous)


@pytest.mark.skipif(os.name != "posix", reason="needs SIGINT")
def test_ctrl_c_interrupts_advance_to_and_leaves_the_world_consistent():
    world = exact2d.World.from_scene(gas_scene(400, seed=1, width=40.0))
    # Some 5 x 10^7 events: minutes of work, so an interrupt that is ignored fails the test.
    until = 1e6
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        world.advance_to(until)
    timer.cancel()
    assert 0 < world.time < until
    assert world.step() is not None
    assert world.positions().shape == (400, 2)


@pytest.mark.skipif(os.name != "posix", reason="needs SIGINT")
def test_ctrl_c_interrupts_run_many():
    scenes = [gas_scene(400, seed=s, width=40.0) for s in range(2)]
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        exact2d.run_many(scenes, 1e6, threads=2)
    timer.cancel()


def test_long_runs_release_the_gil():
    world = exact2d.World.from_scene(gas_scene(400, seed=2, width=40.0))
    counter = [0]
    seen = {}

    def run():
        seen["before"] = counter[0]
        world.advance_to(1000.0)  # some 5 x 10^4 events
        seen["after"] = counter[0]

    thread = threading.Thread(target=run)
    thread.start()
    while thread.is_alive():
        counter[0] += 1
    thread.join()
    # Held through the run, the GIL would have kept this thread from counting meanwhile.
    assert seen["after"] - seen["before"] > 1000, seen
