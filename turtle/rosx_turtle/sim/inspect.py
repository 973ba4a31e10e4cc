"""`Inspector`: what ``rosx sim``'s details show of a topic or a node, asked of the master.

A topic's info is ``rostopic info``'s text and a node's is ``rosnode info``'s
(`rosx.graph.describe`); a topic's messages are echoed as ``rostopic echo`` prints them
(`rosx.msg.text.echo`), through a node of its own (``/rosx_sim_echo_<pid>_<ms>``, as rostopic's
is anonymous) that lives while something is echoed. Every method may block (the master, the
nodes) and is called from worker threads; failures come back as the text to show.
"""

from __future__ import annotations

import threading
from typing import TYPE_CHECKING

from rosx.graph.describe import NodeContactError, UnknownTopicError, node_info, topic_description
from rosx.master.client import MasterClient, MasterError
from rosx.msg.codec.classes import get_message_class
from rosx.transport.errors import TransportError

if TYPE_CHECKING:
    from collections.abc import Callable, Mapping

    from rosx.node import Node, RawMessage

CALLER_ID = "/rosx_sim_info"
#: Seconds the master has to answer.
TIMEOUT = 5.0


class Inspector:
    """Info and echo for the master at ``master_uri``."""

    def __init__(self, master_uri: str, environ: Mapping[str, str]) -> None:
        self.master_uri = master_uri
        self.environ = environ
        self._lock = threading.Lock()
        self._node: Node | None = None
        self._echoes = 0

    def describe_topic(self, topic: str) -> str:
        """``rostopic info TOPIC``'s text, or why there is none."""
        return self._ask(lambda master: topic_description(master, topic))

    def describe_node(self, node: str) -> str:
        """``rosnode info NODE``'s text (its dashed line first), or why there is none."""
        return self._ask(lambda master: "-" * 80 + "\n" + node_info(master, node))

    def _ask(self, question: Callable[[MasterClient], str]) -> str:
        master = MasterClient(self.master_uri, CALLER_ID, timeout=TIMEOUT)
        try:
            return question(master)
        except UnknownTopicError as error:
            return f"ERROR: {error}\n"
        except NodeContactError as error:
            return f"ERROR: {error}\n"
        except (MasterError, TransportError) as error:
            return f"ERROR: cannot ask the master at {self.master_uri}: {error}\n"
        finally:
            master.close()

    def echo(self, topic: str, offer: Callable[[str], object]) -> Callable[[], None]:
        """Call ``offer(text)`` with each message of ``topic`` as ``rostopic echo`` prints it
        (on the topic's thread); returns the function that stops echoing."""
        from rosx.msg.text.echo import echo_record, format_message  # noqa: PLC0415 - the text forms load on first use

        def arrived(raw: RawMessage) -> None:
            try:
                message = get_message_class(raw.type)().deserialize(raw._buff)
            except Exception as error:  # an unknown or broken type: say so, keep echoing
                offer(f"cannot decode {raw.type}: {error}\n")
                return
            offer(echo_record(format_message(message)))

        subscriber = self._started().subscribe(topic, None, arrived)
        stopped = threading.Event()

        def stop() -> None:
            if stopped.is_set():
                return
            stopped.set()
            subscriber.unregister()
            self._release()

        return stop

    def _started(self) -> Node:
        with self._lock:
            self._echoes += 1
            if self._node is None:
                from rosx.names.anonymous import anonymous_node_name  # noqa: PLC0415 - name rules load only when used
                from rosx.node import Node  # noqa: PLC0415 - the node runtime loads with the first node

                name = anonymous_node_name("rosx_sim_echo")
                self._node = Node(
                    name, master_uri=self.master_uri, environ=self.environ, rosout_enabled=False
                ).start()
            return self._node

    def _release(self) -> None:
        with self._lock:
            self._echoes -= 1
            node = self._node if self._echoes == 0 else None
            if node is not None:
                self._node = None
        if node is not None:
            node.shutdown("echo closed")

    def close(self) -> None:
        """Stop the echo node, if any."""
        with self._lock:
            node, self._node, self._echoes = self._node, None, 0
        if node is not None:
            node.shutdown("rosx sim is done")
