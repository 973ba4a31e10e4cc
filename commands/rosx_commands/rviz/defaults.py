"""Where rviz's config comes from when none is given: ``~/.rviz/default.rviz`` if it exists,
else the bundled rviz package's ``default.rviz``, as rviz does."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from rosx_commands.context import Environment
    from rosx_commands.rviz.config import RvizConfig


def default_config_path(env: Environment) -> Path:
    """rviz's own default config: ``~/.rviz/default.rviz``."""
    home = env.environ.get("HOME") or str(Path.home())
    return Path(home) / ".rviz" / "default.rviz"


def bundled_default() -> Path:
    """The rviz package's ``default.rviz`` that rosx ships."""
    from rosx.packages.crawl import PREFIX  # noqa: PLC0415 - the package index loads only when used

    return PREFIX / "share" / "rviz" / "default.rviz"


def starting_config(default: Path) -> RvizConfig:
    """The config rviz starts with when given none: ``default`` if it exists, else the
    bundled one.

    Raises:
        ConfigError: the file cannot be loaded.
    """
    from rosx_commands.rviz.config import load_config  # noqa: PLC0415 - this tool's parts load only when used

    return load_config(str(default if default.is_file() else bundled_default()))


__all__ = ["bundled_default", "default_config_path", "starting_config"]
