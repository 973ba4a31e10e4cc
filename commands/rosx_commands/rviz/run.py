"""Building rviz's app for a master and running it until the user quits."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from rosx_commands.rviz.app import make_rviz_app
from rosx_commands.rviz.live import LiveSource
from rosx_commands.rviz.manager import Manager
from rosx_commands.rviz.pane import RvizPane, RvizSettings
from rosx_commands.rviz.tools import configured
from rosx_commands.rviz.view import View
from rosx_turtle.tui.running import run_app

if TYPE_CHECKING:
    from rosx_commands.context import Environment
    from rosx_commands.rviz.app import RvizApp
    from rosx_commands.rviz.config import RvizConfig


def _parts(
    env: Environment, config: RvizConfig, fixed_frame: str | None, save_path: Path
) -> tuple[Manager, LiveSource, View, RvizSettings]:
    from rosx.tf.core import BufferCore  # noqa: PLC0415 - tf code loads only when used

    manager = Manager(config, BufferCore(), fixed_frame)
    settings = RvizSettings(save_path=save_path, snapshot_dir=Path.cwd())
    return manager, LiveSource(env), View.from_spec(config.view), settings


def live_app(
    env: Environment, config: RvizConfig, fixed_frame: str | None, save_path: Path
) -> RvizApp:
    """The app on ``env``'s master (its node starts once the app is up)."""
    manager, source, view, settings = _parts(env, config, fixed_frame, save_path)
    return make_rviz_app(config, manager, source, view, configured(config.tools), settings)


def rviz_tab(env: Environment) -> RvizPane:
    """rviz as a tab of ``rosx rqt``, with the config ``rosx rviz`` loads when given none."""
    from rosx_commands.rviz.defaults import default_config_path, starting_config  # noqa: PLC0415 - this tool's parts load only when used

    save_path = default_config_path(env)
    config = starting_config(save_path)
    manager, source, view, settings = _parts(env, config, None, save_path)
    return RvizPane(config, manager, source, view, configured(config.tools), settings)


def run_rviz(
    env: Environment, config: RvizConfig, fixed_frame: str | None, save_path: Path
) -> None:
    """Run rviz until ``q``, Ctrl-C or SIGTERM."""
    run_app(live_app(env, config, fixed_frame, save_path))


__all__ = ["live_app", "run_rviz", "rviz_tab"]
