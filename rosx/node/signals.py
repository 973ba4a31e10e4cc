"""Shutting nodes down on SIGINT and SIGTERM, when their creator asks for it (rospy's default).

`install_signal_handlers` must be called from the main thread. On a signal the nodes shut down
on a thread of their own (a handler runs between two bytecodes of the main thread, which may
hold a lock the shutdown needs), with the reason rospy gives (``signal-2``), then the handler
that was installed before runs, as rospy chains them: for SIGINT that is Python's, which raises
`KeyboardInterrupt` in the main thread.
"""

from __future__ import annotations

import signal
import threading
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from collections.abc import Callable, Iterable
    from types import FrameType


def install_signal_handlers(
    shutdown: Callable[[str], object],
    signals: Iterable[int] = (signal.SIGINT, signal.SIGTERM),
) -> None:
    """On each of ``signals``, call ``shutdown("signal-N")`` and then the previous handler."""
    for signum in signals:
        previous = signal.getsignal(signum)

        def handler(sig: int, frame: FrameType | None, previous: Any = previous) -> None:
            threading.Thread(
                target=shutdown, args=(f"signal-{sig}",), name="rosx-signal", daemon=True
            ).start()
            if callable(previous) and previous not in (signal.SIG_IGN, signal.SIG_DFL):
                previous(sig, frame)

        signal.signal(signum, handler)
