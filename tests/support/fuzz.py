"""What the parsers' fuzzers share: hypothesis settings sized for CI, and guards against hangs
and runaway memory.

Every fuzzer in the suite is marked ``fuzz`` and takes its settings from `fuzz_settings`: a
few seconds each in CI, derandomized so that the suite gives the same verdict on every run.
``ROSX_FUZZ=N`` multiplies the examples by N and draws them at random, for long runs::

    ROSX_FUZZ=200 python -m pytest -m fuzz -x -q

A parser under fuzz either accepts its input or refuses it with its own error class: any
other exception fails the test, as does an input that takes longer than `HANG_SECONDS`
(`no_hang`) or, for the named bombs, allocates more than a bound (`peak_allocation`).
"""

from __future__ import annotations

import contextlib
import os
import signal
import tracemalloc
from typing import TYPE_CHECKING, Any

from hypothesis import HealthCheck, settings

if TYPE_CHECKING:
    from collections.abc import Callable, Iterator

#: How many times the CI examples to run (``ROSX_FUZZ``); above 1, examples are random.
SCALE = float(os.environ.get("ROSX_FUZZ", "1") or "1")
#: Longer than any parser takes on any input on a loaded machine; shorter than a hang.
HANG_SECONDS = 20.0
#: What a small input may make a parser allocate at most.
MEMORY_BOUND = 64 << 20


def fuzz_settings(examples: int, **extra: Any) -> settings:
    """Settings for a fuzzer that runs ``examples`` examples in CI (`SCALE` times as many otherwise)."""
    if SCALE <= 1:  # the same examples on every run, and nothing written to .hypothesis/
        extra = {"derandomize": True, "database": None, **extra}
    return settings(
        max_examples=max(1, int(examples * SCALE)),
        deadline=None,
        suppress_health_check=[
            HealthCheck.too_slow,
            HealthCheck.data_too_large,
            HealthCheck.filter_too_much,
            HealthCheck.function_scoped_fixture,
        ],
        **extra,
    )


class HangError(AssertionError):
    """A parser took longer than `HANG_SECONDS` on one input."""


@contextlib.contextmanager
def no_hang(seconds: float = HANG_SECONDS) -> Iterator[None]:
    """Fail with `HangError` if the block takes longer than ``seconds`` (main thread only)."""

    def expired(signum: int, frame: object) -> None:
        raise HangError(f"no answer within {seconds} s")

    previous = signal.signal(signal.SIGALRM, expired)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)


def peak_allocation(call: Callable[[], object]) -> int:
    """The most memory ``call()`` held at once (bytes, Python's allocators and numpy's),
    whether it returned or raised."""
    tracemalloc.start()
    try:
        tracemalloc.reset_peak()
        with contextlib.suppress(Exception):
            call()
        return tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
