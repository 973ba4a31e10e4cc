"""The turtle engine against turtlesim's numbers (Noetic): pure, no ROS, no clock."""

from __future__ import annotations

import numpy as np
import pytest

from rosx_turtle.engine import (
    CENTRE,
    PI,
    WORLD_SIZE,
    NameTakenError,
    Simulation,
    TickReport,
    Turtles,
    wall_warning,
)
from rosx_turtle.engine.constants import DEFAULT_BACKGROUND, DEFAULT_PEN, DT

BACKGROUND = tuple(DEFAULT_BACKGROUND)
PEN = tuple(DEFAULT_PEN)


def pond() -> Simulation:
    """A simulation as turtlesim starts: turtle1 at the centre, heading 0."""
    sim = Simulation(seed=7)
    assert sim.spawn(CENTRE, CENTRE, 0.0) == "turtle1"
    return sim


def run(sim: Simulation, ticks: int, start: float) -> list[TickReport]:
    """``ticks`` ticks, 16 ms of wall time apart from ``start``."""
    return [sim.tick(start + k * DT) for k in range(ticks)]


def test_world_and_start_pose() -> None:
    assert WORLD_SIZE == 11.088889122009277
    assert CENTRE == 5.544444561004639
    assert f"{CENTRE:f}" == "5.544445"
    report = pond().tick(0.0)
    assert report.turtles.names == ("turtle1",)
    assert report.pose(0) == (5.544444561004639, 5.544444561004639, 0.0, 0.0, 0.0)
    assert report.x.dtype == np.float32
    assert not report.changed


def test_one_command_moves_about_two_metres_then_stops() -> None:
    sim = pond()
    sim.command("turtle1", 2.0, 0.0, 0.0, now=100.0)
    reports = run(sim, 120, start=100.0)
    moving = [r for r in reports if r.changed]
    assert len(moving) in (62, 63)
    assert all(r.pose(0)[3] == 2.0 for r in moving)
    assert reports[-1].pose(0)[3:] == (0.0, 0.0)
    travelled = reports[-1].pose(0)[0] - CENTRE
    assert travelled == pytest.approx(0.032 * len(moving))
    assert abs(travelled - 2.0) < 0.02
    assert reports[-1].pose(0)[1] == CENTRE


def test_commands_replace_each_other_and_a_zero_twist_stops_at_once() -> None:
    sim = pond()
    sim.command("turtle1", 2.0, 0.0, 0.0, now=0.0)
    sim.command("turtle1", 1.0, 0.0, 0.0, now=0.0)
    first = sim.tick(0.0)
    assert first.pose(0)[0] == pytest.approx(CENTRE + 0.016)
    sim.command("turtle1", 0.0, 0.0, 0.0, now=0.016)
    assert not sim.tick(0.032).changed


def test_a_command_lasts_exactly_one_second_of_wall_time() -> None:
    sim = pond()
    sim.command("turtle1", 1.0, 0.0, 0.0, now=10.0)
    assert sim.tick(11.0).pose(0)[3] == 1.0  # 1.0 s is not more than 1.0 s
    assert sim.tick(11.001).pose(0)[3] == 0.0


def test_reversing_reports_a_positive_speed_and_the_signed_turn_rate() -> None:
    sim = pond()
    sim.command("turtle1", -2.0, 0.0, -1.5, now=0.0)
    x, _, theta, linear, angular = sim.tick(0.0).pose(0)
    assert x < CENTRE
    assert theta == pytest.approx(-1.5 * DT)
    assert (linear, angular) == (2.0, -1.5)


def test_semi_implicit_euler_uses_the_new_heading() -> None:
    sim = pond()
    sim.command("turtle1", 1.0, 0.0, 10.0, now=0.0)
    x, y, theta, *_ = sim.tick(0.0).pose(0)
    turned = 10.0 * DT
    assert theta == pytest.approx(turned)
    assert x == pytest.approx(CENTRE + np.cos(turned) * DT)
    assert y == pytest.approx(CENTRE + np.sin(turned) * DT)


def test_linear_y_moves_sideways_in_noetic() -> None:
    sim = pond()
    sim.command("turtle1", 0.0, 1.0, 0.0, now=0.0)
    x, y, _, linear, _ = sim.tick(0.0).pose(0)
    assert x == CENTRE
    assert y == pytest.approx(CENTRE + DT)
    assert linear == 1.0


@pytest.mark.parametrize("rate", [2.0, -2.0, 7.3, -50.0])
def test_theta_stays_in_minus_pi_to_pi(rate: float) -> None:
    sim = pond()
    thetas = []
    for k in range(400):
        sim.command("turtle1", 0.0, 0.0, rate, now=k * DT)
        thetas.append(sim.tick(k * DT).turtles.theta[0])
    assert all(-PI <= t < PI for t in thetas)
    assert min(thetas) < -3.0 and max(thetas) > 3.0


def test_one_turn_command_turns_about_two_radians() -> None:
    sim = pond()
    sim.command("turtle1", 0.0, 0.0, 2.0, now=0.0)
    theta = run(sim, 100, start=0.0)[-1].pose(0)[2]
    assert abs(theta - 2.0) < 0.04


def test_the_wall_warning_prints_internal_top_origin_y() -> None:
    sim = pond()
    sim.teleport_absolute("turtle1", WORLD_SIZE, CENTRE, 0.0)
    sim.tick(0.0)
    sim.command("turtle1", 2.0, 0.0, 0.0, now=0.0)
    first, second = run(sim, 2, start=0.0)
    assert first.walls.messages() == [
        "Oh no! I hit the wall! (Clamping from [x=11.120889, y=5.544445])"
    ]
    assert second.walls.messages() == first.walls.messages()  # pushing on: every tick
    assert first.pose(0)[0] == WORLD_SIZE
    assert first.pose(0)[3] == 2.0  # velocities are not touched


def test_leaving_through_the_bottom_prints_y_beyond_the_height() -> None:
    sim = pond()
    sim.teleport_absolute("turtle1", 3.0, 0.0, -PI / 2)
    sim.tick(0.0)
    sim.command("turtle1", 2.0, 0.0, 0.0, now=0.0)
    report = sim.tick(0.0)
    assert report.walls.messages() == [
        "Oh no! I hit the wall! (Clamping from [x=3.000000, y=11.120889])"
    ]
    assert report.pose(0)[1] == 0.0


def test_leaving_through_the_top_prints_a_negative_y() -> None:
    sim = pond()
    sim.teleport_absolute("turtle1", 3.0, WORLD_SIZE, PI / 2)
    sim.tick(0.0)
    sim.command("turtle1", 2.0, 0.0, 0.0, now=0.0)
    report = sim.tick(0.0)
    assert report.walls.messages() == [
        "Oh no! I hit the wall! (Clamping from [x=3.000000, y=-0.032000])"
    ]
    assert report.pose(0)[1] == pytest.approx(WORLD_SIZE)


def test_wall_warning_text() -> None:
    assert (
        wall_warning(-0.5, 2.25)
        == "Oh no! I hit the wall! (Clamping from [x=-0.500000, y=2.250000])"
    )


def test_teleports_wait_for_the_next_tick() -> None:
    sim = pond()
    assert sim.teleport_absolute("turtle1", 1.0, 2.0, 0.5)
    assert sim.turtles.x[0] == CENTRE
    report = sim.tick(0.0)
    x, y, theta, *_ = report.pose(0)
    assert (x, theta) == (1.0, np.float32(0.5))
    assert y == pytest.approx(2.0)
    assert report.changed
    assert not report.walls.messages()


def test_absolute_teleport_above_the_world_lands_on_the_top_edge_silently() -> None:
    sim = pond()
    sim.teleport_absolute("turtle1", 5.0, 20.0, 0.0)
    report = sim.tick(0.0)
    assert report.pose(0)[1] == WORLD_SIZE
    assert len(report.walls) == 0


def test_absolute_teleport_left_of_the_world_hits_the_wall() -> None:
    sim = pond()
    sim.teleport_absolute("turtle1", -1.0, CENTRE, 0.0)
    report = sim.tick(0.0)
    assert report.walls.messages() == [
        "Oh no! I hit the wall! (Clamping from [x=-1.000000, y=5.544445])"
    ]
    assert report.pose(0)[0] == 0.0


def test_relative_teleport_turns_then_moves() -> None:
    sim = pond()
    sim.teleport_relative("turtle1", 1.0, PI / 2)
    x, y, theta, *_ = sim.tick(0.0).pose(0)
    assert x == pytest.approx(CENTRE, abs=1e-6)
    assert y == pytest.approx(CENTRE + 1.0)
    assert theta == pytest.approx(PI / 2)


def test_teleports_apply_in_order_and_keep_the_velocity() -> None:
    sim = pond()
    sim.command("turtle1", 1.0, 0.0, 0.0, now=0.0)
    sim.teleport_absolute("turtle1", 2.0, 2.0, 0.0)
    sim.teleport_relative("turtle1", 1.0, 0.0)
    report = sim.tick(0.0)
    assert report.pose(0)[0] == pytest.approx(3.0 + DT)
    assert len(report.strokes) == 3  # two jumps and the step


def test_teleports_of_unknown_or_killed_turtles_do_nothing() -> None:
    sim = pond()
    assert not sim.teleport_absolute("nobody", 1.0, 1.0, 0.0)
    sim.spawn(1.0, 1.0, 0.0, "t")
    sim.teleport_relative("t", 1.0, 0.0)
    sim.kill("t")
    assert not sim.tick(0.0).changed


def test_spawn_naming_counter() -> None:
    sim = pond()
    assert sim.spawn(2.0, 3.0, 0.5) == "turtle2"
    assert sim.spawn(2.0, 3.0, 0.5) == "turtle3"
    assert sim.kill("turtle2")
    assert sim.spawn(1.0, 1.0, 0.0) == "turtle4"  # kill never lowers the counter
    assert sim.spawn(1.0, 1.0, 0.0, "turtle5") == "turtle5"  # explicit: counter unchanged
    assert sim.counter == 4
    assert sim.spawn(1.0, 1.0, 0.0) == "turtle6"  # taken names are skipped
    with pytest.raises(NameTakenError):
        sim.spawn(1.0, 1.0, 0.0, "turtle3")
    assert sim.turtles.names == ("turtle1", "turtle3", "turtle4", "turtle5", "turtle6")


def test_spawn_takes_float32_values_without_clamping() -> None:
    sim = Simulation(seed=1)
    sim.spawn(0.1, 20.0, 4.0, "far")
    assert sim.turtles.x[0] == np.float32(0.1)
    assert sim.turtles.theta[0] == np.float32(4.0)
    report = sim.tick(0.0)
    assert report.walls.messages() == [
        f"Oh no! I hit the wall! (Clamping from [x={np.float32(0.1):f}, y=-8.911111])"
    ]
    assert -PI <= report.turtles.theta[0] < PI


def test_kill_and_reset() -> None:
    sim = pond()
    sim.spawn(1.0, 1.0, 0.0)
    assert not sim.kill("nobody")
    assert not sim.kill("")
    assert sim.kill("turtle1")
    assert sim.turtles.names == ("turtle2",)
    assert sim.kill("turtle2")
    assert len(sim.tick(0.0).turtles) == 0
    sim.spawn(1.0, 1.0, 0.0)
    assert sim.reset(BACKGROUND) == "turtle1"
    assert sim.counter == 1
    assert sim.turtles.names == ("turtle1",)
    assert sim.spawn(1.0, 1.0, 0.0) == "turtle2"


def test_pen_draws_trails_unless_off() -> None:
    sim = pond()
    sim.command("turtle1", 2.0, 0.0, 0.0, now=0.0)
    report = sim.tick(0.0)
    assert len(report.strokes) == 1
    assert tuple(report.strokes.rgb[0]) == PEN
    assert report.strokes.width[0] == 3
    assert sim.set_pen("turtle1", 255, 0, 0, 5, 1)
    report = sim.tick(0.0)
    assert report.changed and len(report.strokes) == 0
    assert tuple(sim.turtles.pen_rgb[0]) == PEN  # off keeps colour and width
    assert sim.turtles.pen_width[0] == 3


def test_pen_width_zero_is_a_fresh_one_pixel_pen() -> None:
    sim = pond()
    sim.set_pen("turtle1", 10, 20, 30, 7, 0)
    assert sim.turtles.pen_width[0] == 7
    sim.set_pen("turtle1", 10, 20, 30, 0, 0)
    assert sim.turtles.pen_width[0] == 1
    assert tuple(sim.turtles.pen_rgb[0]) == (10, 20, 30)
    assert not sim.set_pen("nobody", 0, 0, 0, 0, 0)


def test_colour_sensor_reads_background_then_pen() -> None:
    sim = pond()
    assert tuple(sim.tick(0.0).colours[0]) == BACKGROUND
    sim.set_pen("turtle1", 255, 0, 0, 3, 0)
    sim.command("turtle1", 1.0, 0.0, 0.0, now=0.0)  # 0.72 px a tick: within the trail's cap
    first, *later = run(sim, 20, start=0.0)
    assert tuple(first.colours[0]) == BACKGROUND  # read before this tick's own trail
    assert {tuple(report.colours[0]) for report in later} == {(255, 0, 0)}


def test_clear_erases_trails_and_takes_the_new_background() -> None:
    sim = pond()
    sim.command("turtle1", 2.0, 0.0, 0.0, now=0.0)
    run(sim, 3, start=0.0)
    assert tuple(sim.tick(5.0).colours[0]) == PEN
    sim.clear((1, 2, 259))
    assert tuple(sim.tick(5.0).colours[0]) == (1, 2, 3)
    assert (sim.canvas.pixels == (1, 2, 3)).all()


def test_rows_are_sorted_by_name_and_stepped_together() -> None:
    sim = Simulation(seed=3)
    for name, x in (("b", 1.0), ("a", 2.0), ("c", 3.0)):
        sim.spawn(x, 1.0, 0.0, name)
        sim.command(name, x, 0.0, 0.5, now=0.0)
    together = sim.tick(0.0)
    assert together.turtles.names == ("a", "b", "c")
    for name, x in (("b", 1.0), ("a", 2.0), ("c", 3.0)):
        alone = Simulation(seed=3)
        alone.spawn(x, 1.0, 0.0, name)
        alone.command(name, x, 0.0, 0.5, now=0.0)
        assert alone.tick(0.0).pose(0) == together.pose(together.turtles.row(name) or 0)


def test_turtles_create_sorts_and_refuses_duplicates() -> None:
    turtles = Turtles.create(["b", "a"], [1.0, 2.0], [3.0, 4.0], [0.0, 0.1])
    assert turtles.names == ("a", "b")
    assert list(turtles.x) == [2.0, 1.0]
    assert turtles.row("b") == 1 and "a" in turtles
    with pytest.raises(ValueError, match="unique"):
        Turtles.create(["a", "a"], 0.0, 0.0, 0.0)


def test_sprites_are_chosen_from_fourteen() -> None:
    sim = Simulation(seed=5)
    for _ in range(50):
        sim.spawn(1.0, 1.0, 0.0)
    assert set(sim.turtles.sprite.tolist()) <= set(range(14))
    assert len(set(sim.turtles.sprite.tolist())) > 1
