"""rqt_plot's series: the command line shorthand, ring buffers that never grow, thinning."""

from __future__ import annotations

import numpy as np
import pytest

from rosx_commands.rqt_plot.feed import _numeric_path
from rosx_commands.rqt_plot.series import Series, SeriesError, envelope, expand_args


def test_shorthand_expands_as_rqt_plot_does() -> None:
    assert expand_args(["/turtle1/pose/x:y:theta"]) == [
        "/turtle1/pose/x",
        "/turtle1/pose/y",
        "/turtle1/pose/theta",
    ]
    assert expand_args(["/a/x,/b/y", "/scan/ranges[0]"]) == ["/a/x", "/b/y", "/scan/ranges[0]"]
    assert expand_args(["/odom/twist/twist/linear/x:y"]) == [
        "/odom/twist/twist/linear/x",
        "/odom/twist/twist/linear/y",
    ]
    with pytest.raises(SeriesError, match="/pose:x must contain a topic and field name"):
        expand_args(["/pose:x"])


def test_a_full_buffer_drops_the_oldest_and_keeps_time_order() -> None:
    series = Series("/x", capacity=5)
    for i in range(12):
        series.append(float(i), float(i * 10))
    times, values = series.all()
    assert times.tolist() == [7.0, 8.0, 9.0, 10.0, 11.0]
    assert values.tolist() == [70.0, 80.0, 90.0, 100.0, 110.0]
    assert len(series) == 5 and series.latest == 110.0 and series.received == 12
    times, values = series.window(8.5, 10.0)
    assert times.tolist() == [9.0, 10.0] and values.tolist() == [90.0, 100.0]
    series.clear()
    assert len(series) == 0 and series.latest is None and series.all()[0].size == 0


def test_envelope_keeps_each_columns_extremes() -> None:
    times = np.linspace(0.0, 10.0, 10_001)
    values = np.sin(times)
    values[5000] = 7.0  # a spike the thinning must not lose
    xs, ys = envelope(times, values, 0.0, 10.0, 100)
    assert len(xs) <= 2 * 101
    assert ys.max() == 7.0 and ys.min() == pytest.approx(values.min())
    assert (np.diff(xs) >= 0).all()
    few_t, few_v = np.arange(5.0), np.arange(5.0)
    assert envelope(few_t, few_v, 0.0, 5.0, 100)[0] is few_t


def test_only_numeric_fields_and_array_elements_plot() -> None:
    from rosx.msg.codec.classes import get_message_class
    from rosx.msg.store import TypeStore

    store = TypeStore([])
    scan = get_message_class("sensor_msgs/LaserScan")(ranges=[1.5, 2.5])
    assert _numeric_path(store, "sensor_msgs/LaserScan", "/scan/ranges[1]", "/ranges[1]")(
        scan
    ) == pytest.approx(2.5)
    stamp = _numeric_path(store, "sensor_msgs/LaserScan", "/scan/header/stamp", "/header/stamp")
    scan.header.stamp.secs, scan.header.stamp.nsecs = 3, 500_000_000
    assert stamp(scan) == 3.5
    refusals = {
        "/ranges": "/scan/ranges is an array (float32[]): plot one element, as /scan/ranges[0]",
        "/header/frame_id": "/scan/header/frame_id is not numeric (string)",
        "": "/scan is a topic (sensor_msgs/LaserScan): name a numeric field of it",
        "/nope": "/scan/nope: no field named nope in /nope",
    }
    for path, message in refusals.items():
        with pytest.raises(SeriesError) as refused:
            _numeric_path(store, "sensor_msgs/LaserScan", "/scan" + path, path)
        assert str(refused.value) == message
