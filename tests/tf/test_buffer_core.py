"""tf2's buffer core without ROS 1: lookups at a given time, along the chains the core keeps,
give what tf2's own walk gives, to the bit, and fail with its texts.

The reference is the core's ``_walk``, tf2's ``walkToTopParent`` step by step, which
`test_against_debian_tf2.py` holds equal to Debian's tf2 where Debian's is installed.
"""

from __future__ import annotations

import math
import random

from rosx.tf import stamps
from rosx.tf.core import BufferCore
from rosx.tf.exceptions import TransformException

START = 1000 * stamps.SECOND
STEP = 10_000_000  # 100 Hz

# Two arms on a base, a head with a static camera, a second tree.
TREE = [
    ("odom", "map"),
    ("base", "odom"),
    *[(f"left_{i}", "base" if i == 1 else f"left_{i - 1}") for i in range(1, 8)],
    *[(f"right_{i}", "base" if i == 1 else f"right_{i - 1}") for i in range(1, 6)],
    ("head", "base"),
    ("camera", "head"),
    ("cup", "left_3"),
    ("palm", "island"),
]
STATIC = {"camera", "left_3"}


def _values(rng: random.Random, skewed: bool) -> tuple[float, ...]:
    """A transform with signed zeros now and then; quaternions up to 0.4 % off unit length
    where ``skewed`` (tf2 accepts 1 %)."""
    translation = [rng.choice((0.0, -0.0, rng.uniform(-2, 2), rng.uniform(-2, 2))) for _ in "xyz"]
    if rng.random() < 0.2:  # about z only
        q = [0.0, -0.0, rng.uniform(-1, 1), rng.uniform(-1, 1)]
    else:
        q = [rng.gauss(0.0, 1.0) for _ in "xyzw"]
    n = math.sqrt(sum(x * x for x in q)) * (1.0 + (rng.uniform(-0.004, 0.004) if skewed else 0))
    return (*translation, *(x / n for x in q))


def _buffer(rng: random.Random) -> BufferCore:
    """Three seconds with jitter: the cup changes hands at 1.5 s, the head stops at 2 s, odom's
    quaternions are a little off unit length."""
    core = BufferCore()
    for k in range(300):
        for child, parent in TREE:
            if (child in STATIC and k) or (child == "head" and k > 200):
                continue
            mover = "right_5" if child == "cup" and k >= 150 else parent
            stamp = START + k * STEP + rng.randrange(-3_000_000, 3_000_000)
            values = _values(rng, child == "odom")
            assert core.set(mover, child, stamp, values, "test", child in STATIC)  # type: ignore[arg-type]
    return core


def _answers(core: BufferCore, target: str, source: str, time: int) -> tuple[object, object]:
    """``lookup``'s answer (or error class and text), and tf2's walk's."""
    try:
        ours: object = repr(core.lookup(target, source, time))
    except TransformException as error:
        ours = (type(error).__name__, str(error))
    ids = core._ids
    code, stamp, values, text = core._walk(time, ids[target], ids[source], True)
    names = {1: "LookupException", 2: "ConnectivityException", 3: "ExtrapolationException"}
    theirs = repr((stamp, values)) if not code else (names[code], text)
    return ours, theirs


def test_lookups_at_given_times_are_tf2s_walk_to_the_bit() -> None:
    rng = random.Random(30)
    core = _buffer(rng)
    frames = sorted({name for pair in TREE for name in pair})
    left = core._caches[core._ids["left_1"]].stamps  # type: ignore[union-attr]
    failed = 0
    for _ in range(4000):
        target, source = rng.sample(frames, 2)
        # within the buffer, before and after it, and right on a stamp
        time = rng.choice((START + rng.randrange(-10 * STEP, 310 * STEP), rng.choice(left)))
        ours, theirs = _answers(core, target, source, time)
        assert ours == theirs, (target, source, time)
        failed += isinstance(theirs, tuple)
        # asked again at once (kept walks), then the other way round
        assert _answers(core, target, source, time) == (theirs, theirs)
        assert _answers(core, source, target, time)[0] == _answers(core, source, target, time)[1]
    assert 400 < failed < 3000  # both ways were taken


def test_what_is_kept_follows_new_parents_statics_and_clears() -> None:
    core = BufferCore()
    identity = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)
    for k in range(11):
        stamp = START + k * STEP
        core.set("map", "table", stamp, (1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0))
        core.set("map", "hand", stamp, (0.0, 2.0, 0.0, 0.0, 0.0, 0.0, 1.0))
    core.set("hand", "finger", 0, (0.0, 0.0, 0.1, 0.0, 0.0, 0.0, 1.0), is_static=True)
    core.set("table", "cup", START, (0.0, 0.0, 0.5, 0.0, 0.0, 0.0, 1.0))
    core.set("table", "cup", START + 9 * STEP, (0.0, 0.0, 0.5, 0.0, 0.0, 0.0, 1.0))
    middle = START + 4 * STEP + 1
    assert core.lookup("map", "cup", middle)[1][:3] == (1.0, 0.0, 0.5)
    assert core.lookup("finger", "map", middle + 1)[1][:3] == (0.0, -2.0, -0.1)
    # a static frame sent again moves, whatever was asked before
    core.set("hand", "finger", 0, (0.0, 0.0, 0.3, 0.0, 0.0, 0.0, 1.0), is_static=True)
    assert core.lookup("finger", "map", middle + 2)[1][:3] == (0.0, -2.0, -0.3)
    core.set("table", "finger", 0, (0.0, 0.0, 0.3, 0.0, 0.0, 0.0, 1.0), is_static=True)
    assert core.lookup("finger", "map", middle + 3)[1][:3] == (-1.0, 0.0, -0.3)
    # picked up: the cup's newer transforms are to the hand
    assert core.lookup("map", "cup", middle + 4)[1][:3] == (1.0, 0.0, 0.5)
    core.set("hand", "cup", START + 10 * STEP, (0.0, 0.0, 0.2, 0.0, 0.0, 0.0, 1.0))
    assert core.lookup("map", "cup", middle + 5)[1][:3] == (1.0, 0.0, 0.5)
    assert core.lookup("map", "cup", START + 10 * STEP)[1][:3] == (0.0, 2.0, 0.2)
    # cleared: moving frames are gone, static ones stay
    core.clear()
    assert core.lookup("table", "finger", middle + 5) == (
        middle + 5,
        (0.0, 0.0, 0.3, *identity[3:]),
    )
    for target, source in (("map", "finger"), ("map", "cup")):
        ours, theirs = _answers(core, target, source, middle + 7)
        assert ours == theirs
        assert isinstance(ours, tuple)
