"""teleop_twist_keyboard's keys and speeds (`rosx_turtle.teleop_twist.TwistKeys`)."""

from __future__ import annotations

import pytest

from rosx_turtle.teleop_twist import HELP, TwistKeys, speeds_line


def test_moves_stops_and_strafes() -> None:
    keys = TwistKeys()
    keys, lines, send = keys.press("i")
    assert (keys.command(), lines, send) == ((0.5, 0.0, 0.0, 0.0), [], True)
    keys, _, _ = keys.press("u")
    assert keys.command() == (0.5, 0.0, 0.0, 1.0)
    keys, _, _ = keys.press("J")
    assert keys.command() == (0.0, 0.5, 0.0, 0.0)
    keys, _, send = keys.press("k")
    assert (keys.command(), send) == ((0.0, 0.0, 0.0, 0.0), True)
    keys, _, send = keys.press("")  # the key timeout, already stopped: nothing to send
    assert not send


def test_speeds_scale_and_stop_at_their_limits() -> None:
    keys, lines, _ = TwistKeys().press("q")
    assert (keys.speed, keys.turn) == pytest.approx((0.55, 1.1))
    assert lines == [speeds_line(keys.speed, keys.turn)]
    assert speeds_line(0.5, 1.0) == "currently:\tspeed 0.5\tturn 1.0 "
    keys, _, _ = TwistKeys(speed_limit=0.52).press("w")
    assert keys.speed == 0.52
    keys, lines, _ = TwistKeys(speed_limit=0.52).press("w")
    assert lines[0] == "Linear speed limit reached!"
    keys = TwistKeys()
    for _ in range(14):
        keys, lines, _ = keys.press("c")
    assert HELP not in lines
    keys, lines, _ = keys.press("c")
    assert lines[-1] == HELP  # the help again after fifteen changes
