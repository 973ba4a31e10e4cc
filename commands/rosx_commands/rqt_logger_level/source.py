"""Where rqt_logger_level reads and sets levels: every node that serves ``~set_logger_level``.

`LiveSource` asks the master which services exist (`rosx.graph.state.registrations`) and keeps
the nodes
that serve both ``~get_loggers`` (``roscpp/GetLoggers``) and ``~set_logger_level``
(``roscpp/SetLoggerLevel``), as rqt_logger_level does; rosx, rospy and roscpp nodes all serve
them. Every method may block (network calls) and is called from worker threads only; tests
pass a source of their own with the same methods (`LevelSource`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Protocol

if TYPE_CHECKING:
    from collections.abc import Iterable, Sequence

    from rosx.master.client import MasterClient

GET_LOGGERS = "/get_loggers"
SET_LOGGER_LEVEL = "/set_logger_level"
#: The levels offered, in rqt_logger_level's order and words.
LEVELS = ("Debug", "Info", "Warn", "Error", "Fatal")
CALLER_ID = "/rqt_logger_level"
#: Seconds a node has to answer one service call.
CALL_TIMEOUT = 5.0


class LevelSource(Protocol):
    """Where rqt_logger_level reads and sets levels (`LiveSource`, or a test's)."""

    def nodes(self) -> list[str]:
        """The nodes whose levels can be set, sorted."""
        ...

    def loggers(self, node: str) -> list[tuple[str, str]]:
        """``(logger, LEVEL)`` of every logger of ``node``."""
        ...

    def set_level(self, node: str, logger: str, level: str) -> None:
        """Set ``logger`` of ``node`` to ``level`` (a name of `LEVELS`)."""
        ...

    def close(self) -> None:
        """Release the source's connections."""


def level_nodes(services: Iterable[tuple[str, Sequence[str]]]) -> list[str]:
    """The nodes that serve both logger services, from the services and their providers."""
    names = {name for name, _providers in services}
    return sorted(
        name[: -len(SET_LOGGER_LEVEL)]
        for name in names
        if name.endswith(SET_LOGGER_LEVEL) and name[: -len(SET_LOGGER_LEVEL)] + GET_LOGGERS in names
    )


class LiveSource:
    """The nodes of the master at ``uri``."""

    def __init__(self, uri: str, caller_id: str = CALLER_ID) -> None:
        self.uri = uri
        self.caller_id = caller_id
        self._master: MasterClient | None = None

    @property
    def master(self) -> MasterClient:
        """A client for the master at ``uri``, made on first use."""
        if self._master is None:
            from rosx.master.client import MasterClient  # noqa: PLC0415 - the master's code loads only to talk to one

            self._master = MasterClient(self.uri, self.caller_id, timeout=CALL_TIMEOUT)
        return self._master

    def nodes(self) -> list[str]:
        """The nodes that serve both ``get_loggers`` and ``set_logger_level`` (rqt_logger_level's
        list)."""
        from rosx.graph.state import registrations  # noqa: PLC0415 - as the master client

        return level_nodes(registrations(self.master).services.items())

    def loggers(self, node: str) -> list[tuple[str, str]]:
        """``node``'s loggers and their levels in upper case, from its ``~get_loggers`` service."""
        response = self._call(node + GET_LOGGERS, "roscpp/GetLoggers")
        return [(logger.name, logger.level.upper()) for logger in response.loggers]

    def set_level(self, node: str, logger: str, level: str) -> None:
        """Call ``node``'s ``~set_logger_level`` for ``logger``; the service takes the level in
        lower case."""
        self._call(node + SET_LOGGER_LEVEL, "roscpp/SetLoggerLevel", logger, level.lower())

    def _call(self, service: str, type_name: str, *args: str) -> Any:
        from rosx.msg.codec.classes import get_service_class  # noqa: PLC0415 - message classes load on first use
        from rosx.node.service_client import ServiceClient  # noqa: PLC0415 - the node runtime loads with the first node

        service_class = get_service_class(type_name)
        client = ServiceClient(self.master, service, service_class)
        try:
            return client.call(service_class._request_class(*args), timeout=CALL_TIMEOUT)
        finally:
            client.close()

    def close(self) -> None:
        """Close the master connection."""
        if self._master is not None:
            self._master.close()
            self._master = None
