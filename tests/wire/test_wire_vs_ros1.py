"""The wire layer against ROS 1 itself: rosgraph's header codec and rospy's handshake code.

ROS 1's Python runs under Debian's /usr/bin/python3 in one subprocess per module; it computes
what rosgraph and rospy produce for the inputs below, and each test compares rosx with that.
Skipped where /usr/bin/python3 cannot import rospy.
"""

from __future__ import annotations

import json
import subprocess
from pathlib import Path
from typing import Any

import pytest

from rosx.wire.errors import ProtocolError
from rosx.wire.header import decode_header, encode_header
from rosx.wire.rosrpc import (
    ServiceClientAccepted,
    ServiceInfo,
    accept_client,
    client_header,
    encode_error,
    parse_rosrpc_uri,
    server_header,
)
from rosx.wire.tcpros import (
    Publication,
    SubscriberAccepted,
    accept_subscriber,
    publisher_header,
    subscriber_header,
)
from tests.support.ros1 import ros1_python_imports

ROS1_PYTHON = Path("/usr/bin/python3")


pytestmark = pytest.mark.skipif(
    not ros1_python_imports("rospy", "rosgraph", "std_msgs.msg", "std_srvs.srv"),
    reason="ROS 1 (rospy for /usr/bin/python3) is not installed",
)

HEADERS: list[dict[str, str]] = [
    {},
    {"callerid": "/talker"},
    {"topic": "/chatter", "md5sum": "*", "callerid": "/n\u00e9", "type": "*"},
    {"message_definition": "int32 A=1\nstring s\n", "latching": "0", "error": "x=y=z"},
    {"probe": "1", "md5sum": "*", "callerid": "/rosservice", "service": "/add_two_ints"},
]

STRING_MD5 = "992ce8a1687cec8c8bd883ec73ca41d1"
EMPTY_MD5 = "d41d8cd98f00b204e9800998ecf8427e"

TOPIC_REQUESTS: list[dict[str, str]] = [
    {"topic": "/chatter", "md5sum": "bad", "callerid": "/l", "type": "std_msgs/String"},
    {"topic": "/chatter", "md5sum": "bad", "callerid": "/l"},
    {"topic": "/chatter", "md5sum": "bad", "callerid": "/l", "type": "std_msgs/Int32"},
    {"topic": "/nope", "md5sum": "*", "callerid": "/l"},
    {"md5sum": "*", "callerid": "/l"},
    {"topic": "/chatter", "callerid": "/l"},
    {"topic": "/chatter", "md5sum": "*"},
    {"topic": "/chatter", "md5sum": "*", "callerid": "/l"},
    {"topic": "/chatter", "md5sum": STRING_MD5, "callerid": "/l", "type": "*"},
]

SERVICE_REQUESTS: list[dict[str, str]] = [
    {"service": "/empty", "md5sum": "bad", "callerid": "/c"},
    {"service": "/nope", "md5sum": "*", "callerid": "/c"},
    {"md5sum": "*", "callerid": "/c"},
    {"service": "/empty", "callerid": "/c"},
    {"service": "/empty", "md5sum": "*"},
    {"service": "/empty", "md5sum": "*", "callerid": "/c", "probe": "1"},
]

ROSRPC_URIS = ["rosrpc://host:1234", "rosrpc://h:1/x", "http://h:1", "rosrpc://h", "rosrpc://h:p"]

# Runs under ROS 1's Python; reads the inputs as JSON on stdin, prints its answers as JSON.
ROS1_SCRIPT = r"""
import json, socket, sys
import rosgraph.network as network
import rospy.core, rospy.names
import rospy.impl.registration as registration
import rospy.impl.tcpros_pubsub as pubsub
import rospy.impl.tcpros_service as service
from std_msgs.msg import String
from std_srvs.srv import Empty

given = json.load(sys.stdin)
rospy.names._set_caller_id("/talker")
out = {}
out["encoded"] = [network.encode_ros_handshake_header(h).hex() for h in given["headers"]]
out["decoded"] = [network.decode_ros_handshake_header(bytes.fromhex(b)) for b in given["ours"]]

registration.get_topic_manager().acquire_impl(registration.Registration.PUB, "/chatter", String)
handler = pubsub.TCPROSHandler()

def answer(handle, header):
    # Returns rospy's refusal text, or the hex of the header it wrote back when it accepted.
    ours, theirs = socket.socketpair()
    refusal = handle(ours, ("h", 1), header)
    if refusal is not None:
        return refusal
    theirs.settimeout(5)
    data = theirs.recv(4)
    while len(data) < 4 + int.from_bytes(data[:4], "little"):
        data += theirs.recv(65536)
    return data.hex()

out["topic_refusals"] = [
    answer(handler.topic_connection_handler, h) for h in given["topic_requests"]
]

empty = service.ServiceImpl("/empty", Empty, lambda request: None)
empty.uri = "rosrpc://h:1"
service.get_service_manager().register("/empty", empty)
out["service_refusals"] = [
    answer(service.service_connection_handler, h) for h in given["service_requests"]
]

out["sub_fields"] = pubsub.TCPROSSub("/chatter", String, tcp_nodelay=True).get_header_fields()
out["pub_fields"] = pubsub.TCPROSPub("/chatter", String, is_latch=True).get_header_fields()
out["server_fields"] = service.TCPService("/empty", Empty).get_header_fields()
out["client_fields"] = service.TCPROSServiceClient("/empty", Empty).get_header_fields()
proxy = service.ServiceProxy("/empty", Empty, persistent=True)
out["persistent_fields"] = proxy.protocol.get_header_fields()
out["definition"] = String._full_text

class Recorder:
    def write_data(self, data):
        self.data = data

recorder = Recorder()
empty._write_service_error(recorder, "no \u00e9")
out["error_bytes"] = recorder.data.hex()

uris = []
for uri in given["uris"]:
    try:
        uris.append(list(rospy.core.parse_rosrpc_uri(uri)))
    except Exception as exc:
        uris.append(str(exc))
out["uris"] = uris
print(json.dumps(out))
"""


@pytest.fixture(scope="module")
def ros1() -> dict[str, Any]:
    given = {
        "headers": HEADERS,
        "ours": [encode_header(h).hex() for h in HEADERS],
        "topic_requests": TOPIC_REQUESTS,
        "service_requests": SERVICE_REQUESTS,
        "uris": ROSRPC_URIS,
    }
    result = subprocess.run(
        [str(ROS1_PYTHON), "-c", ROS1_SCRIPT],
        input=json.dumps(given),
        capture_output=True,
        text=True,
        check=False,
        env={"PATH": "/usr/bin:/bin", "ROS_MASTER_URI": "http://127.0.0.1:1/", "HOME": "/tmp"},
    )
    assert result.returncode == 0, result.stderr
    answers: dict[str, Any] = json.loads(result.stdout)
    return answers


def test_headers_encode_like_rosgraph_once_sorted(ros1: dict[str, Any]) -> None:
    for fields, theirs in zip(HEADERS, ros1["encoded"], strict=True):
        assert encode_header(dict(sorted(fields.items()))).hex() == theirs


def test_rosgraph_decodes_our_headers_and_we_decode_theirs(ros1: dict[str, Any]) -> None:
    for fields, decoded, theirs in zip(HEADERS, ros1["decoded"], ros1["encoded"], strict=True):
        assert decoded == fields
        assert decode_header(bytes.fromhex(theirs)[4:]) == fields


def test_topic_decisions_match_rospy(ros1: dict[str, Any]) -> None:
    chatter = Publication("/chatter", "std_msgs/String", STRING_MD5, ros1["definition"])
    for request, theirs in zip(TOPIC_REQUESTS, ros1["topic_refusals"], strict=True):
        decision = accept_subscriber(
            request, callerid="/talker", publications={"/chatter": chatter}
        )
        if isinstance(decision, SubscriberAccepted):
            assert encode_header(decision.reply).hex() == theirs, request
        else:
            assert decision.reason == theirs, request


def test_service_decisions_match_rospy(ros1: dict[str, Any]) -> None:
    empty = ServiceInfo(
        "/empty", "std_srvs/Empty", EMPTY_MD5, "std_srvs/EmptyRequest", "std_srvs/EmptyResponse"
    )
    for request, theirs in zip(SERVICE_REQUESTS, ros1["service_refusals"], strict=True):
        decision = accept_client(request, callerid="/talker", services={"/empty": empty})
        if isinstance(decision, ServiceClientAccepted):
            # rospy's server sends a subset of roscpp's fields; rosx sends them all.
            sent = decode_header(bytes.fromhex(theirs)[4:])
            assert sent.items() <= decision.reply.items(), request
            assert set(decision.reply) - set(sent) == {"request_type", "response_type"}
        else:
            assert decision.reason == theirs, request


def test_handshake_fields_match_rospy(ros1: dict[str, Any]) -> None:
    definition = ros1["definition"]
    sub = subscriber_header(
        callerid="/talker",
        topic="/chatter",
        md5sum=STRING_MD5,
        msg_type="std_msgs/String",
        message_definition=definition,
        tcp_nodelay=True,
    )
    assert sub == ros1["sub_fields"]
    chatter = Publication("/chatter", "std_msgs/String", STRING_MD5, definition, latching=True)
    assert publisher_header(chatter, callerid="/talker") == ros1["pub_fields"]
    client = client_header(callerid="/talker", service="/empty", md5sum=EMPTY_MD5)
    assert client == ros1["client_fields"]
    persistent = client_header(
        callerid="/talker", service="/empty", md5sum=EMPTY_MD5, persistent=True
    )
    assert persistent == ros1["persistent_fields"]
    empty = ServiceInfo(
        "/empty", "std_srvs/Empty", EMPTY_MD5, "std_srvs/EmptyRequest", "std_srvs/EmptyResponse"
    )
    # rospy's server sends a subset of roscpp's fields; rosx sends them all.
    ours = server_header(empty, callerid="/talker")
    assert ros1["server_fields"].items() <= ours.items()


def test_service_error_bytes_match_rospy(ros1: dict[str, Any]) -> None:
    assert encode_error("no \u00e9").hex() == ros1["error_bytes"]


def test_rosrpc_uris_match_rospy(ros1: dict[str, Any]) -> None:
    for uri, theirs in zip(ROSRPC_URIS, ros1["uris"], strict=True):
        try:
            ours: object = list(parse_rosrpc_uri(uri))
        except ProtocolError as exc:
            ours = str(exc)
        assert ours == theirs, uri
