"""Fixtures for the simulator's node tests: stageros in this process on the test's master."""

from __future__ import annotations

import io
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest

from rosx_turtle.console import Console
from rosx_turtle.roscpp import NodeArgs
from rosx_turtle.stage.node.stageros import StageNode
from rosx_turtle.stage.world.load import load_world


@pytest.fixture
def make_stage(
    master: str, tmp_path: Path
) -> Iterator[Callable[..., tuple[StageNode, io.StringIO]]]:
    """Start stageros on a world's text (``argv`` as remapping arguments); shut down after."""
    nodes: list[StageNode] = []

    def make(
        text: str, *argv: str, speed: float = 1.0, use_model_names: bool = False
    ) -> tuple[StageNode, io.StringIO]:
        path = tmp_path / f"w{len(nodes)}.world"
        path.write_text(text)
        world, grid = load_world(path)
        out = io.StringIO()
        node = StageNode(
            NodeArgs.parse(argv, "stageros"),
            world,
            grid,
            environ={"ROS_MASTER_URI": master},
            console=Console(out, out, {}),
            speed=speed,
            use_model_names=use_model_names,
        )
        nodes.append(node)
        node.start()
        return node, out

    yield make
    for node in nodes:
        node.shutdown("test over")
