"""``rosx sim``: Lab 1 in one process (master, /rosout, turtlesim, teleop and a screen)."""

from __future__ import annotations

from collections.abc import Sequence

from rosx_commands.context import Environment


def sim(argv: Sequence[str], env: Environment) -> int:
    """Run ``rosx sim ARGV…`` (see `rosx_turtle.sim.run`)."""
    from rosx_turtle.sim import run_sim  # noqa: PLC0415 - turtlesim only for this command

    return run_sim(argv, env)
