"""The Foxglove WebSocket protocol (``foxglove.websocket.v1``) for one client, sans-I/O.

Implements the protocol of foxglove/ws-protocol as Foxglove Studio and Lichtblick speak it,
for a ROS 1 graph: the server's topics are channels with the ``ros1`` encoding and their
``ros1msg`` schemas (the full definition text), messages travel as their ROS 1 bytes, and
the client may publish (``clientPublish``), call services (``services``: the request and
response as ROS 1 bytes), read and set parameters (``parameters``), and follow ``/clock``
(``time``, when ``/use_sim_time`` is set).

Text frames are JSON (``serverInfo``, ``advertise``, ``status``…), binary frames start with
an opcode byte, then little-endian fields:

- server → client: 1 message data (u32 subscription, u64 timestamp ns, payload), 2 time
  (u64 ns), 3 service call response (u32 service, u32 call, u32 encoding length, encoding,
  payload);
- client → server: 1 message data (u32 channel, payload), 2 service call request (as 3).

Like `rosx.bridge.protocol`, this module only decides: what needs the graph leaves as an
event (below), and the answers come back through the methods that make frames.
"""

from __future__ import annotations

import json
import struct
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, ClassVar

from rosx.msg.codec.classes import get_message_class, get_service_class

if TYPE_CHECKING:
    from collections.abc import Callable, Mapping

    from rosx.bridge.ops import Pieces
    from rosx.msg.codec.message import Message

SUBPROTOCOL = "foxglove.websocket.v1"
ENCODING = "ros1"
SCHEMA_ENCODING = "ros1msg"
INFO, WARNING, ERROR = 0, 1, 2

_MESSAGE_DATA = struct.Struct("<BIQ")
_TIME = struct.Struct("<BQ")
_CALL = struct.Struct("<BIII")
_CLIENT_DATA = struct.Struct("<BI")


# -- events for the shell -------------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class Subscribe:
    """The client's first subscription to ``topic``."""

    topic: str


@dataclass(frozen=True, slots=True)
class Unsubscribe:
    """The client's last subscription to ``topic`` went."""

    topic: str


@dataclass(frozen=True, slots=True)
class Advertise:
    """The client publishes ``topic`` with ``msg_class``."""

    topic: str
    msg_class: type[Message]


@dataclass(frozen=True, slots=True)
class Unadvertise:
    """The client stops publishing ``topic``."""

    topic: str


@dataclass(frozen=True, slots=True)
class PublishRaw:
    """Publish ``payload`` (ROS 1 bytes) on ``topic``, which the client advertised."""

    topic: str
    payload: bytes


@dataclass(frozen=True, slots=True)
class CallService:
    """Call ``service`` of ``type`` with the serialized request; answer with `call_response`
    or `call_failure` for ``service_id``/``call_id``."""

    service: str
    type: str
    service_id: int
    call_id: int
    payload: bytes


@dataclass(frozen=True, slots=True)
class GetParameters:
    """Read ``names`` (none: every parameter); answer with `parameter_values` and ``id``."""

    names: tuple[str, ...]
    id: str | None


@dataclass(frozen=True, slots=True)
class SetParameters:
    """Set each name to its value; answer with `parameter_values` when ``id`` is given."""

    values: tuple[tuple[str, Any], ...]
    id: str | None


Event = (
    Subscribe | Unsubscribe | Advertise | Unadvertise | PublishRaw | CallService
    | GetParameters | SetParameters
)  # fmt: skip
Frame = str | bytes


@dataclass(slots=True)
class Reaction:
    """Frames for the client and events for the shell, from one input."""

    frames: list[Frame] = field(default_factory=list)
    events: list[Event] = field(default_factory=list)


class FoxgloveSession:
    """One client's Foxglove session. See the module docstring.

    Args:
        name: The server's name in ``serverInfo``.
        sim_time: Whether ``/use_sim_time`` is set (the ``time`` capability).
    """

    def __init__(self, *, name: str = "rosx", sim_time: bool = False) -> None:
        self.name = name
        self.sim_time = sim_time
        self.channels: dict[str, int] = {}  # topic → channel id
        self.channel_types: dict[int, str] = {}
        self.services: dict[str, int] = {}  # service → id
        self.service_types: dict[int, tuple[str, str]] = {}  # id → (name, type)
        self.subscriptions: dict[int, str] = {}  # subscription id → topic
        self.client_channels: dict[int, str] = {}  # client channel id → topic
        self._next_channel = 1
        self._next_service = 1

    # -- the server's side -------------------------------------------------------------------

    def hello(self) -> list[Frame]:
        """The ``serverInfo`` frame that opens the session."""
        capabilities = ["clientPublish", "parameters", "services"]
        if self.sim_time:
            capabilities.append("time")
        info = {
            "op": "serverInfo",
            "name": self.name,
            "capabilities": capabilities,
            "supportedEncodings": [ENCODING],
            "metadata": {"ROS_DISTRO": "noetic"},
        }
        return [json.dumps(info)]

    def update_graph(self, topics: Mapping[str, str], services: Mapping[str, str]) -> list[Frame]:
        """Advertise what is new in the graph (``topics``/``services``: name → type) and
        withdraw what went. Types this server cannot describe are left out."""
        frames: list[Frame] = []
        gone = [t for t, cid in self.channels.items() if topics.get(t) != self.channel_types[cid]]
        if gone:
            ids = [self.channels.pop(t) for t in gone]
            for cid in ids:
                del self.channel_types[cid]
            frames.append(json.dumps({"op": "unadvertise", "channelIds": ids}))
        added = []
        for topic, type_name in sorted(topics.items()):
            if topic in self.channels:
                continue
            try:
                schema = get_message_class(type_name)._full_text
            except Exception:  # a type only its publisher knows: no channel for it
                continue
            cid = self._next_channel
            self._next_channel += 1
            self.channels[topic] = cid
            self.channel_types[cid] = type_name
            added.append(
                {
                    "id": cid,
                    "topic": topic,
                    "encoding": ENCODING,
                    "schemaName": type_name,
                    "schema": schema,
                    "schemaEncoding": SCHEMA_ENCODING,
                }
            )
        if added:
            frames.append(json.dumps({"op": "advertise", "channels": added}))
        frames += self._update_services(services)
        return frames

    def _update_services(self, services: Mapping[str, str]) -> list[Frame]:
        frames: list[Frame] = []
        gone = [
            s for s, sid in self.services.items() if services.get(s) != self.service_types[sid][1]
        ]
        if gone:
            ids = [self.services.pop(s) for s in gone]
            for sid in ids:
                del self.service_types[sid]
            frames.append(json.dumps({"op": "unadvertiseServices", "serviceIds": ids}))
        added = []
        for name, type_name in sorted(services.items()):
            if name in self.services or not type_name:
                continue
            try:
                service_class = get_service_class(type_name)
            except Exception:  # a type only its server knows: not offered
                continue
            sid = self._next_service
            self._next_service += 1
            self.services[name] = sid
            self.service_types[sid] = (name, type_name)
            request = service_class._request_class
            response = service_class._response_class
            added.append(
                {
                    "id": sid,
                    "name": name,
                    "type": type_name,
                    "request": _schema(request),
                    "response": _schema(response),
                    "requestSchema": request._full_text,
                    "responseSchema": response._full_text,
                }
            )
        if added:
            frames.append(json.dumps({"op": "advertiseServices", "services": added}))
        return frames

    def deliver(self, topic: str, payload: bytes, stamp_ns: int) -> list[Frame | Pieces]:
        """The ``message data`` frames of one message of ``topic``, one per subscription (the
        payload beside its head, not copied)."""
        return [
            (_MESSAGE_DATA.pack(1, sub_id, stamp_ns), payload)
            for sub_id, subscribed in self.subscriptions.items()
            if subscribed == topic
        ]

    def time(self, stamp_ns: int) -> Frame:
        """A ``time`` frame (``/clock``)."""
        return _TIME.pack(2, stamp_ns)

    def call_response(self, call: CallService, payload: bytes) -> Frame:
        """The ``service call response`` frame of a call that succeeded."""
        encoding = ENCODING.encode()
        head = _CALL.pack(3, call.service_id, call.call_id, len(encoding))
        return head + encoding + payload

    def call_failure(self, call: CallService, message: str) -> Frame:
        """The ``serviceCallFailure`` frame of a call that failed."""
        failure = {
            "op": "serviceCallFailure",
            "serviceId": call.service_id,
            "callId": call.call_id,
            "message": message,
        }
        return json.dumps(failure)

    def parameter_values(self, values: Mapping[str, Any], rid: str | None) -> Frame:
        """A ``parameterValues`` frame."""
        params = [_parameter(name, value) for name, value in sorted(values.items())]
        frame: dict[str, Any] = {"op": "parameterValues", "parameters": params}
        if rid is not None:
            frame["id"] = rid
        return json.dumps(frame)

    def status(self, level: int, message: str) -> Frame:
        """A ``status`` frame."""
        return json.dumps({"op": "status", "level": level, "message": message})

    # -- the client's side ---------------------------------------------------------------------

    def receive(self, data: str | bytes) -> Reaction:
        """Handle one frame from the client; what cannot be done gets an error status."""
        try:
            if isinstance(data, bytes):
                return self._binary(data)
            request = json.loads(data)
            if not isinstance(request, dict) or not isinstance(request.get("op"), str):
                raise _RefusalError("Expected a JSON object with an op")
            handler = self._ops.get(request["op"])
            if handler is None:
                raise _RefusalError(f'Unrecognized client opcode "{request["op"]}"')
            return handler(self, request)
        except (ValueError, RecursionError) as exc:  # JSON errors (nesting), _RefusalError
            return Reaction(frames=[self.status(ERROR, str(exc))])
        except (KeyError, TypeError) as exc:
            return Reaction(frames=[self.status(ERROR, f"Invalid request: missing or wrong {exc}")])

    def _subscribe(self, request: dict[str, Any]) -> Reaction:
        reaction = Reaction()
        by_id = {cid: topic for topic, cid in self.channels.items()}
        for sub in request["subscriptions"]:
            sub_id, cid = int(sub["id"]), int(sub["channelId"])
            topic = by_id.get(cid)
            if topic is None:
                reaction.frames.append(self.status(WARNING, f"Channel {cid} is not available"))
                continue
            if sub_id in self.subscriptions:
                reaction.frames.append(
                    self.status(ERROR, f"Subscription ID {sub_id} was already used")
                )
                continue
            if topic not in self.subscriptions.values():
                reaction.events.append(Subscribe(topic))
            self.subscriptions[sub_id] = topic
        return reaction

    def _unsubscribe(self, request: dict[str, Any]) -> Reaction:
        reaction = Reaction()
        for sub_id in request["subscriptionIds"]:
            topic = self.subscriptions.pop(int(sub_id), None)
            if topic is None:
                reaction.frames.append(self.status(WARNING, f"Unknown subscription ID {sub_id}"))
            elif topic not in self.subscriptions.values():
                reaction.events.append(Unsubscribe(topic))
        return reaction

    def _advertise(self, request: dict[str, Any]) -> Reaction:
        reaction = Reaction()
        for channel in request["channels"]:
            cid, topic, type_name = (
                int(channel["id"]),
                str(channel["topic"]),
                str(channel["schemaName"]),
            )
            if channel.get("encoding") != ENCODING:
                reaction.frames.append(
                    self.status(ERROR, f"Channel {cid}: only the {ENCODING} encoding is supported")
                )
                continue
            try:
                msg_class = get_message_class(type_name)
            except Exception:
                reaction.frames.append(
                    self.status(ERROR, f"Channel {cid}: unknown type {type_name}")
                )
                continue
            self.client_channels[cid] = topic
            reaction.events.append(Advertise(topic, msg_class))
        return reaction

    def _unadvertise(self, request: dict[str, Any]) -> Reaction:
        reaction = Reaction()
        for cid in request["channelIds"]:
            topic = self.client_channels.pop(int(cid), None)
            if topic is not None and topic not in self.client_channels.values():
                reaction.events.append(Unadvertise(topic))
        return reaction

    def _get_parameters(self, request: dict[str, Any]) -> Reaction:
        names = tuple(str(n) for n in request.get("parameterNames") or ())
        return Reaction(events=[GetParameters(names, request.get("id"))])

    def _set_parameters(self, request: dict[str, Any]) -> Reaction:
        values = tuple((str(p["name"]), p.get("value")) for p in request["parameters"])
        return Reaction(events=[SetParameters(values, request.get("id"))])

    _ops: ClassVar[dict[str, Callable[[FoxgloveSession, dict[str, Any]], Reaction]]] = {
        "subscribe": _subscribe,
        "unsubscribe": _unsubscribe,
        "advertise": _advertise,
        "unadvertise": _unadvertise,
        "getParameters": _get_parameters,
        "setParameters": _set_parameters,
    }

    def _binary(self, data: bytes) -> Reaction:
        if not data:
            raise _RefusalError("Empty binary message")
        op = data[0]
        if op == 1:
            if len(data) < _CLIENT_DATA.size:
                raise _RefusalError("Truncated message data")
            _, cid = _CLIENT_DATA.unpack_from(data)
            topic = self.client_channels.get(cid)
            if topic is None:
                raise _RefusalError(f"Channel {cid} is not advertised by this client")
            return Reaction(events=[PublishRaw(topic, data[_CLIENT_DATA.size :])])
        if op == 2:
            if len(data) < _CALL.size:
                raise _RefusalError("Truncated service call request")
            _, sid, call_id, length = _CALL.unpack_from(data)
            encoding = data[_CALL.size : _CALL.size + length].decode(errors="replace")
            known = self.service_types.get(sid)
            if known is None:
                raise _RefusalError(f"Service {sid} is not advertised")
            if encoding != ENCODING:
                raise _RefusalError(
                    f"Service call encoding {encoding} is not supported: use {ENCODING}"
                )
            payload = data[_CALL.size + length :]
            return Reaction(events=[CallService(known[0], known[1], sid, call_id, payload)])
        raise _RefusalError(f"Unrecognized client opcode {op}")


class _RefusalError(ValueError):
    """A request the session refuses; the text is the status."""


def _schema(cls: type[Message]) -> dict[str, str]:
    return {
        "encoding": ENCODING,
        "schemaName": cls._type,
        "schemaEncoding": SCHEMA_ENCODING,
        "schema": cls._full_text,
    }


def _parameter(name: str, value: Any) -> dict[str, Any]:
    if isinstance(value, bytes | bytearray):
        import base64  # noqa: PLC0415 - binary parameters are rare

        return {"name": name, "value": base64.b64encode(value).decode(), "type": "byte_array"}
    if isinstance(value, float):
        return {"name": name, "value": value, "type": "float64"}
    return {"name": name, "value": value}


__all__ = [
    "SUBPROTOCOL",
    "Advertise",
    "CallService",
    "FoxgloveSession",
    "GetParameters",
    "PublishRaw",
    "Reaction",
    "SetParameters",
    "Subscribe",
    "Unadvertise",
    "Unsubscribe",
]
