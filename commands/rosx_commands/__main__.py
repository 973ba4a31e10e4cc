"""``python -m rosx_commands …`` is ``rosx …``."""

from rosx_commands.main import run

run()
