"""Fixtures for turtlesim's node tests: a rosx master in this process, simulators and client
nodes that always shut down, and the simulator's console captured."""

from __future__ import annotations

import io
from collections.abc import Callable, Iterator

import pytest

from rosx_turtle.console import Console
from rosx_turtle.node import TurtlesimNode
from rosx_turtle.roscpp import NodeArgs
from tests.support.simulators import Sim


@pytest.fixture
def make_sim(master: str) -> Iterator[Callable[..., Sim]]:
    """Start simulators (``argv`` as on a command line) on the test's master."""
    sims: list[TurtlesimNode] = []

    def make(*argv: str) -> Sim:
        out, err = io.StringIO(), io.StringIO()
        sim = TurtlesimNode(
            NodeArgs.parse(argv, "turtlesim"),
            environ={"ROS_MASTER_URI": master},
            console=Console(out, err, {}),
            seed=1,
        )
        sims.append(sim)
        sim.start()
        return Sim(sim, out, err)

    yield make
    for sim in sims:
        sim.shutdown("test over")
