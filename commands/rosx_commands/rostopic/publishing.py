"""How ``rostopic pub`` publishes: latched, once, at a rate, or document by document.

The texts and loops are ROS 1's:

* without ``-r``: print ``publishing and latching message. Press ctrl-C to terminate`` (with
  ``-1``: ``… for 3.0 seconds``), publish latched, and stay up (``-1``: until delivered);
* with ``-r HZ``: publish at that rate until interrupted, refilling ``now``/``auto`` before
  each message with ``-s``; ``-v`` prints each message;
* from ``-f FILE`` or standard input: first wait (at most 5 s) for a subscriber, then publish
  each YAML document in turn, at 10 Hz unless told otherwise.

One difference, asked for by users: ``-1`` does not always stay 3 s. It leaves as soon as
every subscriber the master knows of is connected and has been sent the message. While the
master knows of none it stays the full 3 s, as ROS 1 does: a ``rostopic echo`` started first
only subscribes once it sees the topic published, and must still get the message.
"""

from __future__ import annotations

import time
from typing import TYPE_CHECKING, Any

from rosx.graph.state import registrations
from rosx.master.client import MasterError
from rosx.msg.codec.message import MessageException
from rosx.transport.errors import TransportError
from rosx_commands.rostopic.session import fail

if TYPE_CHECKING:
    from collections.abc import Iterable

    from rosx.msg.codec.message import Message
    from rosx.node import Publisher
    from rosx_commands.context import Environment
    from rosx_commands.rostopic.session import Session

#: How long ``-1`` may wait for the subscribers (ROS 1 always waits this long).
ONCE_DELAY = 3.0
#: How long ``-f``/stdin publishing waits for a first subscriber.
SUBSCRIBER_TIMEOUT = 5.0
#: Seconds between two looks at the master's subscribers while ``-1`` waits.
_MASTER_POLL = 0.1


class Publishing:
    """Publishes messages of one type on one topic for ``rostopic pub``."""

    def __init__(
        self,
        env: Environment,
        session: Session,
        publisher: Publisher,
        *,
        verbose: bool = False,
        substitute_keywords: bool = False,
    ) -> None:
        self.env = env
        self.session = session
        self.publisher = publisher
        self.msg_class: type[Message] = publisher.data_class
        self.verbose = verbose
        self.substitute_keywords = substitute_keywords

    # -- one message -------------------------------------------------------------------------

    def fill(self, msg: Message, args: list[Any]) -> None:
        """Fill ``msg`` from YAML values; ROS 1's error with the expected fields if they do not fit.

        Raises:
            ValueError: a scalar where a message is needed (``-f``/stdin report it and stop).
        """
        from rosx.msg.text.yamlargs import fill_message_args, publish_error_text  # noqa: PLC0415 - the text forms load on first use

        try:
            fill_message_args(msg, args, store=self.session.store)
        except MessageException as error:
            fail(publish_error_text(error, msg))

    def send(self, msg: Message) -> None:
        """Publish ``msg``, or ROS 1's error naming the field of the wrong type."""
        try:
            self.publisher.publish(msg)
        except (MessageException, TypeError, ValueError, OverflowError) as error:
            from rosx.msg.describe import describe_msg  # noqa: PLC0415 - the message layer loads on first use

            store = self.session.store
            text = describe_msg(store.msg(self.msg_class._type), store.msg)
            fail(
                "Unable to publish message. One of the fields has an incorrect type:\n"
                f"  {error}\n\nmsg file:\n{text}"
            )

    def publish_message(self, args: list[Any], rate: float | None, once: bool) -> None:
        """ROS 1's ``publish_message``: fill a new message, then publish it latched or at a rate."""
        msg = self.msg_class()
        self.fill(msg, args)
        if rate is not None:
            self.at_rate(msg, args, rate)
            return
        what = f"[{msg}]" if self.verbose else "message"
        ending = f" for {ONCE_DELAY} seconds" if once else ". Press ctrl-C to terminate"
        self._say(f"publishing and latching {what}{ending}")
        self.send(msg)
        if not once:
            self.spin()

    def at_rate(self, msg: Message, args: list[Any], rate: float) -> None:
        """Publish ``msg`` ``rate`` times a second until interrupted."""
        from rosx.node import Rate  # noqa: PLC0415 - the node runtime loads with the first node
        from rosx.node.errors import NodeShutdownError, TimeMovedBackwardsError  # noqa: PLC0415 - the node runtime loads with the first node

        node = self.publisher.node
        pacer = Rate(rate, shutdown=node.shutdown_event, clock=node.clock)
        while not node.is_shutdown():
            if self.substitute_keywords:
                self.fill(msg, args)
            if self.verbose:
                self._say(f"publishing {msg}")
            self.send(msg)
            try:
                pacer.sleep()
            except (NodeShutdownError, TimeMovedBackwardsError):  # as rospy's Rate: the end
                return

    def spin(self) -> None:
        """Stay up (the latched message stays available) until Ctrl-C or ``rosnode kill``."""
        while self.session.sleep(1.0):
            pass

    # -- the three ways in -------------------------------------------------------------------

    def from_argv(self, args: list[Any], rate: float | None, once: bool) -> None:
        """Values given on the command line."""
        try:
            self.publish_message(args, rate, once)
        except ValueError as error:
            from rosx.msg.text.yamlargs import publish_error_text  # noqa: PLC0415 - the text forms load on first use

            fail(publish_error_text(error, self.msg_class()))
        if once:
            self.wait_for_delivery(ONCE_DELAY)

    def from_documents(
        self, documents: Iterable[Any], rate: float | None, once: bool, *, exactly_one: bool
    ) -> None:
        """YAML documents from ``-f FILE`` or standard input, one message each."""
        from rosx.node import Rate  # noqa: PLC0415 - the node runtime loads with the first node
        from rosx.node.errors import NodeShutdownError, TimeMovedBackwardsError  # noqa: PLC0415 - the node runtime loads with the first node

        node = self.publisher.node
        pacer = (
            Rate(rate, shutdown=node.shutdown_event, clock=node.clock) if rate is not None else None
        )
        self.wait_for_subscriber(SUBSCRIBER_TIMEOUT)
        for document in documents:
            if node.is_shutdown():
                break
            if document:
                args = document if isinstance(document, list) else [document]
                try:
                    if exactly_one and rate is not None:
                        self._say("Got one message and a rate, publishing repeatedly")
                        self.publish_message(args, rate, once)
                    else:
                        self.publish_message(args, None, pacer is not None or once)
                except ValueError as error:
                    self.env.stderr.write(f"{error}\n")
                    break
            if pacer is not None:
                try:
                    pacer.sleep()
                except (NodeShutdownError, TimeMovedBackwardsError):  # as rospy's Rate: the end
                    break
            if node.is_shutdown() or once:
                break
        if once:
            self.wait_for_delivery(ONCE_DELAY)

    # -- waiting for subscribers -------------------------------------------------------------

    def wait_for_subscriber(self, timeout: float) -> None:
        """Wait until some subscriber is connected, at most ``timeout`` seconds."""
        deadline = time.monotonic() + timeout
        while self.publisher.get_num_connections() == 0 and time.monotonic() < deadline:
            if not self.session.sleep(0.01):
                return

    def wait_for_delivery(self, cap: float) -> None:
        """Wait until every subscriber the master lists has been sent the message (≤ ``cap`` s).

        With no subscriber listed, wait the whole ``cap``: tools waiting for the topic to
        appear subscribe only now. A subscriber has the message once its connection carried
        the header and one message and has nothing left queued: the bytes are then with the
        kernel, which delivers them even after this process closes the connection.
        """
        deadline = time.monotonic() + cap
        known: set[str] | None = None
        asked = 0.0
        while True:
            current = time.monotonic()
            if current - asked >= _MASTER_POLL:
                known = self._known_subscribers()
                asked = current
            if known and known <= self.publisher.delivered_to():
                return
            remaining = deadline - time.monotonic()
            if remaining <= 0 or not self.session.sleep(min(0.01, remaining)):
                return

    def _known_subscribers(self) -> set[str] | None:
        """The nodes the master lists as subscribers of the topic (None if it cannot say)."""
        try:
            state = registrations(self.session.master)
        except (TransportError, MasterError):
            return None
        return set(state.subscribers.get(self.publisher.name, ())) - {self.publisher.node.name}

    def _say(self, text: str) -> None:
        self.env.stdout.write(text + "\n")
        self.env.stdout.flush()
