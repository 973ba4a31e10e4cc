"""The TCPROS topic handshake (ROS wiki ROS/TCPROS and ROS/Connection Header).

A subscriber connects to the port a publisher named in its ``requestTopic`` reply and sends its
header: ``callerid``, ``topic``, ``md5sum``, ``type``, ``message_definition`` and ``tcp_nodelay``.
The publisher checks it against what it publishes and answers with its own header (``callerid``,
``topic``, ``md5sum``, ``type``, ``message_definition``, ``latching``) or with an ``error`` header
and a closed connection. Messages follow as frames (see `framing`).

This module builds both headers and makes both decisions; it does not know sockets, nodes or
queues. The publisher side takes the node's publications as a mapping from topic to
`Publication`; the texts of its refusals are rospy's, word for word, because ROS 1 tools show
them to users. ``*`` as md5sum (and as type) is the wildcard that ``AnyMsg`` subscribers such as
``rostopic echo`` send before they know a topic's type.

Header builders return fields sorted by name, as rospy and roscpp send them, so the encoded bytes
match ROS 1's.
"""

from __future__ import annotations

from rosx.record import Record
from rosx.wire.header import Refused

TYPE_CHECKING = False
if TYPE_CHECKING:
    from collections.abc import Mapping
    from typing import Literal

#: The md5sum (and type) that matches any message type.
WILDCARD = "*"

#: rospy's refusal of a connection header that names neither a topic nor a service.
NO_TOPIC_OR_SERVICE = "no topic or service name detected"

_SUBSCRIBER_REQUIRED = ("topic", "md5sum", "callerid")
_PUBLISHER_REQUIRED = ("md5sum", "type")


class Publication(Record):
    """What a publisher offers on one topic, as its connection header states it.

    ``headers`` are fields the publisher adds to that header (rospy's ``headers=``), over the
    standard ones if they share a name.
    """

    __match_args__ = ("topic", "type", "md5sum", "message_definition", "latching", "headers")
    __slots__ = __match_args__
    topic: str
    type: str
    md5sum: str
    message_definition: str
    latching: bool
    headers: tuple[tuple[str, str], ...]

    def __init__(
        self,
        topic: str,
        type: str,
        md5sum: str,
        message_definition: str = "",
        latching: bool = False,
        headers: tuple[tuple[str, str], ...] = (),
    ) -> None:
        super().__init__(
            topic=topic,
            type=type,
            md5sum=md5sum,
            message_definition=message_definition,
            latching=latching,
            headers=headers,
        )


class SubscriberAccepted(Record):
    """The publisher side accepted a subscriber: send `reply`, then stream messages.

    ``tcp_nodelay`` is what the subscriber asked for, or ``None`` if it did not say.
    """

    __match_args__ = ("callerid", "publication", "tcp_nodelay", "reply")
    __slots__ = __match_args__
    callerid: str
    publication: Publication
    tcp_nodelay: bool | None
    reply: dict[str, str]

    def __init__(
        self,
        callerid: str,
        publication: Publication,
        tcp_nodelay: bool | None,
        reply: dict[str, str],
    ) -> None:
        super().__init__(
            callerid=callerid, publication=publication, tcp_nodelay=tcp_nodelay, reply=reply
        )


class PublisherAccepted(Record):
    """The subscriber side accepted a publisher's reply; frames that follow are messages."""

    __match_args__ = ("callerid", "type", "md5sum", "latching", "message_definition", "header")
    __slots__ = __match_args__
    callerid: str | None
    type: str
    md5sum: str
    latching: bool
    message_definition: str | None
    header: dict[str, str]

    def __init__(
        self,
        *,
        callerid: str | None,
        type: str,
        md5sum: str,
        latching: bool,
        message_definition: str | None,
        header: dict[str, str],
    ) -> None:
        super().__init__(
            callerid=callerid,
            type=type,
            md5sum=md5sum,
            latching=latching,
            message_definition=message_definition,
            header=header,
        )


def _sorted(fields: dict[str, str]) -> dict[str, str]:
    return dict(sorted(fields.items()))


def connection_kind(header: Mapping[str, str]) -> Literal["topic", "service"] | None:
    """Which handshake an incoming header starts: a topic subscription, a service call, or none.

    A TCPROS server port serves both; when this returns ``None`` the server refuses with
    `NO_TOPIC_OR_SERVICE`.
    """
    if "topic" in header:
        return "topic"
    if "service" in header:
        return "service"
    return None


def subscriber_header(
    *,
    callerid: str,
    topic: str,
    md5sum: str,
    msg_type: str,
    message_definition: str | None = None,
    tcp_nodelay: bool = False,
) -> dict[str, str]:
    """The header a subscriber sends. ``message_definition`` is omitted when ``None`` (roscpp)."""
    fields = {
        "callerid": callerid,
        "topic": topic,
        "md5sum": md5sum,
        "type": msg_type,
        "tcp_nodelay": "1" if tcp_nodelay else "0",
    }
    if message_definition is not None:
        fields["message_definition"] = message_definition
    return _sorted(fields)


def publisher_header(publication: Publication, *, callerid: str) -> dict[str, str]:
    """The header a publisher sends back to an accepted subscriber."""
    fields = {
        "callerid": callerid,
        "topic": publication.topic,
        "md5sum": publication.md5sum,
        "type": publication.type,
        "message_definition": publication.message_definition,
        "latching": "1" if publication.latching else "0",
    }
    fields.update(publication.headers)
    return _sorted(fields)


def accept_subscriber(
    request: Mapping[str, str],
    *,
    callerid: str,
    publications: Mapping[str, Publication],
) -> SubscriberAccepted | Refused:
    """Decide, on the publisher side, whether to serve the subscriber whose header is `request`.

    Args:
        request: the subscriber's decoded header.
        callerid: this node's name, sent back and named in refusals.
        publications: this node's publications by resolved topic name, in registration order.
    """
    for name in _SUBSCRIBER_REQUIRED:
        if name not in request:
            return Refused(f"Missing required '{name}' field")
    topic = request["topic"]
    publication = publications.get(topic)
    if publication is None:
        topics = [[name, pub.type] for name, pub in publications.items()]
        return Refused(f"[{callerid}] is not a publisher of [{topic}]. Topics are {topics!r}")
    md5sum = request["md5sum"]
    if WILDCARD not in (md5sum, publication.md5sum) and md5sum != publication.md5sum:
        requested_type = request.get("type", publication.type)
        if requested_type not in (WILDCARD, publication.type):
            return Refused(f"topic types do not match: [{requested_type}] vs. [{publication.type}]")
        return Refused(
            f"Client [{request['callerid']}] wants topic [{topic}] to have datatype/md5sum "
            f"[{requested_type}/{md5sum}], but our version has "
            f"[{publication.type}/{publication.md5sum}] Dropping connection."
        )
    nodelay = request.get("tcp_nodelay")
    return SubscriberAccepted(
        callerid=request["callerid"],
        publication=publication,
        tcp_nodelay=None if nodelay is None else nodelay.strip() == "1",
        reply=publisher_header(publication, callerid=callerid),
    )


def check_reply(reply: Mapping[str, str], *, md5sum: str, what: str, name: str) -> Refused | None:
    """The checks a connecting side makes on the header it gets back; ``None`` if it passes.

    Shared by topics (`check_publisher_reply`) and services (`rosrpc`). ``what`` and ``name``
    (e.g. ``"topic"``, ``"/chatter"``) only word the md5 mismatch.
    """
    if "error" in reply:
        return Refused(reply["error"], by_peer=True)
    for field in _PUBLISHER_REQUIRED:
        if field not in reply:
            return Refused(f"header missing required field [{field}]")
    theirs = reply["md5sum"]
    if WILDCARD not in (md5sum, theirs) and md5sum != theirs:
        return Refused(
            f"[{reply.get('callerid', '?')}] sent md5sum [{theirs}] for {what} [{name}], "
            f"but this side expects [{md5sum}]"
        )
    return None


def check_publisher_reply(
    reply: Mapping[str, str], *, topic: str, md5sum: str
) -> PublisherAccepted | Refused:
    """Decide, on the subscriber side, whether the publisher's reply header lets data flow.

    Args:
        reply: the publisher's decoded header.
        topic: the topic subscribed to (only named in refusals).
        md5sum: the md5sum this subscriber asked for; ``*`` accepts any.
    """
    refused = check_reply(reply, md5sum=md5sum, what="topic", name=topic)
    if refused is not None:
        return refused
    return PublisherAccepted(
        callerid=reply.get("callerid"),
        type=reply["type"],
        md5sum=reply["md5sum"],
        latching=reply.get("latching", "0") == "1",
        message_definition=reply.get("message_definition"),
        header=dict(reply),
    )
