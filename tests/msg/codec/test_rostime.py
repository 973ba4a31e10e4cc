"""Tests for rosx.msg.codec.rostime: Time and Duration as genpy defines them.

The last test evaluates a table of expressions with both rosx and genpy (Debian's
/usr/bin/python3 in a subprocess) and compares the results; it is skipped where genpy is absent.
"""

from __future__ import annotations

import copy
import json
import pickle
import subprocess
from pathlib import Path

import pytest

from rosx.msg.codec.rostime import Duration, Time, TVal

ROS1_PYTHON = Path("/usr/bin/python3")


def _genpy_available() -> bool:
    if not ROS1_PYTHON.exists():
        return False
    probe = subprocess.run(
        [str(ROS1_PYTHON), "-c", "import genpy"], capture_output=True, check=False
    )
    return probe.returncode == 0


# -- construction and canonical form --------------------------------------------------------


def test_defaults_are_zero() -> None:
    assert (Time().secs, Time().nsecs) == (0, 0)
    assert (Duration().secs, Duration().nsecs) == (0, 0)
    assert Time().is_zero() and not Time(0, 1).is_zero()


@pytest.mark.parametrize(
    ("secs", "nsecs", "expected"),
    [
        (1, 1_500_000_000, (2, 500_000_000)),
        (1, 2_000_000_000, (3, 0)),
        (5, -1, (4, 999_999_999)),
        (0, -1_500_000_000, (-2, 500_000_000)),
        (-1, 5, (-1, 5)),
    ],
)
def test_duration_is_canonicalised(secs: int, nsecs: int, expected: tuple[int, int]) -> None:
    value = Duration(secs, nsecs)
    assert (value.secs, value.nsecs) == expected


def test_time_is_canonicalised_and_never_negative() -> None:
    value = Time(1, 1_000_000_001)
    assert (value.secs, value.nsecs) == (2, 1)
    with pytest.raises(TypeError, match="time values must be positive"):
        Time(-1)
    with pytest.raises(TypeError, match="time values must be positive"):
        Time(0, -1)


def test_float_seconds() -> None:
    value = Time(1.5)
    assert (value.secs, value.nsecs) == (1, 500_000_000)
    negative = Duration(-1.5)
    assert (negative.secs, negative.nsecs) == (-2, 500_000_000)
    with pytest.raises(ValueError, match="nsecs cannot be set"):
        Time(1.5, 3)


def test_from_and_to_seconds_and_nanoseconds() -> None:
    assert Time.from_sec(2.25) == Time(2, 250_000_000)
    assert Duration.from_sec(-0.5) == Duration(-1, 500_000_000)
    assert Time.from_nsec(3_000_000_007) == Time(3, 7)
    assert Duration.from_nsec(-1) == Duration(-1, 999_999_999)
    assert Time(2, 500_000_000).to_sec() == 2.5
    assert Time(2, 5).to_nsec() == 2_000_000_005
    assert Duration(-1, 999_999_999).to_nsec() == -1
    assert Time(3, 0).to_time() == 3.0
    assert isinstance(Time.from_sec(1.0), Time)


def test_set_and_canon() -> None:
    value = Time()
    value.set(1, 2_000_000_000)
    assert (value.secs, value.nsecs) == (1, 2_000_000_000)
    value.canon()
    assert (value.secs, value.nsecs) == (3, 0)


# -- arithmetic -----------------------------------------------------------------------------


def test_time_arithmetic() -> None:
    assert Time(5, 0) - Time(3, 500_000_000) == Duration(1, 500_000_000)
    assert isinstance(Time(5) - Time(3), Duration)
    assert Time(5, 0) + Duration(1, 600_000_000) == Time(6, 600_000_000)
    assert Duration(1) + Time(5) == Time(6)
    assert Time(5, 0) - Duration(0, 1) == Time(4, 999_999_999)
    with pytest.raises(TypeError):
        Time(5) + Time(1)
    with pytest.raises(TypeError, match="time values must be positive"):
        Time(1) - Duration(2)


def test_duration_arithmetic() -> None:
    assert Duration(1, 500_000_000) + Duration(0, 600_000_000) == Duration(2, 100_000_000)
    assert Duration(1) - Duration(2, 1) == Duration(-2, 999_999_999)
    assert Duration(1, 500_000_000) * 3 == Duration(4, 500_000_000)
    assert 2 * Duration(1, 250_000_000) == Duration(2, 500_000_000)
    assert Duration(3) * 0.5 == Duration(1, 500_000_000)
    assert Duration(3) / 2 == Duration(1, 500_000_000)
    assert Duration(3) // 2 == Duration(1)
    assert Duration(3) / Duration(2) == 1.5
    assert Duration(7) // Duration(2) == 3
    assert Duration(7) % Duration(2) == Duration(1)
    assert divmod(Duration(7), Duration(2)) == (3, Duration(1))
    assert -Duration(1, 5) == Duration(-2, 999_999_995)
    assert abs(Duration(-2, 999_999_995)) == Duration(1, 5)
    positive = Duration(4)
    assert abs(positive) is positive


def test_comparisons_stay_within_a_kind() -> None:
    assert Time(1) < Time(1, 1) <= Time(1, 1) < Time(2)
    assert Duration(-1) < Duration(0) and Duration(2) >= Duration(2)
    assert Time(1) != Duration(1)
    assert (Time(1) == Duration(1)) is False
    assert Time(1) != 1
    with pytest.raises(TypeError):
        _ = Time(1) < Duration(2)
    with pytest.raises(TypeError):
        _ = Duration(1) < 3


def test_truth_hash_and_texts() -> None:
    assert not Time() and Time(0, 1) and Duration(-1)
    assert hash(Time(1, 2)) == hash(Time(1, 2)) == hash((1, 2))
    assert len({Time(1, 2), Time(1, 2), Time(2)}) == 2
    assert str(Time(1, 5)) == "1000000005"
    assert repr(Time(1, 5)) == "genpy.Time[1000000005]"
    assert repr(Duration(-1, 999_999_999)) == "genpy.Duration[-1]"
    assert str(Duration(-2)) == "-2000000000"
    assert Time._slot_types == ["int32", "int32"]
    assert isinstance(Time(), TVal) and isinstance(Duration(), TVal)


def test_pickle_and_copy() -> None:
    for value in (Time(3, 4), Duration(-3, 4)):
        assert pickle.loads(pickle.dumps(value)) == value
        assert copy.deepcopy(value) == value and copy.copy(value) is not value
    assert Time(1, 2).__getstate__() == [1, 2]


# -- against genpy --------------------------------------------------------------------------

_EXPRESSIONS = [
    "Time(1, 1500000000)",
    "Duration(0, -1500000000)",
    "Duration(-1.25)",
    "Time(2.000000001)",
    "Time.from_sec(1700000000.123456)",
    "Duration.from_sec(-3.7)",
    "Time(5) - Time(3, 500000000)",
    "Time(5, 0) + Duration(1, 600000000)",
    "Duration(1) + Time(5)",
    "Duration(1, 500000000) * 3",
    "Duration(3) * 0.3",
    "Duration(3) / 7",
    "Duration(3) // 2",
    "Duration(-3) // 2",
    "Duration(7) / Duration(2)",
    "Duration(7) // Duration(2)",
    "Duration(7) % Duration(3)",
    "divmod(Duration(7), Duration(2))",
    "-Duration(1, 5)",
    "abs(Duration(-2, 999999995))",
    "Time(1) < Time(1, 1)",
    "Time(1) == Duration(1)",
    "bool(Duration())",
    "str(Duration(-2, 5))",
    "Time(3, 7).to_sec()",
    "Duration(-3, 7).to_nsec()",
]

_EVALUATE = """
import json, sys
{imports}
print(json.dumps([repr(eval(e)) for e in json.loads(sys.argv[1])]))
"""


@pytest.mark.skipif(not _genpy_available(), reason="genpy (Debian's /usr/bin/python3) not found")
def test_same_results_as_genpy() -> None:
    ours = [repr(eval(expression)) for expression in _EXPRESSIONS]
    script = _EVALUATE.format(imports="from genpy import Time, Duration")
    result = subprocess.run(
        [str(ROS1_PYTHON), "-c", script, json.dumps(_EXPRESSIONS)],
        capture_output=True,
        text=True,
        check=True,
    )
    theirs = json.loads(result.stdout)
    assert dict(zip(_EXPRESSIONS, ours, strict=True)) == dict(
        zip(_EXPRESSIONS, theirs, strict=True)
    )
