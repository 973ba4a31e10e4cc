"""Dead nodes: ``rosnode list --dead`` names the nodes that no longer answer; ``rosnode ping``
of one prints ROS 1's text and, unlike ROS 1, exits 1."""

from __future__ import annotations

from collections.abc import Callable

from rosx.master.client import MasterClient
from rosx.node import Node
from tests.support.cli import clean_environ, rosx
from tests.support.procs import free_port


def _ghost(master: str) -> str:
    """Register ``/ghost`` with a Slave API URI where nothing listens; that URI."""
    uri = f"http://127.0.0.1:{free_port()}/"
    MasterClient(master, "/ghost").call("registerPublisher", "/haunt", "std_msgs/Empty", uri)
    return uri


def test_list_dead_names_only_the_nodes_that_do_not_answer(
    master: str, make_node: Callable[..., Node]
) -> None:
    make_node("alive")
    ghost = _ghost(master)
    env = clean_environ(ROS_MASTER_URI=master)
    listed = rosx("rosnode", "list", environ=env)
    assert {"/alive", "/ghost", "/rosout"} <= set(listed.out.split())
    dead = rosx("rosnode", "list", "--dead", environ=env)
    assert (dead.out, dead.err, dead.status) == ("/ghost\n", "", 0)
    dead_uris = rosx("rosnode", "list", "--dead", "-u", environ=env)
    assert dead_uris.out == f"{ghost}\n"


def test_ping_of_a_dead_node_says_so_and_fails(master: str) -> None:
    ghost = _ghost(master)
    done = rosx(
        "rosnode", "ping", "-c", "1", "/ghost", environ=clean_environ(ROS_MASTER_URI=master)
    )
    assert done.out == "rosnode: node is [/ghost]\npinging /ghost with a timeout of 3.0s\n"
    assert done.err == f"ERROR: connection refused to [{ghost}]\n"
    assert done.status == 1


def test_ping_of_a_live_node_succeeds(master: str, make_node: Callable[..., Node]) -> None:
    make_node("pingme")
    done = rosx(
        "rosnode", "ping", "-c", "1", "/pingme", environ=clean_environ(ROS_MASTER_URI=master)
    )
    assert done.status == 0
    assert done.err == ""


def test_cleanup_names_why_each_dead_node_failed_then_purges_it_once_confirmed(
    master: str, make_node: Callable[..., Node]
) -> None:
    make_node("alive")
    ghost = _ghost(master)
    env = clean_environ(ROS_MASTER_URI=master)
    asked = (
        "Unable to contact the following nodes:\n * /ghost\n"
        "Warning: these might include alive and functioning nodes, e.g. in unstable networks.\n"
        "Cleanup will purge all information about these nodes from the master.\n"
        "Please type y or n to continue:\n"
    )
    kept = rosx("rosnode", "cleanup", stdin="n\n", environ=env)
    assert (kept.out, kept.err, kept.status) == (
        asked + "aborting\n",
        f"ERROR: connection refused to [{ghost}]\n",
        0,
    )
    assert "/ghost" in rosx("rosnode", "list", environ=env).out.split()
    purged = rosx("rosnode", "cleanup", stdin="y\n", environ=env)
    assert (purged.out, purged.err, purged.status) == (
        asked + "Unregistering /ghost\ndone\n",
        f"ERROR: connection refused to [{ghost}]\n",
        0,
    )
    listed = rosx("rosnode", "list", environ=env).out.split()
    assert "/ghost" not in listed and "/alive" in listed
