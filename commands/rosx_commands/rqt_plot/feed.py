"""Where the plot's samples come from: `LiveFeed` subscribes to the topics of its series on a
master; tests use a feed of their own with the same methods (`PlotFeed`) and append samples
themselves.

`attach` and `detach` may block (the master, the node) and are called from worker threads.
Samples are appended on the subscriptions' threads; the UI only reads them.
"""

from __future__ import annotations

import threading
import time
from typing import TYPE_CHECKING, Any, Protocol

from rosx_commands.rqt_plot.series import Series, SeriesError
from rosx_commands.toolnode import ToolNode

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx.msg.store import TypeStore
    from rosx.node import Subscriber
    from rosx_commands.context import Environment

CALLER_ID = "/rqt_plot"
#: Field types a series can plot (times and durations as seconds).
NUMERIC = frozenset(
    {"bool", "byte", "char", "time", "duration", "float32", "float64"}
    | {f"{sign}int{bits}" for sign in ("", "u") for bits in (8, 16, 32, 64)}
)


class PlotFeed(Protocol):
    """Where the plot's series get their values (the live feed, or a test's)."""

    def now(self) -> float:
        """Seconds since the plot started: the right edge of the time window."""
        ...

    def attach(self, series: Series) -> bool:
        """Start feeding ``series``; False while its topic is not published (try again later).
        Raises `SeriesError` for a name that cannot be plotted."""
        ...

    def detach(self, series: Series) -> None:
        """Stop feeding ``series``."""

    def close(self) -> None:
        """Release the feed's node."""


class LiveFeed(ToolNode):
    """A master's topics, through one node of its own (``/rqt_plot_<pid>_<ms>``)."""

    def __init__(self, env: Environment, clock: Callable[[], float] = time.monotonic) -> None:
        super().__init__(env, "rqt_plot")
        self._clock = clock
        self._start = clock()
        self._subscribers: dict[Series, Subscriber] = {}
        self._lock = threading.Lock()

    def now(self) -> float:
        """Seconds since the plot started: the right edge of the time window."""
        return self._clock() - self._start

    def attach(self, series: Series) -> bool:
        """Subscribe ``series``'s topic and append its field's value per message; False while the
        topic is not published (try again later). Raises `SeriesError` for a name that cannot be
        plotted."""
        from rosx.msg.codec.classes import get_message_class  # noqa: PLC0415 - message classes load on first use
        from rosx.msg.text.fieldpath import find_topic  # noqa: PLC0415 - the text forms load on first use
        from rosx.names.script import ros_namespace, script_resolve_name  # noqa: PLC0415 - name rules load only when used

        name = script_resolve_name("rqt_plot", series.name, ros_namespace(self.env.environ))
        store = self._types()
        master = self.env.master(CALLER_ID)
        try:
            types = master.topic_types()
        finally:
            master.close()
        found = find_topic(name, types, store)
        if found is None:
            owner = max((t for t in types if name.startswith(t + "/")), key=len, default=None)
            if owner is not None:  # a published topic without that field: say which is wrong
                _numeric_path(store, types[owner], name, name[len(owner) :])
            series.status = "not published yet"
            return False
        topic, type_name = found
        evaluate = _numeric_path(store, type_name, name, name[len(topic) :])
        msg_class = get_message_class(type_name, store)
        node = self._started()
        clock, start = self._clock, self._start

        def sample(msg: object) -> None:
            try:
                value = evaluate(msg)
            except (ValueError, TypeError) as error:
                series.status = str(error)
                return
            series.append(clock() - start, value)

        with self._lock:
            self._subscribers[series] = node.subscribe(topic, msg_class, sample)
        series.status = ""
        return True

    def detach(self, series: Series) -> None:
        """Unsubscribe ``series``; a series not attached is ignored."""
        with self._lock:
            subscriber = self._subscribers.pop(series, None)
        if subscriber is not None:
            subscriber.unregister()


def _numeric_path(
    store: TypeStore, type_name: str, name: str, text: str
) -> Callable[[object], float]:
    """A function giving the number ``text`` (a field path) selects in a message of
    ``type_name``; `SeriesError` if it selects no number."""
    from rosx.msg.text.fieldpath import (  # noqa: PLC0415 - the text forms load on first use
        FieldPathError,
        field_type,
        parse_field_path,
    )

    try:
        path = parse_field_path(text)
        declared = field_type(store.msg, type_name, path)
    except FieldPathError as error:
        raise SeriesError(f"{name}: {error}") from None
    if declared is None:
        raise SeriesError(f"{name} is a topic ({type_name}): name a numeric field of it")
    base, array = declared.split("[", 1)[0], "[" in declared
    if array and not isinstance(path.steps[-1].selector, int):
        raise SeriesError(f"{name} is an array ({declared}): plot one element, as {name}[0]")
    if base not in NUMERIC:
        raise SeriesError(f"{name} is not numeric ({declared})")

    def evaluate(msg: object) -> float:
        value: Any = path.evaluate(msg)
        if hasattr(value, "to_sec"):
            return float(value.to_sec())
        return float(value)

    return evaluate
