"""The turtle engine's speed: one 16 ms tick of 1, 100 and 10 000 turtles.

turtlesim itself has no ROS 1 counterpart on this machine to compare with (it is a Qt program),
so the figure is held against the tick it must fit in: every turtle stepped in well under 16 ms
on one core. Each turtle drives in a circle (2 m/s, 1 rad/s) from a random place, so every tick
integrates, clamps the ones that reach a wall, reads every colour sensor and draws every trail.
Printed: the median and the 90th percentile of a tick, for pens on (the whole tick) and pens off
(motion and sensors without drawing), and the share of the 16 ms budget the median uses.

    python bench/bench_turtle.py [--ticks 200] [--seed 1]
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path[:0] = [str(ROOT), str(ROOT / "turtle")]

TICK_MS = 16.0


def populate(count: int, seed: int, pens: bool) -> object:
    import numpy as np

    from rosx_turtle.engine import WORLD_SIZE, Simulation, Turtles

    rng = np.random.default_rng(seed)
    sim = Simulation(seed=seed)
    turtles = Turtles.create(
        [f"turtle{i + 1}" for i in range(count)],
        rng.uniform(0, WORLD_SIZE, count),
        rng.uniform(0, WORLD_SIZE, count),
        rng.uniform(-np.pi, np.pi, count),
        rng.integers(14, size=count),
    )
    sim.turtles = turtles.evolve(
        vx=np.full(count, 2.0),
        w=np.full(count, 1.0),
        pen_on=np.full(count, pens),
    )
    return sim


def measure(count: int, ticks: int, seed: int, pens: bool) -> list[float]:
    sim = populate(count, seed, pens)
    tick = sim.tick  # type: ignore[attr-defined]
    for _ in range(5):  # warm-up
        tick(0.5)
    samples = []
    for _ in range(ticks):
        start = time.perf_counter()
        tick(0.5)  # within a second of the (time 0) command: every turtle keeps moving
        samples.append((time.perf_counter() - start) * 1000)
    return samples


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--ticks", type=int, default=200)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    print("| turtles | pens | median ms/tick | p90 ms/tick | µs/turtle | share of 16 ms |")
    print("|---|---|---|---|---|---|")
    for count in (1, 100, 10_000):
        for pens in (True, False):
            samples = sorted(measure(count, args.ticks, args.seed, pens))
            median = statistics.median(samples)
            p90 = samples[int(len(samples) * 0.9) - 1]
            print(
                f"| {count:,} | {'on' if pens else 'off'} | {median:.3f} | {p90:.3f} "
                f"| {median * 1000 / count:.2f} | {median / TICK_MS:.0%} |"
            )


if __name__ == "__main__":
    main()
