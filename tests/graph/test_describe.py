"""The graph's descriptions: the summaries ``rosx sim``'s panels list, and the texts of
``rosnode info`` / ``rostopic info`` on a live master (compared with ROS 1's in tests/interop)."""

from __future__ import annotations

import pytest

from rosx.graph.describe import (
    NodeSummary,
    TopicSummary,
    UnknownTopicError,
    node_description,
    node_summaries,
    topic_description,
    topic_summaries,
)
from rosx.master.client import MasterClient
from rosx.master.server import MasterThread
from tests.support.graph_states import lab1


def test_summaries_of_lab1() -> None:
    state = lab1()
    assert topic_summaries(state) == (
        TopicSummary("/rosout", "", ("/teleop_turtle", "/turtlesim"), ("/rosout",)),
        TopicSummary("/rosout_agg", "", ("/rosout",), ()),
        TopicSummary("/turtle1/cmd_vel", "geometry_msgs/Twist", ("/teleop_turtle",), ("/turtlesim",)),
        TopicSummary("/turtle1/color_sensor", "", ("/turtlesim",), ()),
        TopicSummary("/turtle1/pose", "", ("/turtlesim",), ()),
    )  # fmt: skip
    assert node_summaries(state) == (
        NodeSummary("/rosout", 1, 1),
        NodeSummary("/teleop_turtle", 2, 0),
        NodeSummary("/turtlesim", 3, 1),
    )


def test_texts_of_a_live_master() -> None:
    with MasterThread(port=0, host="127.0.0.1", advertised_host="127.0.0.1") as master:
        talker = MasterClient(master.uri, "/talker")
        talker.call("registerPublisher", "/chatter", "std_msgs/String", "http://127.0.0.1:9/")
        talker.call("registerService", "/talker/srv", "rosrpc://127.0.0.1:8", "http://127.0.0.1:9/")
        assert node_description(talker, "/talker") == (
            "Node [/talker]\nPublications: \n * /chatter [std_msgs/String]\n\n"
            "Subscriptions: None\n\nServices: \n * /talker/srv\n"
        )
        assert topic_description(talker, "/chatter") == (
            "Type: std_msgs/String\n\nPublishers: \n * /talker (http://127.0.0.1:9/)\n\n"
            "Subscribers: None\n\n"
        )
        with pytest.raises(UnknownTopicError, match=r"^Unknown topic /nope$"):
            topic_description(talker, "/nope")
        talker.close()
