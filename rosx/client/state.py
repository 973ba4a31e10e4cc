"""The process's one rospy-style node: its command line, its `Node`, and how it shuts down.

rospy keeps one node per process in module globals; so does this layer, in `CLIENT`. The rules:

* The command line (``sys.argv`` unless `init_node` is given another) is read for remapping
  arguments on first use, as rospy reads it on import.
* Before `init_node` the process is ``<namespace>unnamed``; publishers, subscribers and services
  created then are kept in `Client.pending` and registered when the node starts.
* Shutting down (`Client.signal_shutdown`, by Ctrl-C, SIGTERM, ``rosnode kill``, a call from user
  code, or the interpreter's exit) happens once: the hooks given to ``on_shutdown`` run, then
  `Client.is_shutdown` becomes true and every sleep wakes, then the node unregisters from the
  master and closes its connections.
"""

from __future__ import annotations

import functools
import os
import sys
import threading
import traceback
from typing import TYPE_CHECKING, Any, Protocol

from rosx.names import (
    RemapArgs,
    is_private,
    make_global_ns,
    namespace_of,
    ns_join,
    parse_remap_args,
    resolve,
    ros_namespace,
)
from rosx.signals import soon

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx.master.client import MasterClient
    from rosx.node import Node

#: How long the interpreter's exit waits for a shutdown that another thread is running.
_EXIT_WAIT = 10.0


class Attachable(Protocol):
    """A publisher, subscriber or service made before the node existed."""

    def _attach(self, node: Node) -> None:
        """Register with ``node``, which has just started."""


class Client:
    """The state behind the module-level functions of the rospy-compatible API."""

    def __init__(self) -> None:
        self.lock = threading.RLock()
        self.node: Node | None = None
        self.init_args: tuple[Any, ...] | None = None
        self.shutdown_event = threading.Event()
        self.finished = threading.Event()
        self.requested = False
        self.shutdown_reason = ""
        #: The reason of the first stopping signal (`shutdown_in_background`), or "".
        self.signalled = ""
        self.client_hooks: list[Callable[[], object]] = []
        self.pending: list[Attachable] = []
        self._args: RemapArgs | None = None
        self._argv: list[str] | None = None
        self._master: MasterClient | None = None
        #: What ``rospy.get_master()`` hands out (`rosx.client.masterproxy`), made once.
        self.script_master: Any = None
        #: The caller id set by ``rospy.names._set_caller_id`` (names resolve and parameters
        #: are asked as that caller, the node's registrations stay), or None.
        self.caller_override: str | None = None

    # -- the command line --------------------------------------------------------------------

    @property
    def argv(self) -> list[str]:
        """The command line the node reads (``sys.argv`` unless `init_node` got another)."""
        return list(sys.argv) if self._argv is None else self._argv

    @property
    def args(self) -> RemapArgs:
        """The command line's remapping arguments."""
        if self._args is None:
            self._args = parse_remap_args(self.argv)
        return self._args

    def reload(self, argv: list[str]) -> None:
        """Read remapping arguments from ``argv`` instead of ``sys.argv``."""
        self._argv = list(argv)
        self._args = parse_remap_args(argv)

    # -- names -------------------------------------------------------------------------------

    def namespace(self) -> str:
        """The node's namespace (``/`` …), known before the node starts."""
        if self.caller_override is not None:
            return namespace_of(self.caller_override)
        if self.node is not None:
            return self.node.namespace
        if self.args.ns:
            return make_global_ns(self.args.ns)
        return ros_namespace(os.environ)

    def caller_id(self) -> str:
        """The node's global name; ``<namespace>unnamed`` before `init_node`."""
        if self.caller_override is not None:
            return self.caller_override
        return self.node.name if self.node is not None else self.namespace() + "unnamed"

    def resolve_name(self, name: str, caller_id: str | None = None) -> str:
        """rospy's ``resolve_name``: ``~x`` under the node, relative names in its namespace,
        then the command line's remappings once the node runs."""
        node = self.node
        if caller_id is None and node is not None and self.caller_override is None:
            return node.resolve(name)
        caller = caller_id or self.caller_id()
        remappings = node.remappings if node is not None else None
        return resolve(name, namespace_of(caller), caller, remappings, strict=False)

    def resolve_graph_name(self, name: str) -> str:
        """A topic or service name as the node will register it (rospy's rules before init).

        Raises:
            ValueError: a ``~name`` before `init_node`.
        """
        if self.node is not None:
            return self.node.resolve(name)
        if is_private(name):
            raise ValueError("~name topics cannot be created before init_node() has been called")
        fake_node = ns_join(self.namespace(), "node")
        resolved = resolve(name, self.namespace(), fake_node, strict=False)
        for source, target in self.args.remappings.items():
            if resolve(source, self.namespace(), fake_node, strict=False) == resolved:
                return resolve(target, self.namespace(), fake_node, strict=False)
        return resolved

    # -- the master before the node exists ---------------------------------------------------

    def master_uri(self) -> str:
        """The master's URI: the node's, else ``__master:=``, else ``ROS_MASTER_URI``."""
        if self.node is not None:
            return self.node.master.uri
        from rosx.master.defaults import master_uri  # noqa: PLC0415 - the master's code loads only to talk to one

        return master_uri(os.environ, self.args.master)

    def master(self) -> MasterClient:
        """The master, called as the node (or as ``/unnamed`` before `init_node`)."""
        if self.node is not None:
            return self.node.master
        with self.lock:
            if self._master is None:
                from rosx.master.client import MasterClient  # noqa: PLC0415 - the master's code loads only to talk to one

                self._master = MasterClient(self.master_uri(), self.caller_id())
            return self._master

    # -- registrations made before the node ---------------------------------------------------

    def attach(self, item: Attachable) -> None:
        """Register ``item`` now if the node runs, else when it starts."""
        with self.lock:
            node = self.node
            if node is None:
                self.pending.append(item)
                return
        item._attach(node)

    def forget(self, item: Attachable) -> None:
        """Drop ``item`` from the registrations waiting for the node."""
        with self.lock:
            if item in self.pending:
                self.pending.remove(item)

    def started(self, node: Node) -> bool:
        """The node is up: register everything that waited for it. False (and the node shut
        down) when a shutdown was requested while it started."""
        with self.lock:
            late = self.requested
            if not late:
                self.node = node
                self._master = None
                waiting, self.pending = self.pending, []
        if late:
            node.shutdown(self.shutdown_reason)
            return False
        for item in waiting:
            item._attach(node)
        return True

    # -- shutdown ----------------------------------------------------------------------------

    @property
    def initialized(self) -> bool:
        """Whether `init_node` has started the node (rospy's time is initialized then)."""
        return self.node is not None

    def is_shutdown(self) -> bool:
        """Whether the node is shutting down or down (rospy's ``is_shutdown``); never blocks."""
        return self.shutdown_event.is_set()

    def add_client_hook(self, hook: Callable[[], object]) -> None:
        """Run ``hook()`` on shutdown (at once if the node has shut down already)."""
        if not callable(hook):
            raise TypeError(
                f"shutdown hook [{hook}] must be a function or callable object: {type(hook)}"
            )
        with self.lock:
            if not self.requested:
                self.client_hooks.append(hook)
                return
        hook()

    def signal_shutdown(self, reason: str) -> None:
        """Shut the node down (once): hooks, then `is_shutdown`, then leave the graph."""
        with self.lock:
            if self.requested:
                return
            self.requested = True
            self.shutdown_reason = reason
            hooks, self.client_hooks = self.client_hooks, []
        try:
            for hook in hooks:
                try:
                    hook()
                except Exception:  # every hook runs, as in rospy
                    traceback.print_exc()
            self.shutdown_event.set()
            node = self.node
            if node is not None:
                node.shutdown(reason)
        finally:
            self.shutdown_event.set()
            self.finished.set()

    def shutdown_in_background(self, reason: str) -> None:
        """`signal_shutdown` from a signal handler, which may have interrupted code holding any
        lock, `threading`'s own among them: it runs on a thread started without them
        (`rosx.signals.soon`). The reason is noted at once, without a lock: an exit that comes
        before that thread has run shuts down for the signal, not for the exit."""
        if not self.signalled:
            self.signalled = reason
        soon(functools.partial(self.signal_shutdown, reason))

    def at_exit(self) -> None:
        """The interpreter is exiting: shut down, or wait for the shutdown under way."""
        self.signal_shutdown(self.signalled or "atexit")
        self.finished.wait(_EXIT_WAIT)


CLIENT = Client()

__all__ = ["CLIENT", "Attachable", "Client"]
