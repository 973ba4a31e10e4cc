"""``rosx sim``'s graph panels read the graph state rqt_graph reads, summarised by rosx.graph."""

from __future__ import annotations

from rosx.graph.describe import NodeSummary, TopicSummary
from rosx.master.client import MasterClient
from rosx.master.server import MasterThread
from rosx_turtle.tui.graph import fetch_graph
from tests.support.procs import free_port


def test_the_panels_list_what_the_master_says() -> None:
    with MasterThread(port=0, host="127.0.0.1", advertised_host="127.0.0.1") as master:
        talker = MasterClient(master.uri, "/talker")
        talker.call("registerPublisher", "/chatter", "std_msgs/String", "http://127.0.0.1:9/")
        talker.close()
        panels = fetch_graph(master.uri)
    assert panels.topics == (TopicSummary("/chatter", "std_msgs/String", ("/talker",), ()),)
    assert panels.nodes == (NodeSummary("/talker", 1, 0),)
    assert panels.error == ""


def test_the_panels_say_when_the_master_does_not_answer() -> None:
    uri = f"http://127.0.0.1:{free_port()}"
    panels = fetch_graph(uri)
    assert (panels.topics, panels.nodes) == ((), ())
    assert panels.error.startswith(f"cannot reach the master at {uri}")
