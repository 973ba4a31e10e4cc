"""ROS 1's ``time`` and ``duration`` primitives as Python values: `Time` and `Duration`.

They behave as genpy's (the classes rospy re-exports): two integer slots ``secs`` and ``nsecs``,
kept canonical (``0 <= nsecs < 10**9``, the overflow carried into ``secs``); construction from
integers or from float seconds; arithmetic ``Time - Time = Duration``, ``Time ± Duration = Time``,
``Duration ± Duration``, ``Duration * number``, ``Duration / number`` and ``//``; ordering only
within one kind; ``str`` giving nanoseconds and ``repr`` giving ``genpy.Time[…]``. A `Time` is
never negative. Reading the clock (``Time.now()``) belongs to the node layer, not here.
"""

from __future__ import annotations

import numbers
from typing import Any, ClassVar, TypeVar

_NSEC_PER_SEC = 1_000_000_000

_T = TypeVar("_T", bound="TVal")
_D = TypeVar("_D", bound="Duration")


def _canon(secs: int, nsecs: int) -> tuple[int, int]:
    carry = nsecs // _NSEC_PER_SEC
    return secs + carry, nsecs - carry * _NSEC_PER_SEC


class TVal:
    """What `Time` and `Duration` share: seconds plus nanoseconds, canonical after construction."""

    __slots__ = ("nsecs", "secs")

    #: Mirrors a message's ``_slot_types`` so that introspection treats both alike.
    _slot_types: ClassVar[list[str]] = ["int32", "int32"]

    def __init__(self, secs: float = 0, nsecs: float = 0) -> None:
        if type(secs) is int and type(nsecs) is int:  # the common case, without an ABC check
            whole, nanos = secs, nsecs
        elif isinstance(secs, numbers.Integral):
            whole, nanos = int(secs), int(nsecs)
        else:
            if nsecs != 0:
                raise ValueError("if secs is a float, nsecs cannot be set")
            whole = int(secs)
            nanos = int((secs - whole) * _NSEC_PER_SEC)
        self.secs, self.nsecs = _canon(whole, nanos)

    @classmethod
    def from_sec(cls: type[_T], float_secs: float) -> _T:
        """The value of ``float_secs`` seconds (``time.time()`` style), to the nanosecond."""
        secs = int(float_secs)
        return cls(secs, int((float_secs - secs) * _NSEC_PER_SEC))

    @classmethod
    def from_nsec(cls: type[_T], nsec: int) -> _T:
        """The value of ``nsec`` nanoseconds."""
        return cls(0, int(nsec))

    def set(self, secs: int, nsecs: int) -> None:
        """Set both fields as given, without canonicalising them."""
        self.secs = secs
        self.nsecs = nsecs

    def canon(self) -> None:
        """Bring fields set by hand (or read off the wire) back to canonical form."""
        self.secs, self.nsecs = _canon(self.secs, self.nsecs)

    def is_zero(self) -> bool:
        """Whether both ``secs`` and ``nsecs`` are zero (rospy's "time not set")."""
        return self.secs == 0 and self.nsecs == 0

    def to_sec(self) -> float:
        """The value in seconds, as a float (digits below about a microsecond are lost for wall
        times)."""
        return float(self.secs) + float(self.nsecs) / 1e9

    def to_nsec(self) -> int:
        """The value in nanoseconds, as an exact integer."""
        return self.secs * _NSEC_PER_SEC + self.nsecs

    def __bool__(self) -> bool:
        return self.secs != 0 or self.nsecs != 0

    def __str__(self) -> str:
        return str(self.to_nsec())

    def __repr__(self) -> str:
        return f"genpy.TVal[{self.to_nsec()}]"

    def __hash__(self) -> int:
        return hash((self.secs, self.nsecs))

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, TVal):
            return False
        return self.to_nsec() == other.to_nsec()

    def __ne__(self, other: object) -> bool:
        return not self.__eq__(other)

    # Ordering is defined within one kind only: a Time is never less than a Duration.
    def _comparable(self, other: object) -> bool:
        return isinstance(other, TVal)

    def __lt__(self, other: object) -> bool:
        if not self._comparable(other):
            return NotImplemented
        assert isinstance(other, TVal)
        return self.to_nsec() < other.to_nsec()

    def __le__(self, other: object) -> bool:
        if not self._comparable(other):
            return NotImplemented
        assert isinstance(other, TVal)
        return self.to_nsec() <= other.to_nsec()

    def __gt__(self, other: object) -> bool:
        if not self._comparable(other):
            return NotImplemented
        assert isinstance(other, TVal)
        return self.to_nsec() > other.to_nsec()

    def __ge__(self, other: object) -> bool:
        if not self._comparable(other):
            return NotImplemented
        assert isinstance(other, TVal)
        return self.to_nsec() >= other.to_nsec()

    def __getstate__(self) -> list[int]:
        return [self.secs, self.nsecs]

    def __setstate__(self, state: list[int]) -> None:
        self.secs, self.nsecs = state


class Time(TVal):
    """A point in time: seconds and nanoseconds since the epoch (ROS 1 ``time``)."""

    __slots__ = ()

    def __init__(self, secs: float = 0, nsecs: float = 0) -> None:
        super().__init__(secs, nsecs)
        if self.secs < 0:
            raise TypeError("time values must be positive")

    def to_time(self) -> float:
        """The time as float seconds; another name for `to_sec`."""
        return self.to_sec()

    def __repr__(self) -> str:
        return f"genpy.Time[{self.to_nsec()}]"

    def __hash__(self) -> int:
        return hash((self.secs, self.nsecs))

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Time):
            return False
        return self.secs == other.secs and self.nsecs == other.nsecs

    def _comparable(self, other: object) -> bool:
        return isinstance(other, Time)

    def __add__(self: _T, other: object) -> _T:
        if not isinstance(other, Duration):
            return NotImplemented
        return type(self)(self.secs + other.secs, self.nsecs + other.nsecs)

    __radd__ = __add__

    def __sub__(self, other: object) -> Any:
        if isinstance(other, Time):
            return Duration(self.secs - other.secs, self.nsecs - other.nsecs)
        if isinstance(other, Duration):
            return type(self)(self.secs - other.secs, self.nsecs - other.nsecs)
        return NotImplemented


class Duration(TVal):
    """A span of time in seconds and nanoseconds, possibly negative (ROS 1 ``duration``)."""

    __slots__ = ()

    def __repr__(self) -> str:
        return f"genpy.Duration[{self.to_nsec()}]"

    def __hash__(self) -> int:
        return hash((self.secs, self.nsecs))

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Duration):
            return False
        return self.secs == other.secs and self.nsecs == other.nsecs

    def _comparable(self, other: object) -> bool:
        return isinstance(other, Duration)

    def __neg__(self: _D) -> _D:
        return type(self)(-self.secs, -self.nsecs)

    def __abs__(self: _D) -> _D:
        # As genpy: a non-negative duration is returned as is, not copied.
        return self if self.secs >= 0 else -self

    def __add__(self: _D, other: object) -> _D:
        if not isinstance(other, Duration):
            return NotImplemented
        return type(self)(self.secs + other.secs, self.nsecs + other.nsecs)

    __radd__ = __add__

    def __sub__(self: _D, other: object) -> _D:
        if not isinstance(other, Duration):
            return NotImplemented
        return type(self)(self.secs - other.secs, self.nsecs - other.nsecs)

    def __mul__(self: _D, val: object) -> _D:
        if isinstance(val, numbers.Integral):
            return type(self)(self.secs * int(val), self.nsecs * int(val))
        if isinstance(val, numbers.Real):
            return type(self).from_sec(self.to_sec() * float(val))
        return NotImplemented

    __rmul__ = __mul__

    def __floordiv__(self, val: object) -> Any:
        if isinstance(val, numbers.Real):
            return type(self).from_sec(self.to_sec() // float(val))
        if isinstance(val, Duration):
            return int(self.to_sec() // val.to_sec())
        return NotImplemented

    def __truediv__(self, val: object) -> Any:
        if isinstance(val, numbers.Real):
            return type(self).from_sec(self.to_sec() / float(val))
        if isinstance(val, Duration):
            return self.to_sec() / val.to_sec()
        return NotImplemented

    def __mod__(self: _D, val: object) -> _D:
        if isinstance(val, Duration):
            return type(self).from_sec(self.to_sec() % val.to_sec())
        return NotImplemented

    def __divmod__(self: _D, val: object) -> tuple[int, _D]:
        if isinstance(val, Duration):
            quotient, remainder = divmod(self.to_sec(), val.to_sec())
            return int(quotient), type(self).from_sec(remainder)
        return NotImplemented


__all__ = ["Duration", "TVal", "Time"]
