"""How turtlesim's programs behave as roscpp nodes, on top of `rosx.node`.

turtlesim and its tutorials are C++ programs; where roscpp differs from rospy (whose habits
`rosx.node.Node` follows), these helpers give roscpp's behaviour:

* `NodeArgs.parse`: a command line's remapping arguments as ``ros::init`` reads them, with
  ``_param:=value`` typed as roscpp types it (int, then double, then bool, else string);
* `sub_name`: a name under a ``ros::NodeHandle(ns)`` (the namespace resolved and remapped
  first, then the name under it, remapped again), e.g. ``input/pose`` in mimic;
* `advertise_service`: a service with roscpp's failure semantics. A callback that returns
  ``None`` (false in C++) answers ``ok=0`` with an **empty** error text, so ROS 1's rosservice
  prints ``responded with an error: b''``; one that raises answers with the exception's text,
  after logging ``Exception thrown while processing service call: <text>`` at ERROR;
* `param_int`: ``NodeHandle::param<int>``'s reading of a parameter value.
"""

from __future__ import annotations

import math
import re
from typing import TYPE_CHECKING, Any, NamedTuple

from rosx.names import ns_join, parse_remap_args
from rosx.node import ERROR, Node
from rosx.node.service import ServiceServer, to_response
from rosx.wire.rosrpc import encode_error, encode_response

if TYPE_CHECKING:
    from collections.abc import Callable, Mapping, Sequence

    from rosx.msg.codec.message import ServiceDefinition
    from rosx.node import ServiceHandle

_LEADING_FLOAT = re.compile(
    r"\s*[+-]?(\d+\.?\d*([eE][+-]?\d+)?|\.\d+([eE][+-]?\d+)?|inf|nan)", re.I
)
_INT32 = re.compile(r"[+-]?[0-9]+")
_DOUBLE = re.compile(r"[+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]+)?")


def typed_param(text: str) -> Any:
    """A ``_param:=text`` value typed as roscpp's ``ros::init`` does it."""
    if _INT32.fullmatch(text) and -(2**31) <= int(text) < 2**31:
        return int(text)
    if _DOUBLE.fullmatch(text):
        return float(text)
    if text in ("true", "True", "TRUE"):
        return True
    if text in ("false", "False", "FALSE"):
        return False
    return text


def atof(text: str) -> float:
    """C's ``atof``, as the C++ programs read numbers from their command lines: the number at
    the start of ``text``, 0.0 when there is none."""
    found = _LEADING_FLOAT.match(text)
    return float(found.group(0)) if found else 0.0


class NodeArgs(NamedTuple):
    """What a roscpp node's command line says about the node (remapping arguments only)."""

    name: str
    namespace: str | None
    master_uri: str | None
    host: str | None
    remappings: Mapping[str, str]
    params: Mapping[str, Any]
    argv: Sequence[str]

    @classmethod
    def parse(cls, argv: Sequence[str], default_name: str) -> NodeArgs:
        """Read ``argv`` (without the program name) for a node named ``default_name``."""
        args = parse_remap_args(argv)
        return cls(
            name=args.name or default_name,
            namespace=args.ns,
            master_uri=args.master,
            host=args.hostname or args.ip,
            remappings=dict(args.remappings),
            params={key: typed_param(value) for key, value in args.params.items()},
            argv=tuple(args.argv),
        )

    def make_node(self, environ: Mapping[str, str]) -> Node:
        """A `Node` (not started) as these arguments describe it, quiet on the console; its
        messages' ``header.seq`` counts from 0, as roscpp's do."""
        return Node(
            self.name,
            namespace=self.namespace,
            master_uri=self.master_uri,
            remappings=self.remappings,
            host=self.host,
            environ=environ,
            console=None,
            first_seq=0,
        )

    def set_private_params(self, node: Node) -> None:
        """Set the ``_param:=value`` parameters, as ``ros::init`` does before anything else."""
        for key, value in self.params.items():
            node.params.set("~" + key, value)


def sub_name(node: Node, namespace: str, name: str) -> str:
    """``name`` under ``ros::NodeHandle(namespace)``: both levels resolved and remapped."""
    return node.resolve(ns_join(node.resolve(namespace), name))


def param_int(value: Any, default: int) -> int:
    """``NodeHandle::param<int>``: ints as they are, doubles rounded half up, else ``default``."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return default
    if isinstance(value, int):
        return value
    if not math.isfinite(value):
        return default
    return int(math.floor(value) if math.fmod(value, 1.0) < 0.5 else math.ceil(value))


class _RoscppServer(ServiceServer):
    """A `ServiceServer` answering failures as roscpp does (see the module docstring)."""

    def handle(self, payload: bytes, header: dict[str, str]) -> bytes:
        try:
            request = self.service_class._request_class().deserialize(payload)
            request._connection_header = header
            result = self.handler(request)
            if result is None:
                return encode_error("")
            response = to_response(result, self.service_class._response_class)
            parts: list[bytes] = []
            response.serialize(_Parts(parts))
            return encode_response(b"".join(parts))
        except Exception as exc:  # the caller gets the text; the server goes on
            return encode_error(str(exc))


class _Parts:
    __slots__ = ("write",)

    def __init__(self, parts: list[bytes]) -> None:
        self.write = parts.append


def advertise_service(
    node: Node,
    name: str,
    service_class: type[ServiceDefinition],
    callback: Callable[[Any], object],
    log: Callable[[int, str], None],
) -> ServiceHandle:
    """Serve ``name`` with roscpp's failure semantics; ``log`` receives the ERROR records."""

    def handler(request: Any) -> object:
        try:
            return callback(request)
        except Exception as exc:
            log(ERROR, f"Exception thrown while processing service call: {exc}")
            raise

    return node.advertise_service(name, service_class, handler, server_class=_RoscppServer)
