"""Benchmarks of the Python bindings (printed, never asserted): run with
``python python/bench.py`` after ``pip install ./python``.

1. The Rust loop (``advance_to``: no Python between events) against driving it from Python
   one event at a time (``step_until``, one ``Event`` object per call) and against collecting
   every event as NumPy columns (``advance_to_collect``). Goal: collecting costs under 2x the
   Rust loop.
2. ``OneMoreBrick-v0`` steps per second with a random policy over whole games, on one core
   (floor: 300 steps per second).
3. ``run_many`` on 1 and 2 threads.

The scenes are seeded; the timings are wall-clock and vary with the machine's load.
"""

import argparse
import os
import shutil
import subprocess
import time

import numpy as np

import exact2d
import onemorebrick


def gas_scene(n, seed, side=40.0, radius=0.3):
    """n disks on a lattice in a square box, random velocities."""
    rng = np.random.default_rng(seed)
    per_row = int(np.ceil(np.sqrt(n)))
    spacing = side / (per_row + 1)
    balls = [
        {
            "id": i,
            "pos": [(1 + i % per_row) * spacing, (1 + i // per_row) * spacing],
            "vel": rng.normal(size=2).tolist(),
            "radius": radius,
        }
        for i in range(n)
    ]
    corners = [[0.0, 0.0], [side, 0.0], [side, side], [0.0, side]]
    segments = [{"a": a, "b": b} for a, b in zip(corners, corners[1:] + corners[:1])]
    return {"ball_ball": True, "segments": segments, "balls": balls}


def best_of(repeats, run):
    """The fastest of ``repeats`` runs of ``run()`` (which returns (seconds, events))."""
    return min((run() for _ in range(repeats)), key=lambda r: r[0] / max(r[1], 1))


def timed(scene, until, how):
    world = exact2d.World.from_scene(scene)
    start = time.perf_counter()
    if how == "rust":
        events = world.advance_to(until)
    elif how == "collect":
        events = len(world.advance_to_collect(until)["time"])
    elif how == "step":
        # step() has no target time: take as many events as the Rust loop handles to `until`.
        target = exact2d.World.from_scene(scene).advance_to(until)
        start = time.perf_counter()
        step = world.step
        for events in range(1, target + 1):
            step()
    else:
        events = 0
        step = world.step_until
        while step(until) is not None:
            events += 1
    return time.perf_counter() - start, events


def bench_overhead(n, until, repeats):
    scene = gas_scene(n, seed=1)
    print(f"1. events of a {n}-disk gas to t = {until} (best of {repeats})")
    rows = {}
    for how, label in [
        ("rust", "advance_to (the Rust loop)"),
        ("collect", "advance_to_collect (NumPy columns)"),
        ("python", "step_until per event (an Event each)"),
        ("step", "step() per event (an Event each)"),
    ]:
        seconds, events = best_of(repeats, lambda: timed(scene, until, how))
        rows[how] = seconds / events
        print(f"   {label:<40} {events:>9} events  {1e9 * seconds / events:8.1f} ns/event")
    print(f"   collecting costs {rows['collect'] / rows['rust']:.2f}x the Rust loop (goal < 2x)")
    for how in ("python", "step"):
        name = "step_until" if how == "python" else "step()"
        print(
            f"   one {name} call from Python: {1e9 * (rows[how] - rows['rust']):.0f} ns of "
            f"overhead per event ({rows[how] / rows['rust']:.2f}x the Rust loop)"
        )
    cli = shutil.which("exact2d") or os.path.join(
        os.path.dirname(__file__), "..", "target", "release", "exact2d"
    )
    if os.path.exists(cli):
        import json
        import tempfile

        with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
            json.dump(scene, f)
        out = subprocess.run([cli, "simulate", f.name, "--until", str(until)], capture_output=True, text=True)
        os.unlink(f.name)
        if out.returncode == 0:
            result = json.loads(out.stdout)
            per = result["wall_s"] / result["events"]
            print(f"   the exact2d CLI (no Python at all)        {result['events']:>9} events  {1e9 * per:8.1f} ns/event")


def bench_env(games):
    env = onemorebrick.OneMoreBrickEnv()
    env.action_space.seed(0)
    steps, start = 0, time.perf_counter()
    for k in range(games):
        env.reset(seed=k)
        done = False
        while not done:
            _, _, terminated, truncated, _ = env.step(env.action_space.sample())
            done = terminated or truncated
            steps += 1
    seconds = time.perf_counter() - start
    print(f"2. OneMoreBrick-v0, random policy, {games} whole games: {steps} steps in {seconds:.2f} s")
    print(f"   {steps / seconds:.0f} steps per second on one core (floor: 300)")


def bench_run_many(count, n, until):
    scenes = [gas_scene(n, seed=s) for s in range(count)]
    print(f"3. run_many: {count} gases of {n} disks to t = {until}")
    base = None
    for threads in (1, 2):
        start = time.perf_counter()
        results = exact2d.run_many(scenes, until, threads=threads)
        seconds = time.perf_counter() - start
        events = sum(r["events"] for r in results)
        base = base or seconds
        print(
            f"   threads={threads}: {seconds:.2f} s, {events / seconds / 1e6:.2f} M events/s, "
            f"speed-up {base / seconds:.2f}x"
        )


def main():
    parser = argparse.ArgumentParser(description="benchmarks of the Python bindings")
    parser.add_argument("--quick", action="store_true", help="smaller runs")
    args = parser.parse_args()
    q = args.quick
    bench_overhead(1000, 20.0 if q else 100.0, 2 if q else 3)
    bench_env(5 if q else 30)
    bench_run_many(4 if q else 8, 1000, 20.0 if q else 60.0)


if __name__ == "__main__":
    main()
