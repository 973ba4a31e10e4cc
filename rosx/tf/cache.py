"""The per-frame caches of tf2's buffer: a frame's transforms to its parent over time.

A `TimeCache` keeps the transforms of a moving frame for ``max_storage`` nanoseconds behind the
newest, sorted by stamp (``bisect`` finds the two around a time); a `StaticCache` keeps one
transform valid at every time. Both answer as tf2's ``TimeCache``/``StaticCache`` do, texts
included: a time outside the buffered span is an extrapolation, described in tf2's words; an
insertion older than the span or at a stamp already held is refused with tf2's
``TF_OLD_DATA``/``TF_REPEATED_DATA`` text.

A sample is a tuple ``(parent_id, tx, ty, tz, qx, qy, qz, qw)``; interpolation between two
samples is tf2's (linear translation, slerp rotation, the same operations in the same order),
so the numbers are ROS 1's to the last bit. What tf2's slerp computes from the two samples
alone (the angle between them, ``1 / sin`` of it, which way round) does not depend on the time
asked, so a `TimeCache` computes it once for each two neighbours, as their `Span`, the first
time a lookup falls between them (most never are: a listener stores thousands a second, and
most lookups ask the latest time). A lookup at a past time then costs a bisection, two sines
and a few products per frame (`rosx.tf.core`'s ``_climb``). Nothing here locks or does I/O:
the buffer (`rosx.tf.core`) does the locking.
"""

from __future__ import annotations

from bisect import bisect_right
from math import acos, sin, sqrt
from typing import Any

from rosx.tf import stamps
from rosx.tf.stamps import SECOND

#: (parent_id, tx, ty, tz, qx, qy, qz, qw)
Sample = tuple[int, float, float, float, float, float, float, float]

_OLD_DATA = (
    "TF_OLD_DATA ignoring data from the past (Possible reasons are listed at "
    "http://wiki.ros.org/tf/Errors%%20explained)"
)
_REPEATED_DATA = "TF_REPEATED_DATA ignoring data with redundant timestamp"


def _only_time(asked: int, held: int) -> str:
    # tf2 0.7.6 formats this one into 116 bytes: the longest stamps lose the text's last letter.
    return (
        f"Lookup would require extrapolation at time {stamps.text(asked)}, "
        f"but only time {stamps.text(held)} is in the buffer"
    )[:115]


def _future(asked: int, latest: int) -> str:
    return (
        f"Lookup would require extrapolation {stamps.text(asked - latest)}s into the future.  "
        f"Requested time {stamps.text(asked)} but the latest data is at time "
        f"{stamps.text(latest)}"
    )[:162]


def _past(asked: int, earliest: int) -> str:
    return (
        f"Lookup would require extrapolation {stamps.text(earliest - asked)}s into the past.  "
        f"Requested time {stamps.text(asked)} but the earliest data is at time "
        f"{stamps.text(earliest)}"
    )[:162]


#: What interpolating between two neighbouring samples needs besides the time, as tf2 computes
#: it: ``(t1, seconds, theta, d, ax, ay, az, bx, by, bz, x1, y1, z1, w1, x2, y2, z2, w2)``, the
#: older stamp, the span's ``Duration::toSec()`` (tf2 divides by it), tf2's half angle between
#: the two rotations (0.0: no slerp, the older rotation), ``d = 1 / sin(theta)``, the two
#: translations and the two rotations, the newer one negated where tf2 goes the short way round
#: (``-q2``: a negation is exact). None where the two have different parents: tf2 does not
#: interpolate there, the older sample is the answer.
Span = tuple[
    int, float, float, float, float, float, float, float, float, float,
    float, float, float, float, float, float, float, float,
]  # fmt: skip


#: A `Span` not computed yet (`TimeCache.spans`).
LATER: tuple[()] = ()


def span(t1: int, one: Sample, t2: int, two: Sample) -> Span | None:
    """The `Span` from ``one`` (at ``t1``) to ``two`` (at ``t2``, later)."""
    if one[0] != two[0]:
        return None
    _, ax, ay, az, x1, y1, z1, w1 = one
    _, bx, by, bz, x2, y2, z2, w2 = two
    # Quaternion::slerp, through angleShortestPath
    dot = x1 * x2 + y1 * y2 + z1 * z2 + w1 * w2
    norm = sqrt((x1 * x1 + y1 * y1 + z1 * z1 + w1 * w1) * (x2 * x2 + y2 * y2 + z2 * z2 + w2 * w2))
    # tf2 doubles the angle and halves it again, both exact; dot(-q) is exactly -dot(q);
    # tf2Acos clamps its argument to [-1, 1].
    cosine = -dot / norm if dot < 0 else dot / norm
    theta = acos(cosine) if cosine < 1.0 else 0.0
    d = 1.0 / sin(theta) if theta != 0.0 else 0.0
    if dot < 0:
        x2, y2, z2, w2 = -x2, -y2, -z2, -w2
    # Duration::toSec() of the span, as tf2 divides by it
    seconds = stamps.to_sec(t2 - t1)
    return (t1, seconds, theta, d, ax, ay, az, bx, by, bz, x1, y1, z1, w1, x2, y2, z2, w2)


def fill(stamps_: list[int], samples: list[Sample], spans: list[Any], i: int) -> Span | None:
    """``spans[i]``, computed now if it was `LATER`."""
    at = spans[i] = span(stamps_[i], samples[i], stamps_[i + 1], samples[i + 1])
    return at


def interpolate(one: Sample, at: Span, time: int) -> Sample:
    """tf2's ``TimeCache::interpolate`` at ``time``, from ``one`` (the older sample) along its
    `Span` ``at`` to the newer."""
    t1, seconds, theta, d, ax, ay, az, bx, by, bz, x1, y1, z1, w1, x2, y2, z2, w2 = at
    into = time - t1
    # Duration::toSec(): seconds + 1e-9 * nanoseconds, the first 0.0 within a second
    ratio = (1e-9 * into if into < SECOND else stamps.to_sec(into)) / seconds
    s = 1.0 - ratio
    if theta != 0.0:
        s0 = sin(s * theta)
        s1 = sin(ratio * theta)
        qx = (x1 * s0 + x2 * s1) * d
        qy = (y1 * s0 + y2 * s1) * d
        qz = (z1 * s0 + z2 * s1) * d
        qw = (w1 * s0 + w2 * s1) * d
    else:
        qx, qy, qz, qw = x1, y1, z1, w1
    return (one[0], s * ax + ratio * bx, s * ay + ratio * by, s * az + ratio * bz, qx, qy, qz, qw)


class TimeCache:
    """The transforms of one moving frame, ``max_storage`` ns behind the newest.

    ``stamps``, ``samples`` and ``spans`` are changed in place, never replaced: the buffer keeps
    them in its chains (`rosx.tf.core`) from one insertion to the next.
    """

    __slots__ = ("answer", "asked", "max_storage", "parent", "samples", "spans", "stamps")

    def __init__(self, max_storage: int) -> None:
        self.max_storage = max_storage
        #: Stamps in ns, oldest first; ``samples[i]`` is the transform at ``stamps[i]``.
        self.stamps: list[int] = []
        self.samples: list[Sample] = []
        #: ``spans[i]``: from ``samples[i]`` to ``samples[i + 1]`` (`span`), `LATER` until
        #: a lookup needs it (`fill`).
        self.spans: list[Span | tuple[()] | None] = []
        #: The parent of every sample held: 0 when none is, -1 when they differ.
        self.parent = 0
        #: The last time `get` was asked for and its answer, until the next insertion: the
        #: frames of a tree are usually looked up many times at one time.
        self.asked = -1
        self.answer: Sample | str = ""

    def get(self, time: int) -> Sample | str:
        """The transform at ``time`` (0: the newest), or tf2's text of why there is none."""
        if time == self.asked:
            return self.answer
        answer = self._get(time)
        self.asked = time
        self.answer = answer
        return answer

    def _get(self, time: int) -> Sample | str:
        stamps_ = self.stamps
        count = len(stamps_)
        if not count:
            return ""
        if not time:
            return self.samples[-1]
        if count == 1:
            if stamps_[0] == time:
                return self.samples[0]
            return _only_time(time, stamps_[0])
        latest = stamps_[-1]
        if time == latest:
            return self.samples[-1]
        earliest = stamps_[0]
        if time == earliest:
            return self.samples[0]
        if time > latest:
            return _future(time, latest)
        if time < earliest:
            return _past(time, earliest)
        i = bisect_right(stamps_, time) - 1
        at = self.spans[i]
        if at is LATER:
            at = fill(stamps_, self.samples, self.spans, i)
        if at is None:
            return self.samples[i]
        return interpolate(self.samples[i], at, time)  # type: ignore[arg-type]

    def parent_at(self, time: int) -> int | str:
        """The parent frame's id at ``time``, or tf2's text of why there is none."""
        stamps_ = self.stamps
        count = len(stamps_)
        if not count:
            return ""
        if not time:
            return self.samples[-1][0]
        if count == 1:
            return self.samples[0][0] if stamps_[0] == time else _only_time(time, stamps_[0])
        latest = stamps_[-1]
        earliest = stamps_[0]
        if time == latest:
            return self.samples[-1][0]
        if time == earliest:
            return self.samples[0][0]
        if time > latest:
            return _future(time, latest)
        if time < earliest:
            return _past(time, earliest)
        return self.samples[bisect_right(stamps_, time) - 1][0]

    def insert(self, stamp: int, sample: Sample) -> str | None:
        """Keep ``sample`` (at ``stamp``) and drop what fell out of the span; or refuse it, with
        tf2's text."""
        self.asked = -1
        stamps_ = self.stamps
        samples = self.samples
        spans = self.spans
        if stamps_:
            latest = stamps_[-1]
            if latest > stamp + self.max_storage:
                return _OLD_DATA
            if stamp > latest:
                spans.append(LATER)
                stamps_.append(stamp)
                samples.append(sample)
            else:
                i = bisect_right(stamps_, stamp)
                if i and stamps_[i - 1] == stamp:
                    return _REPEATED_DATA
                if i:
                    spans[i - 1 : i] = [LATER, LATER]
                else:
                    spans.insert(0, LATER)
                stamps_.insert(i, stamp)
                samples.insert(i, sample)
            if sample[0] != self.parent:
                self.parent = -1
        else:
            stamps_.append(stamp)
            samples.append(sample)
            self.parent = sample[0]
        latest = stamps_[-1] - self.max_storage
        if stamps_[0] < latest:
            drop = 1
            while drop < len(stamps_) and stamps_[drop] < latest:
                drop += 1
            del stamps_[:drop]
            del samples[:drop]
            del spans[:drop]
            if self.parent == -1:  # the other parent's samples may all be gone
                first = samples[0][0]
                if all(held[0] == first for held in samples):
                    self.parent = first
        return None

    def latest(self) -> tuple[int, int]:
        """The newest stamp and the parent then; ``(0, 0)`` when empty."""
        if not self.stamps:
            return 0, 0
        return self.stamps[-1], self.samples[-1][0]

    def newest_stamp(self) -> int:
        """The newest stamp held (ns), or 0 when empty."""
        return self.stamps[-1] if self.stamps else 0

    def oldest_stamp(self) -> int:
        """The oldest stamp held (ns), or 0 when empty."""
        return self.stamps[0] if self.stamps else 0

    def __len__(self) -> int:
        return len(self.stamps)

    def clear(self) -> None:
        """Forget every transform (the buffer's ``clear``, e.g. when ROS time jumps back)."""
        self.asked = -1
        self.parent = 0
        self.stamps.clear()
        self.samples.clear()
        self.spans.clear()


class StaticCache:
    """The one transform of a static frame, the same at every time (its stamp reads 0)."""

    __slots__ = ("parent", "sample")

    def __init__(self) -> None:
        self.sample: Sample = (0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)
        #: The sample's parent, as `TimeCache.parent`.
        self.parent = 0

    def get(self, time: int) -> Sample | str:
        """The static transform, whatever ``time`` is asked for."""
        return self.sample

    def parent_at(self, time: int) -> int | str:
        """The static transform's parent frame id, at any time."""
        return self.sample[0]

    def insert(self, stamp: int, sample: Sample) -> str | None:
        """Replace the transform (a static frame keeps only its last); never refused."""
        self.sample = sample
        self.parent = sample[0]
        return None

    def latest(self) -> tuple[int, int]:
        """``(0, parent)``: a static transform's stamp reads 0."""
        return 0, self.sample[0]

    def newest_stamp(self) -> int:
        """Always 0: a static transform holds at every time."""
        return 0

    def oldest_stamp(self) -> int:
        """Always 0: a static transform holds at every time."""
        return 0

    def __len__(self) -> int:
        return 1

    def clear(self) -> None:
        """Static transforms outlive a clear, as in tf2."""


Cache = TimeCache | StaticCache

__all__ = [
    "LATER",
    "Cache",
    "Sample",
    "Span",
    "StaticCache",
    "TimeCache",
    "fill",
    "interpolate",
    "span",
]
