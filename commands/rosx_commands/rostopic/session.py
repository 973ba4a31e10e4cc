"""The node behind ``rostopic echo``, ``pub``, ``hz``, ``bw`` and ``delay``, and what they share.

A `Session` is one run of a streaming sub-command: it checks the master first (ROS 1's
``Unable to communicate with master!`` within `rosx_commands.context.MASTER_TIMEOUT`), starts
an anonymous node named as ROS 1's tools name theirs (``/rostopic_<pid>_<ms>``), waits for a
topic to be published the way ROS 1's ``get_topic_type(blocking=True)`` does, and always
unregisters the node on the way out: normal exit, error, Ctrl-C or SIGTERM (turned into
``KeyboardInterrupt`` while a session runs on the main thread, as rospy shuts down on it).
"""

from __future__ import annotations

import contextlib
import signal
import threading
import time
from typing import TYPE_CHECKING, Any, NoReturn

from rosx.msg.text.fieldpath import find_topic
from rosx.names.anonymous import anonymous_node_name
from rosx.names.remap_args import RemapArgs
from rosx.signals import handling
from rosx_commands.context import CommandError, Environment
from rosx_commands.rostopic.listing import CALLER_ID

if TYPE_CHECKING:
    from rosx.master.client import MasterClient
    from rosx.msg.codec.message import Message
    from rosx.msg.store import TypeStore
    from rosx.node import Node
    from rosx_commands.cli import ToolParser

#: ROS 1's wildcard type (``AnyMsg``): a topic known only with it has no usable type yet.
ANYTYPE = "*"
#: Seconds between two looks at the master while waiting for a topic.
_POLL = 0.1


class Session:
    """One run of a streaming sub-command (see the module docstring)."""

    def __init__(self, env: Environment) -> None:
        self.env = env
        self.master: MasterClient = env.master(CALLER_ID)
        self.node: Node | None = None
        self._store: TypeStore | None = None
        self._stack = contextlib.ExitStack()

    def __enter__(self) -> Session:
        # While the session runs on the main thread, SIGTERM is Ctrl-C.
        self._stack.enter_context(handling((signal.SIGTERM,), _interrupt))
        return self

    def __exit__(
        self, exc_type: type[BaseException] | None, exc: BaseException | None, tb: object
    ) -> None:
        try:
            if self.node is not None:
                self.node.shutdown("rostopic exited")
        finally:
            self._stack.close()

    # -- the master and the node -------------------------------------------------------------

    def check_master(self) -> None:
        """ROS 1's first step: fail with its error when the master does not answer."""
        self.master.check_online()

    def start_node(self, *, rosout: bool = True) -> Node:
        """Start the tool's node (``/rostopic_<pid>_<ms>`` in ``ROS_NAMESPACE``).

        As rospy's ``init_node``, the command line's ``__name:=`` and ``__ns:=`` rename it,
        its ``from:=to`` remap names, and its ``_param:=value`` set private parameters.
        """
        from rosx.node import Node  # noqa: PLC0415 - only streaming commands need the runtime

        args = self.env.remap_args or RemapArgs()
        node = Node(
            args.name or anonymous_node_name("rostopic"),
            namespace=args.ns,
            remappings=args.remappings,
            private_params=args.params,
            master_uri=self.master.uri,
            environ=self.env.environ,
            rosout_enabled=rosout,
            console=self._console,
            warn_refusals=True,
        )
        self.node = node
        # A master lost from here on raises MasterUnreachable, which the CLI reports.
        node.start()
        # As rospy's init_node: ROS time follows /clock when /use_sim_time is set.
        from rosx.node.simtime import follow_sim_time  # noqa: PLC0415 - with the node runtime

        follow_sim_time(node)
        return node

    def _console(self, level: int, line: str) -> None:
        """The node's warnings and errors on the tool's stderr, as rospy's console shows them
        (a subscriber of another type refused, say)."""
        from rosx.node.rosout import WARN, print_console  # noqa: PLC0415 - with the node runtime

        if level >= WARN:
            print_console(level, line, stderr=self.env.stderr)

    def is_shutdown(self) -> bool:
        """Whether the node was shut down (``rosnode kill``); False before it starts."""
        return self.node is not None and self.node.is_shutdown()

    def sleep(self, seconds: float) -> bool:
        """Sleep ``seconds`` (waking if the node shuts down); False once it has shut down."""
        if self.node is None:
            time.sleep(seconds)
            return True
        return not self.node.wait_for_shutdown(seconds)

    # -- types -------------------------------------------------------------------------------

    @property
    def store(self) -> TypeStore:
        """The message types the tool knows (standard ones and ``ROS_PACKAGE_PATH``'s)."""
        if self._store is None:
            from rosx.msg.store import TypeStore  # noqa: PLC0415 - parsed lazily

            self._store = TypeStore.from_environ(self.env.environ)
        return self._store

    def topic_type(self, name: str) -> tuple[str, str] | None:
        """``(type, topic)`` of the topic ``name`` denotes (itself or a field path into it)."""
        found = find_topic(name, self.master.topic_types(), self.store)
        if found is None or found[1] == ANYTYPE:
            return None
        topic, type_name = found
        return type_name, topic

    def wait_for_topic(self, name: str) -> tuple[str, str] | None:
        """`topic_type`, waiting (with ROS 1's warning) until the topic is published.

        None if the node shut down meanwhile.
        """
        found = self.topic_type(name)
        if found is not None:
            return found
        self.env.stderr.write(f"WARNING: topic [{name}] does not appear to be published yet\n")
        self.env.stderr.flush()
        while self.sleep(_POLL):
            found = self.topic_type(name)
            if found is not None:
                return found
        return None

    def message_class(self, type_name: str) -> type[Message]:
        """The class of ``type_name``, or ROS 1's error when its definition is not found."""
        from rosx.msg.codec.classes import get_message_class  # noqa: PLC0415 - the codegen is lazy

        try:
            return get_message_class(type_name, self.store)
        except Exception:
            raise CommandError(
                f"ERROR: Cannot load message class for [{type_name}]. Are your messages built?"
            ) from None

    def use_sim_time(self, name: str = "use_sim_time") -> bool:
        """Whether the ``use_sim_time`` parameter is set (resolved in the node's namespace)."""
        if self.node is None:
            return False
        try:
            return bool(self.node.params.get(name, False))
        except Exception:
            return False


class MessageFilter:
    """``--filter EXPR``: a Python expression over ``m`` (the message) and ``topic``.

    The expression is compiled once; one that raises counts as not matching and its error is
    printed once (ROS 1 prints a traceback for every message).
    """

    def __init__(self, env: Environment, expression: str, code: Any) -> None:
        self.env = env
        self.expression = expression
        self.code = code
        self._reported = False

    @classmethod
    def compile(
        cls, env: Environment, parser: ToolParser, expression: str | None
    ) -> MessageFilter | None:
        """The filter of ``expression``, None without one; a usage error if it is not Python."""
        if not expression:
            return None
        try:
            code = compile(expression, "<filter>", "eval")
        except SyntaxError as error:
            parser.error(f"invalid filter expression {expression!r}: {error.msg}")
        return cls(env, expression, code)

    def __call__(self, msg: object, topic: str) -> bool:
        """Whether ``--filter``'s expression is true for ``msg`` on ``topic``; an expression that
        raises counts as false, reported once on stderr."""
        try:
            return bool(eval(self.code, {"m": msg, "topic": topic}))
        except Exception as error:
            if not self._reported:
                self._reported = True
                self.env.stderr.write(
                    f"ERROR: filter expression {self.expression!r} failed: "
                    f"{type(error).__name__}: {error}\n"
                )
                self.env.stderr.flush()
            return False


def wait_until(session: Session, done: threading.Event) -> None:
    """Block until ``done`` is set or the node shuts down (Ctrl-C raises out of it)."""
    while not done.is_set() and session.sleep(_POLL):
        pass


def fail(message: str) -> NoReturn:
    """Stop the command with ``ERROR: message`` (status 1), as ROS 1's ROSTopicException."""
    raise CommandError(f"ERROR: {message}")


def _interrupt(signum: int) -> None:
    raise KeyboardInterrupt
