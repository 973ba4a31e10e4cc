"""What rosservice's sub-commands share: the master, service lookups, probes and type classes.

Services do not register their type with the master: like ROS 1's rosservice, rosx asks the
server itself with a probe (`rosx.node.service_client.probe_service`). Every failure of a lookup
is an error with ROS 1's text and rosservice's status 2, including the master being down (the
core's errors are worded by `rosx_commands.errors`).
"""

from __future__ import annotations

from rosx.graph.state import registrations
from rosx.names.resolution import make_global_ns
from rosx.names.script import ros_namespace, script_resolve_name
from rosx_commands.context import CommandError, Environment

TYPE_CHECKING = False
if TYPE_CHECKING:
    from rosx.msg.codec.message import ServiceDefinition
    from rosx.msg.store import TypeStore

CALLER_ID = "/rosservice"
#: rosservice's exit status for every error it reports as ``ERROR: …`` (ROSServiceException).
SERVICE_ERROR = 2


class Services:
    """One rosservice run: its environment, the master and (lazily) the type store."""

    def __init__(self, env: Environment) -> None:
        self.env = env
        self.master = env.master(CALLER_ID)
        self._store: TypeStore | None = None

    @property
    def store(self) -> TypeStore:
        """The type store of this environment's package path, made on first use (typed commands
        only)."""
        if self._store is None:
            from rosx.msg.store import TypeStore  # noqa: PLC0415 - only for typed commands

            self._store = TypeStore.from_environ(self.env.environ)
        return self._store

    def resolve(self, name: str) -> str:
        """A service name typed by the user, resolved as ROS 1's tools do."""
        return script_resolve_name("rosservice", name, ros_namespace(self.env.environ))

    def services(self, namespace: str | None = None) -> list[tuple[str, list[str]]]:
        """Services with the nodes providing them, in the master's order, in ``namespace``."""
        state = registrations(self.master)
        rows = [(name, list(nodes)) for name, nodes in state.services.items()]
        if namespace:
            prefix = make_global_ns(namespace)
            rows = [r for r in rows if r[0] == namespace or r[0].startswith(prefix)]
        return rows

    def node_of(self, name: str) -> str | None:
        """The first node providing ``name``."""
        for service, nodes in self.services():
            if service == name:
                return nodes[0] if nodes else None
        return None

    def uri_of(self, name: str) -> str | None:
        """The ``rosrpc://`` URI of ``name``, or ``None`` if no node provides it."""
        return self.master.lookup_service(name)

    def type_of(self, name: str) -> str | None:
        """The type the server of ``name`` states in answer to a probe, or ``None``.

        Raises:
            ServiceError: the server cannot be reached.
        """
        from rosx.node.service_client import probe_service  # noqa: PLC0415 - not for list

        uri = self.uri_of(name)
        if uri is None:
            return None
        return probe_service(self.master, name, uri=uri).get("type")

    def service_class(self, name: str) -> type[ServiceDefinition]:
        """The class of service ``name``'s type, found by probing it.

        Raises:
            CommandError: the service is unknown, unreachable, or of a type not installed.
        """
        service_type = self.type_of(name)
        if not service_type:
            if name not in [s for s, _ in self.services()]:
                raise CommandError(f"ERROR: Service [{name}] is not available.", SERVICE_ERROR)
            raise CommandError(
                f"ERROR: Unable to determine type of service [{name}].", SERVICE_ERROR
            )
        from rosx.msg.codec.classes import get_service_class  # noqa: PLC0415 - code generation
        from rosx.msg.store import UnknownTypeError  # noqa: PLC0415 - the type store loads on first use

        candidates = [service_type]
        if service_type.endswith("Request"):
            # Some servers state their request type: try the service it belongs to too.
            candidates.append(service_type[: -len("Request")])
        for candidate in candidates:
            try:
                return get_service_class(candidate, self.store)
            except UnknownTypeError:
                continue
        package = service_type.partition("/")[0] if "/" in service_type else None
        raise CommandError(
            f"ERROR: Unable to load type [{service_type}].\nHave you typed 'make' in [{package}]?",
            SERVICE_ERROR,
        )


def request_args(service_class: type[ServiceDefinition]) -> str:
    """The request's field names, as ``rosservice args`` prints them."""
    return " ".join(service_class._request_class.__slots__)
