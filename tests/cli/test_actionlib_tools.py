"""axclient.py and axserver.py on the command line: ROS 1's usage errors, the action's type
found from its goal topic, and a clear refusal without a terminal."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from rosx.msg.codec.classes import get_message_class
from rosx.node import Node
from tests.support.cli import clean_environ, rosx

USAGE = "Usage: {0} /action_name action_type\n\n{0}: error: "


@pytest.mark.parametrize(
    ("argv", "error"),
    [
        (
            ["axclient"],
            "You must specify the action topic name (and optionally type) Eg: ./axclient.py "
            "action_topic actionlib/TwoIntsAction ",
        ),
        (
            ["axclient", "/x", "actionlib/Test"],
            "the action type provided 'actionlib/Test' doesn't end with the 'Action' suffix",
        ),
        (
            ["axserver", "x"],
            "You must specify the action name and type. Eg: ./axserver.py my_action actionlib/Test",
        ),
    ],
)
def test_usage_errors_are_ros1s(argv: list[str], error: str) -> None:
    done = rosx(*argv)
    assert done.status == 2
    assert done.err == USAGE.format(f"{argv[0]}.py") + error + "\n"


def test_the_type_comes_from_the_goal_topic(master: str, make_node: Callable[..., Node]) -> None:
    env = clean_environ(ROS_MASTER_URI=master)
    missing = rosx("axclient", "fibonacci", environ=env)
    assert (missing.status, missing.err) == (
        2,
        USAGE.format("axclient.py") + "unable to retrieve the topic type for goal topic "
        "'fibonacci/goal'\nAre you sure the action server for 'fibonacci' is running?\n",
    )
    server = make_node("fibonacci")
    goal = get_message_class("actionlib_tutorials/FibonacciActionGoal")
    server.subscribe("/fibonacci/goal", goal, lambda msg: None)
    server.subscribe("/plain/goal", get_message_class("std_msgs/String"), lambda msg: None)
    plain = rosx("axclient", "/plain/", environ=env)
    assert plain.err.endswith("error: topic '/plain/goal' is not an action goal topic\n")
    # found: the view is next, and it needs a terminal
    found = rosx("axclient", "fibonacci", environ=env)
    assert (found.status, found.err) == (2, "axclient.py: error: the view needs a terminal\n")


def test_an_unknown_action_type_is_named() -> None:
    done = rosx("axserver", "x", "nope/Thing")
    assert (done.status, done.err) == (1, "Could not load message for: nope/ThingAction\n")
