"""Running an app in the terminal until the user quits, the node goes, or a signal says so.

``q`` and Ctrl-C are the apps' own bindings (a terminal in raw mode delivers Ctrl-C as a key).
SIGTERM, and a node shut down from outside (``rosnode kill``), end the app too: a watcher
thread asks it to exit through ``call_from_thread``, the only way other threads reach it.
This module imports no textual: the caller builds the app.
"""

from __future__ import annotations

import contextlib
import signal
import threading
from typing import TYPE_CHECKING

from rosx.signals import handling

if TYPE_CHECKING:
    from collections.abc import Callable

    from textual.app import App


def run_app(app: App[None], *, gone: Callable[[float], bool] | None = None) -> None:
    """Run ``app`` (blocking) until it exits; ``gone(timeout)`` True ends it as well."""
    done = threading.Event()

    def exit_app() -> None:
        with contextlib.suppress(RuntimeError):  # the app has already stopped
            app.call_from_thread(app.exit)

    def watch(gone: Callable[[float], bool]) -> None:
        while not done.is_set():
            if gone(0.1):
                exit_app()
                return

    watcher = threading.Thread(target=watch, args=(gone,), name="rosx-tui-watch", daemon=True)
    with handling(
        (signal.SIGTERM,), lambda signum: threading.Thread(target=exit_app, daemon=True).start()
    ):
        if gone is not None:
            watcher.start()
        try:
            app.run()
        finally:
            done.set()
            if watcher.is_alive():
                watcher.join(timeout=1.0)
