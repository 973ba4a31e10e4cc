"""The reports of rostopic hz / bw / delay, from fixed arrival times (texts as ROS 1 prints)."""

from __future__ import annotations

from rosx.node.stats import BandwidthTracker, DelayTracker, HzTracker, hz_table


def test_hz_single_topic() -> None:
    tracker = HzTracker()
    assert tracker.report(["/t"]) == "no new messages"
    for when in (10.0, 10.1, 10.2, 10.35):
        tracker.arrived("/t", when)
    assert tracker.report(["/t"]) == (
        "average rate: 8.571\n\tmin: 0.100s max: 0.150s std dev: 0.02357s window: 4"
    )
    assert tracker.report(["/t"]) == "no new messages"


def test_hz_window_keeps_the_last_gaps() -> None:
    tracker = HzTracker(3)
    for when in (0.0, 1.0, 1.5, 1.75):
        tracker.arrived("/t", when)
    assert tracker.report(["/t"]) == (
        "average rate: 2.667\n\tmin: 0.250s max: 0.500s std dev: 0.12500s window: 3"
    )


def test_hz_table_is_ros1s_including_its_window_column() -> None:
    rows = [
        ("/ps", (9.999, 0.0998, 0.1002, 0.0001072, 10)),
        ("/s", (20.0, 0.04854, 0.05142, 0.0004694, 20)),
    ]
    # ROS 1 fills the window column twice per topic, so the second row repeats the first's.
    assert hz_table(rows) == (
        "topic    rate   min_delta   max_delta    std_dev    window\n"
        "==========================================================\n"
        "/ps     9.999   0.0998      0.1002      0.0001072   10    \n"
        "/s      20.0    0.04854     0.05142     0.0004694   10    \n"
    )


def test_bw_units_and_window() -> None:
    tracker = BandwidthTracker()
    tracker.arrived(40, 1.0)
    assert tracker.report(1.5) is None
    tracker.arrived(40, 1.5)
    assert tracker.report(2.0) == (
        "average: 80.00B/s\n\tmean: 40.00B min: 40.00B max: 40.00B window: 2"
    )
    big = BandwidthTracker(2)
    for when in (0.0, 0.5, 1.0):
        big.arrived(1_500_000, when)
    assert big.report(1.5) == (
        "average: 3.00MB/s\n\tmean: 1.50MB min: 1.50MB max: 1.50MB window: 2"
    )


def test_delay() -> None:
    tracker = DelayTracker()
    tracker.arrived(5.0, 4.9)
    assert tracker.report() is None  # the first message only starts the clock
    tracker.arrived(5.1, 4.9)
    tracker.arrived(5.2, 5.15)
    assert tracker.report() == (
        "average delay: 0.125\n\tmin: 0.050s max: 0.200s std dev: 0.07500s window: 3"
    )
    assert tracker.report() == "no new messages"


def test_time_reset_drops_what_was_measured_as_ros1_does() -> None:
    """ROS time reading 0 again (a simulator or a bag restarted): the gaps so far go, once."""
    hz = HzTracker()
    assert hz.time_reset("/t") is False  # nothing measured: ROS 1 prints nothing
    for when in (10.0, 10.5, 11.0):
        hz.arrived("/t", when)
    assert hz.time_reset("/t") is True
    assert hz.time_reset("/t") is False
    assert hz.report(["/t"]) == "no new messages"
    for when in (0.5, 1.0, 1.25):  # time starts again from 0: a new start, then gaps
        hz.arrived("/t", when)
    assert hz.report(["/t"]) == (
        "average rate: 2.667\n\tmin: 0.250s max: 0.500s std dev: 0.12500s window: 3"
    )
    delay = DelayTracker()
    assert delay.time_reset() is False
    for now in (5.0, 5.1):
        delay.arrived(now, 4.9)
    assert delay.time_reset() is True
    assert delay.report() is None
