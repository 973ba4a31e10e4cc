"""``rosx rosclean check|purge``: the disk usage of ROS's log folders, and removing them.

As ROS 1's rosclean: the folders are the log folder (``ROS_LOG_DIR``, else ``ROS_HOME/log``,
`rosx.workspace.logdir`) labelled ``ROS node logs`` and ``ROS_HOME/rosmake`` (``rosmake logs``),
those that exist. ``check`` prints ``du -sh``'s size and the label of each. ``purge`` prints
``Purging <label>.``, shows the ``rm -rf <folder>`` it will run and asks ``(y/n)?`` (lines are
read until one is ``y`` or ``n``), or runs it at once with ``-y``. ``purge --size MB`` removes
the oldest entries of each folder until it is at most that many MB (``du -sb``'s bytes).
Usage errors are argparse's, status 2.
"""

from __future__ import annotations

import shutil
import subprocess
from collections.abc import Sequence
from pathlib import Path

from rosx_commands.cli import run_command
from rosx_commands.context import CommandError, Environment, ExitStatus

MB = 1024 * 1024
_UNSUPPORTED = "rosclean is not supported on this platform"


def _folders(env: Environment) -> list[tuple[Path, str]]:
    from rosx.workspace.logdir import log_dir, ros_home  # noqa: PLC0415 - workspace code loads only when used

    folders = [
        (log_dir(env.environ), "ROS node logs"),
        (ros_home(env.environ) / "rosmake", "rosmake logs"),
    ]
    return [(folder, label) for folder, label in folders if folder.is_dir()]


def _du(*args: str) -> str:
    du = shutil.which("du")
    if du is None:
        raise CommandError(_UNSUPPORTED, ExitStatus.ERROR)
    try:
        done = subprocess.run([du, *args], capture_output=True, text=True, check=False)
        return done.stdout.split()[0]
    except (OSError, IndexError):
        raise CommandError(_UNSUPPORTED, ExitStatus.ERROR) from None


def _bytes(path: Path) -> int:
    try:
        return int(_du("-sb", str(path)))
    except ValueError:
        raise CommandError(_UNSUPPORTED, ExitStatus.ERROR) from None


def _ask(env: Environment, what: str) -> bool:
    env.stdout.write(f"Okay to perform:\n\n{what}\n(y/n)?\n")
    env.stdout.flush()
    while True:
        line = env.stdin.readline()
        answer = line.strip().lower()
        if answer in ("y", "n"):
            return answer == "y"
        if not line:  # end of input: nothing more will come
            return False


def _remove(env: Environment, path: Path) -> None:
    try:
        if path.is_dir() and not path.is_symlink():
            shutil.rmtree(path)
        else:
            path.unlink()
    except OSError:
        env.err("FAILED to execute command")


def _quoted(path: Path) -> str:
    return f'"{path}"' if " " in str(path) else str(path)


def _check(env: Environment) -> int:
    for folder, label in _folders(env):
        env.out(f"{_du('-sh', str(folder))} {label}")
    return ExitStatus.OK


def _purge(env: Environment, yes: bool, size: int | None) -> int:
    for folder, label in _folders(env):
        if not size:
            env.out(f"Purging {label}.")
            if yes:
                _remove(env, folder)
            else:
                env.out("PLEASE BE CAREFUL TO VERIFY THE COMMAND BELOW!")
                if _ask(env, f"rm -rf {_quoted(folder)}"):
                    _remove(env, folder)
            continue
        entries = sorted(folder.iterdir(), key=lambda p: p.lstat().st_mtime)
        used = _bytes(folder)
        if used <= size * MB:
            env.out(
                f"Directory size of {label} is {used // MB} MB which is already below the "
                f"requested threshold of {size} MB."
            )
            continue
        env.out(
            f"Purging {label} until directory size is at most {size} MB "
            f"(currently {used // MB} MB)."
        )
        if not yes:
            env.out("PLEASE BE CAREFUL TO VERIFY THE COMMAND BELOW!")
            if not _ask(env, f"Purge some of old logs in {folder}"):
                return ExitStatus.OK
        for entry in entries:
            if used <= size * MB:
                break
            used -= _bytes(entry)
            _remove(env, entry)
    return ExitStatus.OK


def _rosclean(argv: list[str], env: Environment) -> int:
    from rosx_commands.argparser import ToolArgumentParser  # noqa: PLC0415 - this tool's parts load only when used

    parser = ToolArgumentParser(env, "rosclean")
    commands = parser.add_commands("{check,purge}")
    commands.add_parser("check", help="Check usage of log files")
    purge = commands.add_parser("purge", help="Remove log files")
    purge.add_argument(
        "-y",
        action="store_true",
        default=False,
        help="CAUTION: automatically confirms all questions to delete files",
    )
    purge.add_argument(
        "--size",
        action="store",
        default=None,
        type=int,
        help="Maximum total size in MB to keep when deleting old files",
    )
    args = parser.parse(argv)
    if getattr(args, "{check,purge}") == "check":
        return _check(env)
    return _purge(env, args.y, args.size)


def rosclean(argv: Sequence[str], env: Environment) -> int:
    """Run ``rosclean ARGV…``."""
    return run_command(_rosclean, list(argv), env, error_status=ExitStatus.ERROR)
