"""The rosbridge v2 protocol for one client, sans-I/O: decoded frames in, frames and events out.

Implements ROSBRIDGE_PROTOCOL.md (rosbridge_suite 0.11): ``advertise``, ``unadvertise``,
``publish``, ``subscribe`` (``type``, ``throttle_rate``, ``queue_length``, ``fragment_size``,
``compression`` none/png/cbor/cbor-raw), ``unsubscribe``, ``call_service``,
``advertise_service``, ``unadvertise_service``, ``service_response``, ``set_level``,
``fragment`` (both ways), ``auth``, and ``status`` going out.

The rules, and what rosbridge_suite did instead:

- Every request that cannot be carried out is answered with a ``status`` of level ``error``
  naming what is wrong (truncated or non-object JSON, no op, unknown op, a field missing or of
  the wrong kind, an unknown type, a value that does not fit its field, a message over the
  size limit). rosbridge_suite logged most of these on the server only. The session goes on.
- ``set_level`` (``none``, ``error``, ``warning``, ``info``) filters the statuses this client
  gets; ``error`` at first, as in rosbridge.
- With a token set, nothing but ``auth`` is served until the client authenticates
  (`rosx.bridge.safety`); a wrong one closes the connection (1008).

This module knows no socket, thread, clock or graph: times come in as arguments, and what
needs the graph leaves as an event (`rosx.bridge.ops`) whose outcome comes back through
`publish_typed`, `service_done`, `service_failed` or `error`.
"""

from __future__ import annotations

import json
from typing import TYPE_CHECKING, Any

from rosx.bridge import ops
from rosx.bridge.convert import ConversionError, from_json, json_values
from rosx.bridge.fragments import FragmentError, Reassembly, fragment_frames
from rosx.bridge.requests import RequestError, check_fields, excerpt, kind, message_class
from rosx.bridge.safety import check_auth
from rosx.bridge.subscriptions import SubscriptionOptions, TopicSubscriptions
from rosx.msg.codec.classes import get_service_class
from rosx.msg.store import UnknownTypeError

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx.bridge.outgoing import Outgoing
    from rosx.msg.codec.message import Message, ServiceDefinition
    from rosx.msg.codec.rostime import Time

LEVELS = {"none": 0, "error": 1, "warning": 2, "info": 3}
COMPRESSIONS = ("none", "png", "cbor", "cbor-raw")
#: The largest frame (or reassembled fragments) a client may send, by default: 32 MiB holds a
#: 4K camera image in base64 JSON, and stops a runaway client well before memory does.
DEFAULT_MAX_MESSAGE = 32 << 20


class Session:
    """One client's rosbridge session. See the module docstring.

    Args:
        token: The secret a client must show with ``auth`` first (None: no authentication).
        max_message: The largest message accepted, in bytes (after reassembling fragments).
        client: The client's address as the server saw it (for ``auth``'s check).
    """

    def __init__(
        self,
        *,
        token: str | None = None,
        max_message: int = DEFAULT_MAX_MESSAGE,
        client: str = "",
    ) -> None:
        self.level = LEVELS["error"]
        self.token = token
        self.authenticated = token is None
        self.client = client
        self.max_message = max_message
        self.advertised: dict[str, type[Message]] = {}
        self.topics: dict[str, TopicSubscriptions] = {}
        self.services: dict[str, type[ServiceDefinition]] = {}
        self.pending: dict[str, str] = {}  # request id → service, calls waiting for the client
        self._next_request = 1
        self._next_fragment = 1
        self._reassembly = Reassembly(max_message)
        self._handlers: dict[str, Callable[[dict[str, Any], Time], ops.Reaction]] = {
            "advertise": self._advertise,
            "unadvertise": self._unadvertise,
            "publish": self._publish,
            "subscribe": self._subscribe,
            "unsubscribe": self._unsubscribe,
            "call_service": self._call_service,
            "advertise_service": self._advertise_service,
            "unadvertise_service": self._unadvertise_service,
            "service_response": self._service_response,
            "set_level": self._set_level,
            "fragment": self._fragment,
            "auth": self._auth,
        }

    # -- input from the client ---------------------------------------------------------------

    def receive(self, data: str | bytes, now: Time) -> ops.Reaction:
        """Handle one frame from the client, received at ``now`` (the graph's time)."""
        if len(data) > self.max_message:
            return self.error(
                f"Message of {len(data)} bytes refused: the limit is {self.max_message} bytes"
            )
        if isinstance(data, bytes):
            return self.receive_cbor(data, now)
        try:
            request = json.loads(data)
        except (ValueError, RecursionError) as exc:  # RecursionError: nested too deep
            return self.error(f"Invalid JSON ({exc}): {excerpt(data)}")
        return self.handle(request, now)

    def receive_cbor(self, data: bytes, now: Time) -> ops.Reaction:
        """A binary frame: a request in CBOR (the encoding rosbridge sends back)."""
        import cbor2  # noqa: PLC0415 - only binary frames pay for it

        try:
            request = cbor2.loads(data)
        except Exception as exc:  # cbor2 raises several kinds for malformed input
            return self.error(f"Invalid CBOR in a binary frame ({exc})")
        return self.handle(request, now)

    def handle(self, request: object, now: Time) -> ops.Reaction:
        """Handle one decoded request."""
        if not isinstance(request, dict):
            return self.error(
                f"Expected a JSON object with an 'op' field but received {kind(request)}"
            )
        rid = request.get("id")
        if not isinstance(rid, str | int | float | None):  # ids key subscriptions and fragments
            return self.error(f"Expected field id to be a string. Invalid value: {kind(rid)}")
        op = request.get("op")
        if op is None:
            return self.error(
                "Received a message without an op.  All messages require 'op' field with "
                f"value one of: {sorted(self._handlers)}",
                rid,
            )
        if not isinstance(op, str) or op not in self._handlers:
            return self.error(
                f"Unknown operation: {op}.  Allowed operations: {sorted(self._handlers)}", rid
            )
        if not self.authenticated and op != "auth":
            return self.error(f"{op}: not authenticated: send an 'auth' op first", rid)
        try:
            check_fields(op, request)
            return self._handlers[op](request, now)
        except (RequestError, ConversionError, FragmentError) as exc:
            return self.error(f"{op}: {exc}", rid)

    # -- statuses ----------------------------------------------------------------------------

    def status(self, level: str, text: str, rid: object = None) -> ops.Reaction:
        """A ``status`` frame, if this client's level lets ``level`` through."""
        reaction = ops.Reaction()
        if 0 < LEVELS[level] <= self.level:
            frame: dict[str, Any] = {"op": "status", "level": level, "msg": text}
            if rid is not None:
                frame["id"] = rid
            reaction.frames.append(json.dumps(frame))
        return reaction

    def error(self, text: str, rid: object = None) -> ops.Reaction:
        """An ``error`` status, and the error for the server's log (rosbridge_suite logs what
        it refuses, and only that)."""
        reaction = self.status("error", text, rid)
        reaction.errors.append(text if rid is None else f"[id: {rid}] {text}")
        return reaction

    # -- topics ------------------------------------------------------------------------------

    def _advertise(self, request: dict[str, Any], now: Time) -> ops.Reaction:
        topic, type_name = request["topic"], request["type"]
        msg_class = message_class(type_name)
        known = self.advertised.get(topic)
        if known is not None and known._type != msg_class._type:
            raise RequestError(
                f"{topic} is already advertised by this client with type {known._type}"
            )
        self.advertised[topic] = msg_class
        reaction = self.status("info", f"Advertised {topic}", request.get("id"))
        if known is None:
            event = ops.Advertise(
                topic, msg_class, request.get("latch", False), request.get("queue_size", 100)
            )
            reaction.events.append(event)
        return reaction

    def _unadvertise(self, request: dict[str, Any], now: Time) -> ops.Reaction:
        topic = request["topic"]
        if self.advertised.pop(topic, None) is None:
            return self.status(
                "warning",
                f"unadvertise: {topic} is not advertised by this client",
                request.get("id"),
            )
        reaction = self.status("info", f"Unadvertised {topic}", request.get("id"))
        reaction.events.append(ops.Unadvertise(topic))
        return reaction

    def _publish(self, request: dict[str, Any], now: Time) -> ops.Reaction:
        topic = request["topic"]
        msg_class = self.advertised.get(topic)
        if msg_class is None:
            return ops.Reaction(
                events=[ops.PublishUntyped(topic, request["msg"], request.get("id"))]
            )
        message = from_json(msg_class, request["msg"], stamp=now)
        return ops.Reaction(events=[ops.Publish(topic, message)])

    def publish_typed(
        self, topic: str, type_name: str | None, values: Any, rid: object, now: Time
    ) -> ops.Reaction:
        """Carry out a `PublishUntyped`: the graph says ``topic`` has ``type_name`` (None:
        nobody publishes or subscribes to it). The client publishes as if it had advertised."""
        if type_name is None:
            return self.error(
                f"publish: Cannot infer topic type for topic {topic} as it is not yet "
                "advertised: advertise it first",
                rid,
            )
        try:
            msg_class = message_class(type_name)
            message = from_json(msg_class, values, stamp=now)
        except (RequestError, ConversionError) as exc:
            return self.error(f"publish: {exc}", rid)
        self.advertised[topic] = msg_class
        return ops.Reaction(
            events=[ops.Advertise(topic, msg_class, False, 100), ops.Publish(topic, message)]
        )

    def _subscribe(self, request: dict[str, Any], now: Time) -> ops.Reaction:
        topic = request["topic"]
        type_name = request.get("type") or None
        if type_name is not None:
            message_class(type_name)
        compression = request.get("compression", "none")
        if compression not in COMPRESSIONS:
            raise RequestError(
                f"Unknown compression {compression!r}: one of {', '.join(COMPRESSIONS)}"
            )
        options = SubscriptionOptions(
            throttle_ms=float(request.get("throttle_rate", 0)),
            queue_length=request.get("queue_length", 0),
            fragment_size=request.get("fragment_size"),
            compression=compression,
        )
        entry = self.topics.get(topic)
        reaction = self.status("info", f"Subscribed to {topic}", request.get("id"))
        if entry is None:
            entry = self.topics[topic] = TopicSubscriptions()
            reaction.events.append(ops.Subscribe(topic, type_name, request.get("id")))
        entry.by_id[request.get("id")] = options
        entry.combine(options)
        return reaction

    def _unsubscribe(self, request: dict[str, Any], now: Time) -> ops.Reaction:
        topic, rid = request["topic"], request.get("id")
        entry = self.topics.get(topic)
        if entry is None:
            return self.status("warning", f"unsubscribe: not subscribed to {topic}", rid)
        if rid is None or rid not in entry.by_id:
            entry.by_id.clear()
        else:
            del entry.by_id[rid]
        reaction = self.status("info", f"Unsubscribed from {topic}", rid)
        if entry.by_id:
            entry.combine(next(reversed(entry.by_id.values())))
        else:
            del self.topics[topic]
            reaction.events.append(ops.Unsubscribe(topic))
        return reaction

    def unsubscribe_all(self, topic: str) -> None:
        """Forget every subscription to ``topic`` (the shell could not subscribe)."""
        self.topics.pop(topic, None)

    def options(self, topic: str) -> SubscriptionOptions | None:
        """What this client's subscriptions to ``topic`` add up to (None: not subscribed)."""
        entry = self.topics.get(topic)
        return None if entry is None else entry.options

    def deliver(self, message: Outgoing, now: float) -> list[ops.Frame | ops.Pieces]:
        """The frames that carry ``message`` to this client, at monotonic time ``now``
        (seconds); none when not subscribed or within the topic's ``throttle_rate``."""
        entry = self.topics.get(message.topic)
        if entry is None:
            return []
        options = entry.options
        if options.throttle_ms and (now - entry.last_sent) * 1000.0 < options.throttle_ms:
            return []
        entry.last_sent = now
        compression = options.compression
        try:
            if compression == "cbor-raw":
                return [message.publish_cbor_raw()]
            if compression == "cbor":
                return [message.publish_cbor()]
            text = message.publish_json()
        except Exception as exc:  # a message the codec cannot read must not end the session
            return [*self.error(f"Cannot send a message of {message.topic}: {exc}").frames]
        if compression == "png":
            from rosx.bridge.png import png_frame  # noqa: PLC0415 - Pillow, when asked for

            text = png_frame(text)
        return [*self._maybe_fragment(text, options.fragment_size)]

    def _maybe_fragment(self, text: str, size: int | None) -> list[ops.Frame]:
        if not size or len(text) <= size:
            return [text]
        mid = f"fragment:{self._next_fragment}"
        self._next_fragment += 1
        return list(fragment_frames(text, size, mid))

    # -- services the client calls ------------------------------------------------------------

    def _call_service(self, request: dict[str, Any], now: Time) -> ops.Reaction:
        service = request["service"]
        return ops.Reaction(
            events=[ops.CallService(service, request.get("args"), request.get("id"))]
        )

    def service_request_message(
        self, call: ops.CallService, service_class: type[ServiceDefinition], now: Time
    ) -> Message:
        """The request of ``call`` (args a list in field order, or an object).

        Raises:
            ConversionError: the args do not fit the request.
        """
        request_class = service_class._request_class
        args = call.args
        if args is None:
            args = {}
        elif isinstance(args, list):
            spec = request_class._spec
            names = [] if spec is None else [f.name for f in spec.fields]
            if len(args) > len(names):
                raise ConversionError(
                    f"{request_class._type} has {len(names)} fields, but {len(args)} args came"
                )
            args = dict(zip(names, args, strict=False))
        return from_json(request_class, args, stamp=now)

    def service_done(self, call: ops.CallService, response: Message) -> list[ops.Frame]:
        """The ``service_response`` frames of a call that succeeded."""
        frame: dict[str, Any] = {
            "op": "service_response",
            "service": call.service,
            "values": json_values(response),
            "result": True,
        }
        if call.id is not None:
            frame["id"] = call.id
        return [json.dumps(frame, allow_nan=False)]

    def service_failed(self, call: ops.CallService, error: str) -> ops.Reaction:
        """A failed call: an error status, then ``service_response`` with result false (and
        the error for the server's log)."""
        reaction = self.error(f"call_service {call.service}: {error}", call.id)
        frames = reaction.frames
        frame: dict[str, Any] = {
            "op": "service_response",
            "service": call.service,
            "values": error,
            "result": False,
        }
        if call.id is not None:
            frame["id"] = call.id
        frames.append(json.dumps(frame))
        return reaction

    # -- services the client serves ------------------------------------------------------------

    def _advertise_service(self, request: dict[str, Any], now: Time) -> ops.Reaction:
        service, type_name = request["service"], request["type"]
        try:
            service_class = get_service_class(type_name)
        except (UnknownTypeError, ValueError):
            raise RequestError(f"Unknown service type {type_name}") from None
        reaction = ops.Reaction()
        if service in self.services:
            reaction = self.status(
                "warning", f"Duplicate service advertised. Overwriting {service}."
            )
            reaction.events.append(ops.UnadvertiseService(service))
        self.services[service] = service_class
        reaction.extend(self.status("info", f"Advertised service {service}.", request.get("id")))
        reaction.events.append(ops.AdvertiseService(service, service_class))
        return reaction

    def _unadvertise_service(self, request: dict[str, Any], now: Time) -> ops.Reaction:
        service = request["service"]
        if self.services.pop(service, None) is None:
            raise RequestError(f"Service {service} has not been advertised via rosbridge.")
        reaction = self.status("info", f"Unadvertised service {service}.", request.get("id"))
        for request_id in [r for r, s in self.pending.items() if s == service]:
            del self.pending[request_id]
            reaction.events.append(
                ops.ServiceReply(request_id, None, f"service {service} was unadvertised")
            )
        reaction.events.append(ops.UnadvertiseService(service))
        return reaction

    def service_request(self, service: str, request: Message) -> tuple[str, list[ops.Frame]]:
        """A call of ``service`` (served by this client) to send it: its id and frames."""
        request_id = f"service_request:{service}:{self._next_request}"
        self._next_request += 1
        self.pending[request_id] = service
        frame = {
            "op": "call_service",
            "id": request_id,
            "service": service,
            "args": json_values(request),
        }
        return request_id, [json.dumps(frame, allow_nan=False)]

    def _service_response(self, request: dict[str, Any], now: Time) -> ops.Reaction:
        service, request_id = request["service"], request["id"]
        service_class = self.services.get(service)
        if service_class is None:
            raise RequestError(f"Service {service} has not been advertised via rosbridge.")
        if self.pending.pop(request_id, None) is None:
            raise RequestError(f"no call of {service} waits for an answer with id {request_id}")
        if not request["result"]:
            values = request.get("values")
            why = values if isinstance(values, str) else "the service's client answered false"
            return ops.Reaction(events=[ops.ServiceReply(request_id, None, why)])
        try:
            values = request.get("values") or {}
            response = from_json(service_class._response_class, values, stamp=now)
        except ConversionError as exc:
            reaction = self.error(f"service_response: {exc}", request_id)
            reaction.events.append(ops.ServiceReply(request_id, None, str(exc)))
            return reaction
        return ops.Reaction(events=[ops.ServiceReply(request_id, response, None)])

    # -- the rest ------------------------------------------------------------------------------

    def _set_level(self, request: dict[str, Any], now: Time) -> ops.Reaction:
        level = request["level"]
        if level not in LEVELS:
            raise RequestError(f"Unknown level {level!r}: one of {', '.join(LEVELS)}")
        self.level = LEVELS[level]
        return self.status("info", f"Status level set to {level}", request.get("id"))

    def _fragment(self, request: dict[str, Any], now: Time) -> ops.Reaction:
        whole = self._reassembly.add(
            request["id"], request["num"], request["total"], request["data"]
        )
        if whole is None:
            return ops.Reaction()
        return self.receive(whole, now)

    def _auth(self, request: dict[str, Any], now: Time) -> ops.Reaction:
        if self.token is None:
            return self.status("info", "auth: this server needs no authentication")
        if check_auth(self.token, request, now.secs):
            self.authenticated = True
            return self.status("info", "Authenticated")
        reaction = self.error("auth: authentication failed")
        reaction.events.append(ops.Close(1008, "authentication failed"))
        return reaction


__all__ = ["DEFAULT_MAX_MESSAGE", "LEVELS", "RequestError", "Session", "SubscriptionOptions"]
