"""axclient.py and axserver.py driven by pilot, each against the other side of actionlib in the
test's process: goals edited as YAML, feedback, results, cancels, preemption."""

from __future__ import annotations

import time
from collections.abc import Callable, Iterator
from types import ModuleType
from typing import Any

import pytest
from textual.pilot import Pilot
from textual.widgets import Button, Static, TextArea
from textual.widgets._footer import FooterKey

from rosx.actionlib import SimpleActionClient, SimpleActionServer
from rosx.actionlib.states import Status
from rosx_commands.actionlib_tools.client_app import ClientApp, make_client_app
from rosx_commands.actionlib_tools.forms import action_types
from rosx_commands.actionlib_tools.server_app import ServerApp, ServerPane, make_server_app
from rosx_commands.actionlib_tools.standin import Standin
from tests.support.client import fresh_rospy
from tests.support.pilot import run

TYPES = action_types("actionlib/TestAction")


@pytest.fixture
def rospy(master: str, monkeypatch: pytest.MonkeyPatch) -> Iterator[ModuleType]:
    for module in fresh_rospy(master, monkeypatch):
        module.init_node("axtools_test", disable_signals=True)
        yield module


def text(app: ClientApp | ServerApp, where: str) -> str:
    widget = app.query_one(where)
    if isinstance(widget, TextArea):
        return widget.text
    assert isinstance(widget, Static)
    return str(widget.render()).strip()


async def until(pilot: Pilot[Any], done: Callable[[], bool], what: str) -> None:
    deadline = time.monotonic() + 30
    while not done():
        assert time.monotonic() < deadline, f"timed out waiting for {what}"
        await pilot.pause(0.05)


def _server(name: str) -> SimpleActionServer:
    """Goal n: feedback n, then result 2n; goal 0 runs until preempted."""

    def execute(goal: Any) -> None:
        if goal.goal == 0:
            while not server.is_preempt_requested():
                time.sleep(0.005)
            server.set_preempted(TYPES.result(result=-1))
            return
        server.publish_feedback(TYPES.feedback(feedback=goal.goal))
        server.set_succeeded(TYPES.result(result=2 * goal.goal))

    server = SimpleActionServer(name, TYPES.action, execute, auto_start=False)
    server.start()
    return server


def test_axclient_footer_names_a_quit_key_while_the_goal_is_edited(rospy: ModuleType) -> None:
    """``q`` types into the goal, so textual drops it from the footer; Ctrl-C is named instead."""
    app = make_client_app(TYPES, "/ax_quiet", SimpleActionClient("/ax_quiet", TYPES.action))

    async def drive() -> None:
        async with app.run_test(size=(80, 30)) as pilot:
            await pilot.pause()
            assert isinstance(app.focused, TextArea)
            keys = {(k.key, k.description) for k in app.query(FooterKey)}
            assert ("ctrl+c", "Quit") in keys
            await pilot.press("ctrl+c")
        assert app.return_code == 0

    run(drive())


def test_axclient_sends_the_edited_goal_and_shows_what_comes_back(rospy: ModuleType) -> None:
    _server("/ax_target")
    app = make_client_app(TYPES, "/ax_target", SimpleActionClient("/ax_target", TYPES.action))

    async def drive() -> None:
        async with app.run_test(size=(80, 30)) as pilot:
            assert text(app, "#title") == "/ax_target - actionlib/Test - GUI Client"
            assert text(app, "#goal") == "goal: 0"
            assert text(app, "#status") == "No Goal"
            await until(pilot, lambda: text(app, "#server") == "Connected to server", "server")
            assert not app.query_one("#send", Button).disabled
            app.query_one("#goal", TextArea).text = "goal: 3"
            await pilot.press("ctrl+s")
            finished = "Goal finished with status: SUCCEEDED"
            await until(pilot, lambda: text(app, "#status") == finished, "the result")
            assert (text(app, "#feedback"), text(app, "#result")) == ("feedback: 3", "result: 6")
            assert app.query_one("#cancel", Button).disabled
            app.query_one("#goal", TextArea).text = "goal: 0"
            await pilot.press("ctrl+s")
            await until(pilot, lambda: text(app, "#status") == "Goal is active", "the goal active")
            await pilot.press("ctrl+x")
            preempted = "Goal finished with status: PREEMPTED"
            await until(pilot, lambda: text(app, "#status") == preempted, "the preemption")
            assert text(app, "#result") == "result: -1"
            app.query_one("#goal", TextArea).text = "goal: [1"
            await pilot.press("ctrl+s")
            assert text(app, "#status").startswith("Error serializing goal: ")
            await pilot.press("ctrl+c")

    run(drive())


def test_axserver_holds_goals_until_the_user_ends_them(rospy: ModuleType) -> None:
    def standin(pane: ServerPane) -> Standin:
        return Standin(TYPES, "/ax_standin", pane.report)

    app = make_server_app(TYPES, "/ax_standin", standin)
    client = SimpleActionClient("/ax_standin", TYPES.action)
    feedback: list[int] = []

    async def drive() -> None:
        async with app.run_test(size=(80, 30)) as pilot:
            assert text(app, "#title") == "/ax_standin - actionlib/Test - Standin"
            assert text(app, "#status") == "Waiting For Goal..."
            assert client.wait_for_server(rospy.Duration(10))
            client.send_goal(TYPES.goal(goal=7), feedback_cb=lambda f: feedback.append(f.feedback))
            received = "Received Goal.  Send feedback, succeed, or abort."
            await until(pilot, lambda: text(app, "#status") == received, "the goal")
            assert text(app, "#goal") == "goal: 7"
            app.query_one("#feedback", TextArea).text = "feedback: 5"
            await pilot.press("ctrl+f")
            await until(pilot, lambda: feedback == [5], "the feedback")
            app.query_one("#result", TextArea).text = "result: 70"
            await pilot.press("ctrl+s")
            await until(pilot, lambda: client.get_state() == Status.SUCCEEDED, "success")
            assert client.get_result().result == 70
            await until(pilot, lambda: text(app, "#status") == "Waiting For Goal...", "idle")
            client.send_goal(TYPES.goal(goal=8))
            await until(pilot, lambda: text(app, "#status") == received, "the second goal")
            client.cancel_goal()
            await until(
                pilot, lambda: text(app, "#status") == "Preempt requested...", "the request"
            )
            await pilot.press("ctrl+p")
            await until(pilot, lambda: client.get_state() == Status.PREEMPTED, "preemption")
            await pilot.press("ctrl+c")

    run(drive())
    app.pane.standin.close()  # type: ignore[union-attr]
