"""tf2's buffer core: frames, their caches, and the search between two frames.

`BufferCore` is what ROS 1's C++ ``tf2::BufferCore`` is to ``tf2_ros``: it stores transforms
(``set``), finds the chain between two frames at a time and composes it (``lookup``), says
whether it could (``can``), and describes the tree (``frames_as_yaml``, ``frames_as_string``,
``frames_as_dot``). It has no I/O, clock or ROS: times are integer nanoseconds
(`rosx.tf.stamps`), transforms are tuples ``(tx, ty, tz, qx, qy, qz, qw)``, and failures are
ROS 1's exceptions with ROS 1's texts. Listeners, broadcasters and waits live above it
(`rosx.tf.buffer`).

The search is tf2's ``walkToTopParent``: from the source up to the root, then from the target
up to where the first walk ended, accumulating each side's transform; the two meet at their
common ancestor. The arithmetic is tf2's LinearMath in the same order, so a lookup gives ROS
1's numbers bit for bit (and ``tf_echo``'s ``-0.000`` where ROS 1 prints one). A lookup at
time 0 uses the latest time all frames on the way share (``getLatestCommonTime``).

Two ways make the same walk cheaper. At one time asked again (time 0, or the same stamp for
every frame of a view), each frame's walk to the root is kept until the buffer changes
(`_remembered`). At a new time each call (a message's stamp), the frames tf2's walk would
visit are known beforehand wherever every frame on the way has had one parent over the whole
buffer: the `_Plan` of the pair, kept until a parent changes, holds their transforms' lists,
and `_climb` does each step's interpolation (from the `Span` of the two samples around the
time, which the cache computes once) and accumulation in tf2's operations, with no call per
step; above the frame where the two walks meet, each step is interpolated once for both.
Where a frame on the way has no transform at that time, or the tree is not so simple, `_walk`
answers, with tf2's texts and its ways around a missing frame.

Threads: every public method takes the core's lock, so a listener's thread may insert while
others look up. `add_listener` callbacks run after each insertion, outside the lock.
"""

from __future__ import annotations

import threading
from bisect import bisect_right
from math import isnan, sin
from typing import TYPE_CHECKING, Any

from rosx.tf import stamps
from rosx.tf.cache import LATER, StaticCache, TimeCache, fill
from rosx.tf.exceptions import (
    ConnectivityException,
    ExtrapolationException,
    InvalidArgumentException,
    LookupException,
)
from rosx.tf.stamps import SECOND

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx.tf.cache import Cache, Sample, Span

#: (tx, ty, tz, qx, qy, qz, qw)
Transform = tuple[float, float, float, float, float, float, float]
IDENTITY: Transform = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)
#: One frame's transforms as `_climb` reads them: a `TimeCache`'s ``(stamps, samples, spans)``
#: lists (changed in place by insertions), or a static frame's ``(None, sample, None)``.
_Link = tuple["list[int] | None", Any, Any]
#: How tf2's walk goes between two frames (`BufferCore._plan`): ``(_UP, the source's links up
#: to the target, the target's own, [])``, ``(_DOWN, the target's links up to the source, the
#: source's links to its root, [])`` or ``(_FULL, the source's links up to where the two
#: walks meet, the target's, the links from there to the root)``. The second list of the
#: first two is only read for whether it holds the time, as tf2 does.
_Plan = tuple[int, list[_Link], list[_Link], list[_Link]]
_UP = 0
_DOWN = 1
_FULL = 2

#: tf2's default cache length, in ns (``BufferCore::DEFAULT_CACHE_TIME``: 10 s).
DEFAULT_CACHE_TIME = 10 * stamps.SECOND
#: tf2's ``MAX_GRAPH_DEPTH``: a walk longer than this is a loop.
MAX_GRAPH_DEPTH = 1000
_NORMALIZATION_TOLERANCE = 10e-3
#: How many times' walks to the root `BufferCore._walk_up` keeps between two insertions.
_KEPT_TIMES = 16

# tf2_msgs/TF2Error codes, as walkToTopParent returns them.
NO_ERROR = 0
LOOKUP_ERROR = 1
CONNECTIVITY_ERROR = 2
EXTRAPOLATION_ERROR = 3

_RAISE = {
    LOOKUP_ERROR: LookupException,
    CONNECTIVITY_ERROR: ConnectivityException,
    EXTRAPOLATION_ERROR: ExtrapolationException,
}


def _strip_slash(frame: str) -> str:
    return frame[1:] if frame.startswith("/") else frame


def _rotate(
    qx: float, qy: float, qz: float, qw: float, vx: float, vy: float, vz: float
) -> tuple[float, float, float]:
    """tf2's ``quatRotate``: ``q * v * q⁻¹`` as two quaternion products."""
    x = qw * vx + qy * vz - qz * vy
    y = qw * vy + qz * vx - qx * vz
    z = qw * vz + qx * vy - qy * vx
    w = -qx * vx - qy * vy - qz * vz
    ix, iy, iz = -qx, -qy, -qz
    return (
        w * ix + x * qw + y * iz - z * iy,
        w * iy + y * qw + z * ix - x * iz,
        w * iz + z * qw + x * iy - y * ix,
    )


def _inverse(target: Transform) -> tuple[float, float, float, float, float, float, float]:
    """The inverse of the target side's transform, as tf2's ``finalize`` computes it."""
    tx, ty, tz, qx, qy, qz, qw = target
    ix, iy, iz = -qx, -qy, -qz
    vx, vy, vz = _rotate(ix, iy, iz, qw, -tx, -ty, -tz)
    return (vx, vy, vz, ix, iy, iz, qw)


def _full_path(source: Transform, target: Transform) -> Transform:
    """tf2's ``finalize(FullPath)``: the target side's inverse after the source side."""
    vx, vy, vz, ix, iy, iz, qw = _inverse(target)
    sx, sy, sz, sqx, sqy, sqz, sqw = source
    rx, ry, rz = _rotate(ix, iy, iz, qw, sx, sy, sz)
    return (
        rx + vx,
        ry + vy,
        rz + vz,
        qw * sqx + ix * sqw + iy * sqz - iz * sqy,
        qw * sqy + iy * sqw + iz * sqx - ix * sqz,
        qw * sqz + iz * sqw + ix * sqy - iy * sqx,
        qw * sqw - ix * sqx - iy * sqy - iz * sqz,
    )


def _accumulate(acc: Transform, st: Sample) -> Transform:
    """tf2's ``TransformAccum::accum``: the step ``st`` (child to parent) after ``acc``."""
    _, tx, ty, tz, qx, qy, qz, qw = st
    ax, ay, az, bx, by, bz, bw = acc
    rx, ry, rz = _rotate(qx, qy, qz, qw, ax, ay, az)
    return (
        rx + tx,
        ry + ty,
        rz + tz,
        qw * bx + qx * bw + qy * bz - qz * by,
        qw * by + qy * bw + qz * bx - qx * bz,
        qw * bz + qz * bw + qx * by - qy * bx,
        qw * bw - qx * bx - qy * by - qz * bz,
    )


def _holds(links: list[_Link], time: int) -> bool:
    """Whether every link has a transform at ``time`` (a given time, not 0)."""
    for stamps_, _, _ in links:
        if stamps_ is not None and not (stamps_ and stamps_[0] <= time <= stamps_[-1]):
            return False
    return True


def _edge(
    stamps_: list[int], held: list[Sample], spans: Any, time: int, i: int
) -> Sample | Span | None:
    """What `_climb` reads at ``time`` where the bisection gave ``i`` at either end of a
    cache, as `TimeCache.get` answers there: the newest or oldest sample itself at their
    stamps, the first `Span` just after the oldest, None outside."""
    count = len(stamps_)
    if i == count:
        return held[-1] if count and stamps_[-1] == time else None
    if not i:
        return None
    return held[0] if stamps_[0] == time else spans[0]


def _climb(
    links: list[_Link], time: int, one: Transform, two: Transform | None = None
) -> tuple[Transform, Transform | None] | None:
    """tf2's accumulation up ``links`` at ``time`` (a given time, not 0) after ``one``, and
    after ``two`` too where given (the part above where two walks meet: each step found
    once): each step's transform as `TimeCache.get` interpolates it, then ``accum()``, both in
    tf2's operations and order (a negation moved into a subtraction is exact); None where a
    link has no transform at ``time`` (the caller asks `BufferCore._walk`)."""
    ax, ay, az, bx, by, bz, bw = one
    cx, cy, cz, dx, dy, dz, dw = IDENTITY if two is None else two
    for stamps_, held, spans in links:
        if stamps_ is None:  # static
            _, tx, ty, tz, qx, qy, qz, qw = held
        else:
            i = bisect_right(stamps_, time)
            at: Any = spans[i - 1] if 1 < i < len(stamps_) else _edge(stamps_, held, spans, time, i)
            if at is LATER:  # computed once, the first time a lookup falls there
                at = fill(stamps_, held, spans, i - 1)
            if at is None:
                return None
            if len(at) == 8:  # a sample as it is
                _, tx, ty, tz, qx, qy, qz, qw = at
            else:  # cache.interpolate, inline
                t1, sec, th, d, px, py, pz, nx, ny, nz, x1, y1, z1, w1, x2, y2, z2, w2 = at
                into = time - t1
                ratio = (1e-9 * into if into < SECOND else stamps.to_sec(into)) / sec
                s = 1.0 - ratio
                tx = s * px + ratio * nx
                ty = s * py + ratio * ny
                tz = s * pz + ratio * nz
                if th != 0.0:
                    s0 = sin(s * th)
                    s1 = sin(ratio * th)
                    qx = (x1 * s0 + x2 * s1) * d
                    qy = (y1 * s0 + y2 * s1) * d
                    qz = (z1 * s0 + z2 * s1) * d
                    qw = (w1 * s0 + w2 * s1) * d
                else:
                    qx, qy, qz, qw = x1, y1, z1, w1
        # tf2's accum(): quatRotate(step, acc) + translation; step's rotation * acc's
        nqx = -qx
        x = qw * ax + qy * az - qz * ay
        y = qw * ay + qz * ax - qx * az
        z = qw * az + qx * ay - qy * ax
        w = nqx * ax - qy * ay - qz * az
        ax, ay, az, bx, by, bz, bw = (
            w * nqx + x * qw - y * qz + z * qy + tx,
            w * -qy + y * qw - z * qx + x * qz + ty,
            w * -qz + z * qw - x * qy + y * qx + tz,
            qw * bx + qx * bw + qy * bz - qz * by,
            qw * by + qy * bw + qz * bx - qx * bz,
            qw * bz + qz * bw + qx * by - qy * bx,
            qw * bw - qx * bx - qy * by - qz * bz,
        )
        if two is not None:  # the same for the other walk
            x = qw * cx + qy * cz - qz * cy
            y = qw * cy + qz * cx - qx * cz
            z = qw * cz + qx * cy - qy * cx
            w = nqx * cx - qy * cy - qz * cz
            cx, cy, cz, dx, dy, dz, dw = (
                w * nqx + x * qw - y * qz + z * qy + tx,
                w * -qy + y * qw - z * qx + x * qz + ty,
                w * -qz + z * qw - x * qy + y * qx + tz,
                qw * dx + qx * dw + qy * dz - qz * dy,
                qw * dy + qy * dw + qz * dx - qx * dz,
                qw * dz + qz * dw + qx * dy - qy * dx,
                qw * dw - qx * dx - qy * dy - qz * dz,
            )
    return (ax, ay, az, bx, by, bz, bw), (None if two is None else (cx, cy, cz, dx, dy, dz, dw))


def _follow(plan: _Plan, time: int) -> Transform | None:
    """`lookup`'s answer at a given ``time`` along ``plan``, as tf2's walk composes it; None
    where a frame on the way has no transform then."""
    kind, first, second, above = plan
    if kind == _FULL:
        source = _climb(first, time, IDENTITY)
        if source is None:
            return None
        target = _climb(second, time, IDENTITY)
        if target is None:
            return None
        both = _climb(above, time, source[0], target[0])
        return None if both is None else _full_path(both[0], both[1])  # type: ignore[arg-type]
    if not _holds(second, time):
        return None
    climbed = _climb(first, time, IDENTITY)
    if climbed is None:
        return None
    return climbed[0] if kind == _UP else _inverse(climbed[0])


class BufferCore:
    """Transforms between frames over time: tf2's ``BufferCore`` (see the module docstring).

    Args:
        cache_time: how long each moving frame's transforms are kept, in ns (10 s).
        report: called with ``("Warning" | "Error", text)`` for each transform refused, with
            tf2's text (``TF_REPEATED_DATA …``); None keeps quiet.
    """

    def __init__(
        self,
        cache_time: int = DEFAULT_CACHE_TIME,
        report: Callable[[str, str], object] | None = None,
    ) -> None:
        self.cache_time = cache_time
        self.report = report
        self._lock = threading.RLock()
        #: Frame names by id; id 0 is tf2's ``NO_PARENT``.
        self._names: list[str] = ["NO_PARENT"]
        self._ids: dict[str, int] = {"NO_PARENT": 0}
        self._caches: list[Cache | None] = [None]
        self._authority: dict[int, str] = {}
        self._listeners: list[Callable[[], object]] = []
        #: Counts insertions, so that waiters and views know something changed.
        self.version = 0
        #: Walks to the root by time and frame (`_walk_up`), and latest common times, valid while
        #: `version` is unchanged.
        self._walks: dict[int, dict[int, Any]] = {}
        self._common: dict[tuple[int, int], tuple[int, int, str]] = {}
        self._walks_version = 0
        #: The last time given to `lookup`: asked again, the walks are kept (`_remembered`).
        self._given = -1
        #: `_Plan` by (target id, source id), None where `_walk` goes; emptied when a frame's
        #: parents change.
        self._plans: dict[tuple[int, int], _Plan | None] = {}

    # -- storing -----------------------------------------------------------------------------

    def set(
        self,
        parent: str,
        child: str,
        stamp: int,
        transform: Transform,
        authority: str = "default_authority",
        is_static: bool = False,
    ) -> bool:
        """Store the transform from ``child`` to ``parent`` at ``stamp`` (ns); tf2's
        ``setTransform``. False (and the reason reported) when tf2 refuses it."""
        parent = _strip_slash(parent)
        child = _strip_slash(child)
        errors: list[str] = []
        if child == parent:
            errors.append(
                f'TF_SELF_TRANSFORM: Ignoring transform from authority "{authority}" with '
                f'frame_id and child_frame_id  "{child}" because they are the same'
            )
        if not child:
            errors.append(
                f'TF_NO_CHILD_FRAME_ID: Ignoring transform from authority "{authority}" '
                "because child_frame_id not set "
            )
        if not parent:
            errors.append(
                f'TF_NO_FRAME_ID: Ignoring transform with child_frame_id "{child}"  from '
                f'authority "{authority}" because frame_id not set'
            )
        tx, ty, tz, qx, qy, qz, qw = transform
        if any(isnan(v) for v in transform):
            errors.append(
                f'TF_NAN_INPUT: Ignoring transform for child_frame_id "{child}" from authority '
                f'"{authority}" because of a nan value in the transform '
                f"({tx:f} {ty:f} {tz:f}) ({qx:f} {qy:f} {qz:f} {qw:f})"
            )
        if not abs((qw * qw + qx * qx + qy * qy + qz * qz) - 1.0) < _NORMALIZATION_TOLERANCE:
            errors.append(
                f'TF_DENORMALIZED_QUATERNION: Ignoring transform for child_frame_id "{child}" '
                f'from authority "{authority}" because of an invalid quaternion in the '
                f"transform ({qx:f} {qy:f} {qz:f} {qw:f})"
            )
        if errors:
            if self.report is not None:
                for error in errors:
                    self.report("Error", error)
            return False
        with self._lock:
            child_id = self._id_of(child)
            cache = self._caches[child_id]
            if cache is None:
                cache = StaticCache() if is_static else TimeCache(self.cache_time)
                self._caches[child_id] = cache
            before = cache.parent
            refused = cache.insert(stamp, (self._id_of(parent), tx, ty, tz, qx, qy, qz, qw))
            if refused is None:
                self._authority[child_id] = authority
                self.version += 1
                # a plan holds a static frame's sample itself, a moving frame's lists
                if cache.parent != before or isinstance(cache, StaticCache):
                    self._plans.clear()
        if refused is not None:
            if self.report is not None:
                self.report(
                    "Warning",
                    f"{refused.replace('%%', '%')} for frame {child} at time "
                    f"{stamps.to_sec(stamp):f} according to authority {authority}",
                )
            return False
        for listener in list(self._listeners):
            listener()
        return True

    def _id_of(self, frame: str) -> int:
        """The id of ``frame``, given one if new (under the lock)."""
        number = self._ids.get(frame)
        if number is None:
            number = len(self._names)
            self._ids[frame] = number
            self._names.append(frame)
            self._caches.append(None)
        return number

    def clear(self) -> None:
        """Forget every moving frame's transforms (static ones stay), as tf2's ``clear``."""
        with self._lock:
            for cache in self._caches:
                if cache is not None:
                    cache.clear()
            self.version += 1
            self._plans.clear()

    def add_listener(self, callback: Callable[[], object]) -> None:
        """Call ``callback()`` after each transform stored."""
        self._listeners.append(callback)

    def remove_listener(self, callback: Callable[[], object]) -> None:
        """Stop calling ``callback``."""
        if callback in self._listeners:
            self._listeners.remove(callback)

    # -- checking names ----------------------------------------------------------------------

    def validate(self, function: str, frame: str) -> int:
        """tf2's ``validateFrameId``: the frame's id.

        Raises:
            InvalidArgumentException: empty, or starting with ``/``.
            LookupException: no such frame.
        """
        if not frame:
            raise InvalidArgumentException(
                f"Invalid argument passed to {function} in tf2 frame_ids cannot be empty"
            )
        if frame[0] == "/":
            raise InvalidArgumentException(
                f'Invalid argument "{frame}" passed to {function} in tf2 frame_ids cannot '
                "start with a '/' like: "
            )
        number = self._ids.get(frame, 0)
        if not number:
            raise LookupException(f'"{frame}" passed to {function} does not exist. ')
        return number

    def _warn_frame(self, function: str, frame: str) -> bool:
        """tf2's ``warnFrameId``: report (and say) an empty or slash-led name."""
        if not frame:
            text = f"Invalid argument passed to {function} in tf2 frame_ids cannot be empty"
        elif frame[0] == "/":
            text = (
                f'Invalid argument "{frame}" passed to {function} in tf2 frame_ids cannot '
                "start with a '/' like: "
            )
        else:
            return False
        if self.report is not None:
            self.report("Warning", text)
        return True

    # -- looking up --------------------------------------------------------------------------

    def lookup(self, target: str, source: str, time: int) -> tuple[int, Transform]:
        """tf2's ``lookupTransform``: the stamp used and the transform that takes data in
        ``source`` to ``target`` at ``time`` (ns; 0 the latest common time).

        Raises:
            TransformException: ROS 1's subclass and text for the failure.
        """
        with self._lock:
            if target == source:
                if not time:
                    cache = self._caches[self._ids.get(target, 0)]
                    return (0 if cache is None else cache.newest_stamp()), IDENTITY
                return time, IDENTITY
            ids = self._ids
            target_id = ids.get(target, 0)
            source_id = ids.get(source, 0)
            if not target_id or not source_id or target[0] == "/" or source[0] == "/":
                target_id = self.validate("lookupTransform argument target_frame", target)
                source_id = self.validate("lookupTransform argument source_frame", source)
            if time and time != self._given:  # a new time: along the pair's plan
                self._given = time
                try:
                    plan = self._plans[(target_id, source_id)]
                except KeyError:
                    plan = self._plans[(target_id, source_id)] = self._plan(target_id, source_id)
                if plan is not None:
                    done = _follow(plan, time)
                    if done is not None:
                        return time, done
            else:
                found = self._remembered(time, target_id, source_id)
                if found is not None:
                    return found
            code, stamp, result, text = self._walk(time, target_id, source_id, True)
        if code:
            raise _RAISE[code](text)
        return stamp, result

    # -- plans kept until a parent changes --------------------------------------------------

    def _up(self, frame: int) -> tuple[list[int], int] | None:
        """The frames with transforms from ``frame`` up and the root above them, each frame
        with one parent over its whole buffer; None where one has had two, or none, or for a
        loop."""
        caches = self._caches
        frames: list[int] = []
        while True:
            cache = caches[frame]
            if cache is None:
                return frames, frame
            parent = cache.parent
            if parent <= 0 or len(frames) >= MAX_GRAPH_DEPTH:
                return None
            frames.append(frame)
            frame = parent

    def _plan(self, target_id: int, source_id: int) -> _Plan | None:
        """The `_Plan` of tf2's walk between two frames (see `_walk`) where every transform
        on the way is found; None where `_walk` itself goes."""
        up = self._up(source_id)
        down = self._up(target_id)
        if up is None or down is None:
            return None
        source_frames, source_root = up
        target_frames, target_root = down
        if target_id in source_frames:
            i = source_frames.index(target_id)
            return _UP, self._links(source_frames[:i]), self._links(source_frames[i : i + 1]), []
        if source_id in target_frames:
            j = target_frames.index(source_id)
            return _DOWN, self._links(target_frames[:j]), self._links(source_frames), []
        if source_root != target_root:
            return None
        # both walks go on to the root from the first frame they share
        shared = {*source_frames, source_root}
        k = 0
        while k < len(target_frames) and target_frames[k] not in shared:
            k += 1
        j = source_frames.index(target_frames[k]) if k < len(target_frames) else len(source_frames)
        return (
            _FULL,
            self._links(source_frames[:j]),
            self._links(target_frames[:k]),
            self._links(source_frames[j:]),
        )

    def _links(self, frames: list[int]) -> list[_Link]:
        links: list[_Link] = []
        for frame in frames:
            cache = self._caches[frame]
            if isinstance(cache, TimeCache):
                links.append((cache.stamps, cache.samples, cache.spans))
            elif cache is not None:
                links.append((None, cache.sample, None))
        return links

    # -- walks remembered until the next insertion -------------------------------------------

    def _remembered(
        self, time: int, target_id: int, source_id: int
    ) -> tuple[int, Transform] | None:
        """`lookup`'s answer from the two frames' walks to the root at ``time``, each kept
        until the buffer changes (a tree is usually asked about many times at one time); None
        where tf2's walk would not simply meet at the root (errors, loops), which `_walk`
        answers with tf2's texts.

        tf2's walk accumulates from the source up until it meets the target, and from the
        target up until it meets the source or the source's root; a frame's walk to the root
        holds every partial sum either side needs, computed in the same order, so the answer
        is tf2's to the bit."""
        if self._walks_version != self.version:
            self._walks.clear()
            self._common.clear()
            self._walks_version = self.version
        if not time:
            common = self._common.get((target_id, source_id))
            if common is None:
                common = self._common[(target_id, source_id)] = self._latest_common_time(
                    target_id, source_id
                )
            if common[0]:
                return None
            time = common[1]
        up = self._walk_up(source_id, time)
        if up is None:
            return None
        frames, accs, clean, root = up
        if target_id in frames:
            return time, accs[frames.index(target_id) - 1]
        if not clean:
            return None
        down = self._walk_up(target_id, time)
        if down is None:
            return None
        target_frames, target_accs, target_clean, target_root = down
        if source_id in target_frames:
            return time, _inverse(target_accs[target_frames.index(source_id) - 1])
        if not target_clean or root != target_root:
            return None
        source_acc = accs[-1] if accs else IDENTITY
        target_acc = target_accs[-1] if target_accs else IDENTITY
        return time, _full_path(source_acc, target_acc)

    def _walk_up(self, frame: int, time: int) -> Any:
        """``(frames, sums, clean, root)``: the frames from ``frame`` to its root at ``time``
        whose transforms were found, the accumulated transform after each, whether the walk
        reached a frame without transforms (the root), and that frame; None for a loop."""
        # by time: pairs of frames published at different rates have different latest
        # common times; a few times are kept, that of each kind of pair
        walks = self._walks.get(time)
        if walks is None:
            if len(self._walks) >= _KEPT_TIMES:
                self._walks.clear()
            walks = self._walks[time] = {}
        walk = walks.get(frame)
        if walk is not None:
            return walk
        caches = self._caches
        count = len(caches)
        frames: list[int] = []
        accs: list[Transform] = []
        acc = IDENTITY
        clean = False
        start = frame
        while frame:
            cache = caches[frame] if frame < count else None
            if cache is None:
                clean = True
                break
            step: Any = cache.get(time)
            if isinstance(step, str):
                break
            frames.append(frame)
            parent, tx, ty, tz, qx, qy, qz, qw = step
            ax, ay, az, bx, by, bz, bw = acc
            x = qw * ax + qy * az - qz * ay
            y = qw * ay + qz * ax - qx * az
            z = qw * az + qx * ay - qy * ax
            w = -qx * ax - qy * ay - qz * az
            acc = (
                w * -qx + x * qw + y * -qz - z * -qy + tx,
                w * -qy + y * qw + z * -qx - x * -qz + ty,
                w * -qz + z * qw + x * -qy - y * -qx + tz,
                qw * bx + qx * bw + qy * bz - qz * by,
                qw * by + qy * bw + qz * bx - qx * bz,
                qw * bz + qz * bw + qx * by - qy * bx,
                qw * bw - qx * bx - qy * by - qz * bz,
            )
            accs.append(acc)
            frame = parent
            if len(frames) > MAX_GRAPH_DEPTH:
                return None
        walk = walks[start] = (frames, accs, clean, frame)
        return walk

    def lookup_full(
        self, target: str, target_time: int, source: str, source_time: int, fixed: str
    ) -> tuple[int, Transform]:
        """tf2's ``lookupTransform`` with a fixed frame: ``source`` at ``source_time`` to
        ``fixed``, then ``fixed`` to ``target`` at ``target_time``.

        Raises:
            TransformException: ROS 1's subclass and text for the failure.
        """
        with self._lock:
            self.validate("lookupTransform argument target_frame", target)
            self.validate("lookupTransform argument source_frame", source)
            self.validate("lookupTransform argument fixed_frame", fixed)
        _, first = self.lookup(fixed, source, source_time)
        stamp, second = self.lookup(target, fixed, target_time)
        from rosx.tf import linear  # noqa: PLC0415 - matrices for this call only

        return stamp, linear.compose(second, first)

    def can(self, target: str, source: str, time: int) -> tuple[bool, str]:
        """tf2's ``canTransform``: whether ``lookup`` would succeed, and if not why (the text
        ``can_transform_core`` returns)."""
        if target == source:
            return True, ""
        if self._warn_frame("canTransform argument target_frame", target):
            return False, ""
        if self._warn_frame("canTransform argument source_frame", source):
            return False, ""
        with self._lock:
            target_id = self._ids.get(target, 0)
            source_id = self._ids.get(source, 0)
            if not target_id or not source_id:
                return False, self._missing(target, target_id, source, source_id)
            return self._can(target_id, source_id, time)

    def can_full(
        self, target: str, target_time: int, source: str, source_time: int, fixed: str
    ) -> tuple[bool, str]:
        """tf2's ``canTransform`` with a fixed frame."""
        for name, frame in (("target", target), ("source", source), ("fixed", fixed)):
            if self._warn_frame(f"canTransform argument {name}_frame", frame):
                return False, ""
        with self._lock:
            target_id = self._ids.get(target, 0)
            source_id = self._ids.get(source, 0)
            fixed_id = self._ids.get(fixed, 0)
            if not target_id or not source_id or not fixed_id:
                text = self._missing(target, target_id, source, source_id)
                if not source_id:  # tf2 0.7.6 tests the source twice, not the fixed frame
                    text += " " + f"fixed_frame: {fixed}does not exist."
                return False, text
            ok, text = self._can(target_id, fixed_id, target_time)
            if not ok:
                return False, text
            ok, more = self._can(fixed_id, source_id, source_time)
            return ok, text + more

    @staticmethod
    def _missing(target: str, target_id: int, source: str, source_id: int) -> str:
        text = ""
        if not target_id:
            text += f"canTransform: target_frame {target} does not exist."
        if not source_id:
            if not target_id:
                text += " "
            text += f"canTransform: source_frame {source} does not exist."
        return text

    def _can(self, target_id: int, source_id: int, time: int) -> tuple[bool, str]:
        if target_id == source_id:
            return True, ""
        code, _, _, text = self._walk(time, target_id, source_id, False)
        return not code, text

    def _walk(  # noqa: PLR0915 - tf2's walk as one loop per side: no call per step
        self, time: int, target_id: int, source_id: int, accumulate: bool
    ) -> tuple[int, int, Transform, str]:
        """tf2's ``walkToTopParent`` (see the module docstring): ``(NO_ERROR, time, the
        transform, "")`` or ``(code, 0, IDENTITY, tf2's text)``. Without ``accumulate`` only
        parents are read (``canTransform``), and the transform is the identity."""
        if source_id == target_id:
            return NO_ERROR, time, IDENTITY, ""
        if not time:
            code, time, text = self._latest_common_time(target_id, source_id)
            if code:
                return code, 0, IDENTITY, text
        caches = self._caches
        count = len(caches)
        source_acc = IDENTITY
        frame = source_id
        top_parent = frame
        depth = 0
        extrapolation = ""
        maybe_extrapolation = False
        while frame:
            cache = caches[frame] if frame < count else None
            if cache is None:
                top_parent = frame
                break
            step: Any = cache.get(time) if accumulate else cache.parent_at(time)
            if isinstance(step, str):
                top_parent = frame
                extrapolation = step
                maybe_extrapolation = True
                break
            if frame == target_id:
                return NO_ERROR, time, source_acc, ""
            if accumulate:
                # tf2's accum(): quatRotate(step, acc) + translation; step's rotation * acc's
                parent, tx, ty, tz, qx, qy, qz, qw = step
                ax, ay, az, bx, by, bz, bw = source_acc
                x = qw * ax + qy * az - qz * ay
                y = qw * ay + qz * ax - qx * az
                z = qw * az + qx * ay - qy * ax
                w = -qx * ax - qy * ay - qz * az
                source_acc = (
                    w * -qx + x * qw + y * -qz - z * -qy + tx,
                    w * -qy + y * qw + z * -qx - x * -qz + ty,
                    w * -qz + z * qw + x * -qy - y * -qx + tz,
                    qw * bx + qx * bw + qy * bz - qz * by,
                    qw * by + qy * bw + qz * bx - qx * bz,
                    qw * bz + qz * bw + qx * by - qy * bx,
                    qw * bw - qx * bx - qy * by - qz * bz,
                )
            else:
                parent = step
            top_parent = frame
            frame = parent
            depth += 1
            if depth > MAX_GRAPH_DEPTH:
                return LOOKUP_ERROR, 0, IDENTITY, self._loop_text()
        target_acc = IDENTITY
        frame = target_id
        depth = 0
        while frame != top_parent:
            cache = caches[frame] if frame < count else None
            if cache is None:
                break
            step = cache.get(time) if accumulate else cache.parent_at(time)
            if isinstance(step, str):
                return (
                    EXTRAPOLATION_ERROR,
                    0,
                    IDENTITY,
                    self._on_the_way(step, source_id, target_id),
                )
            if frame == source_id:
                return NO_ERROR, time, _inverse(target_acc) if accumulate else IDENTITY, ""
            if accumulate:
                frame, tx, ty, tz, qx, qy, qz, qw = step
                ax, ay, az, bx, by, bz, bw = target_acc
                x = qw * ax + qy * az - qz * ay
                y = qw * ay + qz * ax - qx * az
                z = qw * az + qx * ay - qy * ax
                w = -qx * ax - qy * ay - qz * az
                target_acc = (
                    w * -qx + x * qw + y * -qz - z * -qy + tx,
                    w * -qy + y * qw + z * -qx - x * -qz + ty,
                    w * -qz + z * qw + x * -qy - y * -qx + tz,
                    qw * bx + qx * bw + qy * bz - qz * by,
                    qw * by + qy * bw + qz * bx - qx * bz,
                    qw * bz + qz * bw + qx * by - qy * bx,
                    qw * bw - qx * bx - qy * by - qz * bz,
                )
            else:
                frame = step
            depth += 1
            if depth > MAX_GRAPH_DEPTH:
                return LOOKUP_ERROR, 0, IDENTITY, self._loop_text()
        if frame != top_parent:
            if maybe_extrapolation:
                return (
                    EXTRAPOLATION_ERROR,
                    0,
                    IDENTITY,
                    self._on_the_way(extrapolation, source_id, target_id),
                )
            return CONNECTIVITY_ERROR, 0, IDENTITY, self._not_connected(source_id, target_id)
        return NO_ERROR, time, _full_path(source_acc, target_acc) if accumulate else IDENTITY, ""

    def _on_the_way(self, text: str, source_id: int, target_id: int) -> str:
        names = self._names
        return (
            f"{text}, when looking up transform from frame [{names[source_id]}] to frame "
            f"[{names[target_id]}]"
        )[:999]

    def _not_connected(self, source_id: int, target_id: int) -> str:
        names = self._names
        return (
            f"Could not find a connection between '{names[target_id]}' and "
            f"'{names[source_id]}' because they are not part of the same tree."
            "Tf has two or more unconnected trees."
        )

    def _loop_text(self) -> str:
        return "The tf tree is invalid because it contains a loop.\n" + self._as_string() + "\n"

    def _latest_common_time(  # noqa: PLR0915 - tf2's two walks, one loop each
        self, target_id: int, source_id: int
    ) -> tuple[int, int, str]:
        """tf2's ``getLatestCommonTime``: ``(NO_ERROR, ns, "")`` or ``(code, 0, text)``."""
        if not source_id or not target_id:
            return LOOKUP_ERROR, 0, ""
        caches = self._caches
        count = len(caches)
        if source_id == target_id:
            cache = caches[source_id] if source_id < count else None
            return NO_ERROR, 0 if cache is None else cache.newest_stamp(), ""
        seen: list[tuple[int, int]] = []
        seen_parents: set[int] = set()
        frame = source_id
        depth = 0
        common = stamps.TIME_MAX
        while frame:
            cache = caches[frame] if frame < count else None
            if cache is None:
                break
            latest, parent = cache.latest()
            if not parent:
                break
            if latest:
                common = min(latest, common)
            seen.append((latest, parent))
            seen_parents.add(parent)
            frame = parent
            if frame == target_id:
                return NO_ERROR, 0 if common == stamps.TIME_MAX else common, ""
            depth += 1
            if depth > MAX_GRAPH_DEPTH:
                return LOOKUP_ERROR, 0, self._loop_text()
        frame = target_id
        depth = 0
        common = stamps.TIME_MAX
        common_parent = 0
        while True:
            cache = caches[frame] if frame < count else None
            if cache is None:
                break
            latest, parent = cache.latest()
            if not parent:
                break
            if latest:
                common = min(latest, common)
            if parent in seen_parents:
                common_parent = parent
                break
            frame = parent
            if frame == source_id:
                return NO_ERROR, 0 if common == stamps.TIME_MAX else common, ""
            depth += 1
            if depth > MAX_GRAPH_DEPTH:
                return LOOKUP_ERROR, 0, self._loop_text()
        if not common_parent:
            return CONNECTIVITY_ERROR, 0, self._not_connected(source_id, target_id)
        for latest, parent in seen:
            if latest:
                common = min(common, latest)
            if parent == common_parent:
                break
        return NO_ERROR, 0 if common == stamps.TIME_MAX else common, ""

    def latest_common_time(self, target: str, source: str) -> int:
        """tf2_py's ``get_latest_common_time``, in ns.

        Raises:
            TransformException: a frame is unknown or the frames do not connect.
        """
        from rosx.tf.exceptions import TransformException  # noqa: PLC0415 - tf code loads only when used

        with self._lock:
            target_id = self.validate("get_latest_common_time", target)
            source_id = self.validate("get_latest_common_time", source)
            code, found, text = self._latest_common_time(target_id, source_id)
        if code:
            raise TransformException(text)
        return found

    def chain(
        self, target: str, target_time: int, source: str, source_time: int, fixed: str
    ) -> list[str]:
        """The frames from ``source`` (at ``source_time``) through ``fixed`` to ``target`` (at
        ``target_time``): tf2's ``_chainAsVector``, which tf's ``chain`` returns.

        Raises:
            TransformException: ROS 1's subclass and text when a walk fails.
        """
        with self._lock:
            ids = self._ids
            first = self._chain_walk(source_time, ids.get(fixed, 0), ids.get(source, 0))
            second = self._chain_walk(target_time, ids.get(target, 0), ids.get(fixed, 0))
            if first and second and first[-1] == second[0]:
                first.pop()
            return [self._names[number] for number in first + second]

    def _chain_walk(  # noqa: PLR0915 - the same walk, recording frames
        self, time: int, target_id: int, source_id: int
    ) -> list[int]:
        """The frames tf2's ``walkToTopParent`` passes from ``source_id`` to ``target_id``."""
        if source_id == target_id:
            return []
        if not time:
            code, time, text = self._latest_common_time(target_id, source_id)
            if code:
                raise _RAISE[code](text)
        caches = self._caches
        count = len(caches)
        chain: list[int] = []
        frame = top_parent = source_id
        extrapolation: str | None = None
        while frame:
            chain.append(frame)
            cache = caches[frame] if frame < count else None
            if cache is None:
                top_parent = frame
                break
            parent = cache.parent_at(time)
            if isinstance(parent, str):
                top_parent = frame
                extrapolation = parent
                break
            if frame == target_id:
                return chain
            top_parent = frame
            frame = parent
            if len(chain) > MAX_GRAPH_DEPTH:
                raise LookupException(self._loop_text())
        backwards: list[int] = []
        frame = target_id
        while frame != top_parent:
            backwards.append(frame)
            cache = caches[frame] if frame < count else None
            if cache is None:
                break
            parent = cache.parent_at(time)
            if isinstance(parent, str):
                raise ExtrapolationException(self._on_the_way(parent, source_id, target_id))
            if frame == source_id:
                return backwards[::-1]
            frame = parent
            if len(backwards) > MAX_GRAPH_DEPTH:
                raise LookupException(self._loop_text())
        if frame != top_parent:
            if extrapolation is not None:
                raise ExtrapolationException(self._on_the_way(extrapolation, source_id, target_id))
            raise ConnectivityException(self._not_connected(source_id, target_id))
        backwards.append(frame)
        m = len(backwards) - 1
        n = len(chain) - 1
        while m >= 0 and n >= 0 and chain[n] == backwards[m]:
            m -= 1
            n -= 1
        if n > 0:
            del chain[n + 2 :]
        if m >= 0:
            chain.extend(backwards[m::-1])
        return chain

    # -- describing --------------------------------------------------------------------------

    def frame_exists(self, frame: str) -> bool:
        """Whether ``frame`` was ever named (as child or parent)."""
        with self._lock:
            return frame in self._ids

    def frame_names(self) -> list[str]:
        """Every frame ever named, in the order they were first seen."""
        with self._lock:
            return self._names[1:]

    def parent_of(self, frame: str, time: int = 0) -> str | None:
        """The parent of ``frame`` at ``time`` (tf2's ``_getParent``); None if it has none."""
        with self._lock:
            number = self._ids.get(frame, 0)
            cache = self._caches[number] if number else None
            if cache is None:
                return None
            parent = cache.parent_at(time)
            if isinstance(parent, str) or not parent:
                return None
            return self._names[parent]

    def frames(self) -> list[FrameInfo]:
        """Every frame but tf2's ``NO_PARENT``, in id order, as tf2's descriptions read them
        (``allFramesAsYAML``, ``_allFramesAsDot``)."""
        with self._lock:
            out = []
            names = self._names
            for number in range(1, len(names)):
                cache = self._caches[number]
                if cache is None:
                    out.append(FrameInfo(names[number], None, "", 0, 0, 0))
                    continue
                step = cache.get(0)
                parent = "" if isinstance(step, str) else names[step[0]]
                out.append(
                    FrameInfo(
                        names[number],
                        parent,
                        self._authority.get(number, "no recorded authority"),
                        len(cache),
                        cache.newest_stamp(),
                        cache.oldest_stamp(),
                    )
                )
            return out

    def _as_string(self) -> str:
        lines = []
        for number, cache in enumerate(self._caches):
            if cache is None:
                continue
            step = cache.get(0)
            parent = 0 if isinstance(step, str) else step[0]
            lines.append(f"Frame {self._names[number]} exists with parent {self._names[parent]}.\n")
        return "".join(lines)

    def frames_as_string(self) -> str:
        """tf2's ``allFramesAsString``: ``Frame X exists with parent Y.`` per frame."""
        with self._lock:
            return self._as_string()

    def frames_as_yaml(self, current_time: float = 0.0) -> str:
        """tf2's ``allFramesAsYAML`` (``transform_delay`` when ``current_time`` > 0, in s)."""
        from rosx.tf.describe import frames_yaml  # noqa: PLC0415 - tf code loads only when used

        return frames_yaml(self.frames(), current_time)

    def frames_as_dot(self, current_time: float = 0.0) -> str:
        """tf2's ``_allFramesAsDot``: the tree in Graphviz's language, as view_frames draws."""
        from rosx.tf.describe import frames_dot  # noqa: PLC0415 - tf code loads only when used

        return frames_dot(self.frames(), current_time)


class FrameInfo:
    """One frame as tf2's descriptions show it.

    ``parent`` is None for a frame only ever named as a parent (no cache: a root), ``""`` for
    one whose cache is empty (after `BufferCore.clear`).
    """

    __slots__ = ("authority", "length", "name", "newest", "oldest", "parent")

    def __init__(
        self,
        name: str,
        parent: str | None,
        authority: str,
        length: int,
        newest: int,
        oldest: int,
    ) -> None:
        self.name = name
        self.parent = parent
        self.authority = authority
        self.length = length
        self.newest = newest
        self.oldest = oldest


__all__ = [
    "DEFAULT_CACHE_TIME",
    "IDENTITY",
    "BufferCore",
    "FrameInfo",
    "Transform",
]
