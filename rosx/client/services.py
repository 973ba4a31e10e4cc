"""rospy's `Service`, `ServiceProxy` and `wait_for_service`, over `rosx.node`.

A `Service` may be created before `init_node` (it registers when the node starts); its handler
runs on a pool thread and may return a response, a dict or tuple of its fields, or a single
field value, or raise `ServiceException` to refuse the request. Any other exception is given to
its ``error_handler(exc, type, value, traceback)`` when it has one, as rospy does, and logged
otherwise; the client gets ``error processing request: <text>`` either way.

A `ServiceProxy` needs no node: called before `init_node` it calls as ``/unnamed``, as rospy
does. `wait_for_service` polls the master and probes the server until it answers, like rospy
(every 0.3 s).
"""

from __future__ import annotations

import time
from typing import TYPE_CHECKING, Any

from rosx.client import state
from rosx.client.exceptions import (
    ROSException,
    ROSInterruptException,
    ROSSerializationException,
    ServiceException,
)
from rosx.client.logs import loginfo, logwarn_throttle
from rosx.client.topics import args_kwds_to_message
from rosx.msg.codec.message import SerializationError, ServiceDefinition

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx.node import Node, ServiceClient, ServiceHandle

_POLL = 0.3
_PROBE_TIMEOUT = 10.0


def _check_service(name: object, service_class: object) -> None:
    if not name or not isinstance(name, str):
        raise ValueError("service name is not a non-empty string")
    if not isinstance(service_class, type) or not issubclass(service_class, ServiceDefinition):
        raise ValueError(f"service_class [{service_class}] is not a service class")


class Service:
    """Serves ``name`` with ``handler(request)``; registered once the node runs."""

    def __init__(
        self,
        name: str,
        service_class: type[ServiceDefinition],
        handler: Callable[[Any], object],
        buff_size: int = 65536,
        error_handler: Callable[..., object] | None = None,
    ) -> None:
        _check_service(name, service_class)
        self._requested_name = name
        self.resolved_name = state.CLIENT.resolve_name(name)
        self.service_class = service_class
        self.request_class = service_class._request_class
        self.response_class = service_class._response_class
        self.handler = handler
        self.error_handler = error_handler
        self.impl: ServiceHandle | None = None
        self.done = False
        state.CLIENT.attach(self)

    def _attach(self, node: Node) -> None:
        if self.done:
            return
        self.impl = node.advertise_service(
            self._requested_name,
            self.service_class,
            self.handler,
            on_exception=None if self.error_handler is None else self._on_exception,
        )
        self.resolved_name = self.impl.name
        self.uri = self.impl.uri

    def _on_exception(self, exc: Exception) -> None:
        assert self.error_handler is not None
        self.error_handler(exc, type(exc), exc, exc.__traceback__)

    def shutdown(self, reason: str = "") -> None:
        """Stop serving and unregister from the master."""
        self.done = True
        state.CLIENT.forget(self)
        impl, self.impl = self.impl, None
        if impl is not None:
            impl.shutdown()

    unregister = shutdown

    def spin(self) -> None:
        """Block until the node shuts down (the service keeps serving meanwhile)."""
        from rosx.client.lifecycle import spin  # noqa: PLC0415 - one way to spin

        spin()


class ServiceProxy:
    """Calls service ``name``: ``proxy(request)``, ``proxy(a, b)`` or ``proxy(a=1, b=2)``."""

    def __init__(
        self,
        name: str,
        service_class: type[ServiceDefinition],
        persistent: bool = False,
        headers: dict[str, str] | None = None,
    ) -> None:
        _check_service(name, service_class)
        self._requested_name = name
        self.resolved_name = state.CLIENT.resolve_name(name)
        self.service_class = service_class
        self.request_class = service_class._request_class
        self.response_class = service_class._response_class
        self.persistent = persistent
        self.headers = dict(headers or {})
        self._client: ServiceClient | None = None
        self._client_node: Node | None = None

    def _service_client(self) -> ServiceClient:
        from rosx.node import ServiceClient  # noqa: PLC0415 - the node runtime loads with the first node

        node = state.CLIENT.node
        if self._client is None or self._client_node is not node:
            if self._client is not None:
                self._client.close()
            self.resolved_name = state.CLIENT.resolve_name(self._requested_name)
            self._client = ServiceClient(
                state.CLIENT.master(),
                self.resolved_name,
                self.service_class,
                persistent=self.persistent,
                headers=self.headers,
            )
            self._client_node = node
        return self._client

    def wait_for_service(self, timeout: float | None = None) -> None:
        """Block until the service is available (see `wait_for_service`)."""
        wait_for_service(self.resolved_name, timeout=timeout)

    def call(self, *args: Any, **kwds: Any) -> Any:
        """Call the service and return its response.

        Raises:
            ServiceException: the call failed, or the server refused the request.
            ROSSerializationException: a request field holds a value that cannot be sent.
            TypeError: the request is not of the service's request type.
        """
        request = args_kwds_to_message(self.request_class, args, kwds)
        try:
            return self._service_client().call(request)
        except SerializationError as exc:
            raise ROSSerializationException(str(exc)) from None

    __call__ = call

    def close(self) -> None:
        """Close a persistent connection."""
        if self._client is not None:
            self._client.close()


def wait_for_service(service: str, timeout: float | None = None) -> None:
    """Block until ``service`` is registered and answers.

    Raises:
        ValueError: ``timeout`` is zero.
        ROSException: ``timeout`` seconds (or a `Duration`) passed first.
        ROSInterruptException: the node shut down meanwhile.
    """
    from rosx.node.service_client import contact_service  # noqa: PLC0415 - the node runtime loads with the first node

    seconds = None if timeout is None else getattr(timeout, "to_sec", lambda: timeout)()
    if seconds is not None and float(seconds) == 0.0:
        raise ValueError("timeout must be non-zero")
    resolved = state.CLIENT.resolve_name(service)
    deadline = None if seconds is None else time.monotonic() + float(seconds)
    failed = False
    while not state.CLIENT.is_shutdown() and (deadline is None or time.monotonic() < deadline):
        answered = contact_service(state.CLIENT.master(), resolved, timeout=_PROBE_TIMEOUT)
        if answered:
            if failed:
                loginfo(f"wait_for_service({resolved}): finally were able to contact service")
            return
        if answered is False:
            failed = True
            logwarn_throttle(
                10, f"wait_for_service({resolved}): failed to contact, will keep trying"
            )
        state.CLIENT.shutdown_event.wait(_POLL)
    if state.CLIENT.is_shutdown():
        raise ROSInterruptException("rospy shutdown")
    raise ROSException(f"timeout exceeded while waiting for service {resolved}")


__all__ = ["Service", "ServiceException", "ServiceProxy", "wait_for_service"]
