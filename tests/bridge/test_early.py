"""A publisher's first second, kept for the subscribers that connect within it."""

from __future__ import annotations

from typing import Any

from rosx.bridge.early import EarlyMessages


def test_subscribers_of_the_first_second_get_what_came_before_them() -> None:
    clock = [100.0]
    early = EarlyMessages(lambda: clock[0])
    early.keep("a")  # type: ignore[arg-type]
    early.keep("b")  # type: ignore[arg-type]
    first: list[Any] = []
    early.subscribed(first.append)
    assert first == ["a", "b"]
    clock[0] = 101.5
    early.keep("c")  # type: ignore[arg-type]
    late: list[Any] = []
    early.subscribed(late.append)
    assert late == []  # past the window, a subscriber gets only what is published from then on
