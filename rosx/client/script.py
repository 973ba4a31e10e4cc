"""Running a user's ROS Python script with rosx's ``rospy`` and message modules.

`run_script` runs a file as ``python FILE ARGS…`` would (``__main__``, ``sys.argv``, the
script's directory first on ``sys.path``), with the ``rospy`` shim importable (`SHIM_DIR`, also
put on ``PYTHONPATH`` for the programs the script starts) and ``<package>.msg`` /
``<package>.srv`` served by `rosx.client.modules`. What the user sees when the script fails is
what Python shows, without rosx's own frames:

* a syntax error: the file, the line, the caret and the message, as Python prints them;
* an uncaught exception: the traceback of the script's frames only;
* Ctrl-C, or a `ROSInterruptException` that reaches the top once the node is shutting down,
  or the API's refusal to go on after Ctrl-C (``init_node interrupted…``): nothing; the status
  is 0 after a shutdown, as with rospy, whose sleeps return quietly.
"""

from __future__ import annotations

import os
import sys
import traceback
import types
from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from collections.abc import Mapping, Sequence
    from typing import TextIO

#: The directory holding the ``rospy`` shim package. Higher layers that serve a ROS 1 module to
#: scripts keep it in their own such directory; whoever runs scripts passes them all (``dirs``).
SHIM_DIR = Path(__file__).resolve().parent / "shim"

_SIGINT_STATUS = 130
_API_DIR = str(Path(__file__).resolve().parent) + os.sep


def shim_environ(environ: Mapping[str, str], dirs: Sequence[Path] = (SHIM_DIR,)) -> dict[str, str]:
    """``environ`` with the shim directories ``dirs`` first on ``PYTHONPATH`` (once each)."""
    env = dict(environ)
    shims = [str(d) for d in dirs]
    entries = [p for p in env.get("PYTHONPATH", "").split(os.pathsep) if p and p not in shims]
    env["PYTHONPATH"] = os.pathsep.join([*shims, *entries])
    return env


def prepare_imports(dirs: Sequence[Path] = (SHIM_DIR,)) -> None:
    """Make ``import rospy`` (and the modules of the other ``dirs``) and ``<package>.msg``
    give rosx's, in this process."""
    from rosx.client.modules import install  # noqa: PLC0415 - the rospy API loads only when used

    for shim in reversed([str(d) for d in dirs]):
        if shim not in sys.path:
            sys.path.insert(0, shim)
    os.environ.update({"PYTHONPATH": shim_environ(os.environ, dirs)["PYTHONPATH"]})
    install()


def _user_traceback(error: BaseException, path: str) -> str:
    """The traceback Python would print for the script, without the frames of the runner
    and of the rospy-compatible API (where a wrong call ends), as for rospy's own modules."""
    tb = error.__traceback__
    while tb is not None and tb.tb_frame.f_code.co_filename != path:
        tb = tb.tb_next
    report = traceback.TracebackException(type(error), error, tb)
    pending = [report]
    while pending:
        current = pending.pop()
        frames = [f for f in current.stack if not f.filename.startswith(_API_DIR)]
        current.stack = traceback.StackSummary.from_list(frames or current.stack)
        pending += [e for e in (current.__cause__, current.__context__) if e is not None]
    return "".join(report.format())


def run_script(
    path: str,
    args: Sequence[str],
    stderr: TextIO | None = None,
    shim_dirs: Sequence[Path] = (SHIM_DIR,),
) -> int:
    """Run the Python script at ``path`` with ``args``, the modules of ``shim_dirs`` importable;
    its exit status.

    Raises nothing for the script's own failures: they are printed on ``stderr``.
    """
    err = sys.stderr if stderr is None else stderr
    try:
        source = Path(path).read_bytes()
    except OSError as error:
        err.write(
            f"rosx run-script: can't open file '{path}': [Errno {error.errno}] {error.strerror}\n"
        )
        return 2
    try:
        code = compile(source, path, "exec", dont_inherit=True)
    except (SyntaxError, ValueError) as error:
        err.write("".join(traceback.format_exception_only(type(error), error)))
        return 1
    prepare_imports(shim_dirs)
    sys.argv = [path, *args]
    sys.path.insert(0, str(Path(path).resolve().parent))
    main = types.ModuleType("__main__")
    main.__file__ = path
    main.__builtins__ = __builtins__  # type: ignore[attr-defined]
    sys.modules["__main__"] = main
    return _execute(code, main, path, err)


def _execute(code: types.CodeType, main: types.ModuleType, path: str, err: TextIO) -> int:
    from rosx.client import state  # noqa: PLC0415 - the rospy API loads only when used

    try:
        exec(code, main.__dict__)
    except SystemExit as done:
        return _exit_status(done.code, err)
    except KeyboardInterrupt as interrupt:
        if state.CLIENT.is_shutdown() or state.CLIENT.requested:
            return 0
        if type(interrupt) is KeyboardInterrupt:
            return _SIGINT_STATUS
        err.write(_user_traceback(interrupt, path))
        return 1
    except BaseException as error:
        if _stopped_by_signal(error):
            return 0
        err.write(_user_traceback(error, path))
        return 1
    return 0


def _stopped_by_signal(error: BaseException) -> bool:
    """Whether ``error`` is the API's answer to Ctrl-C or SIGTERM (``init_node`` interrupted
    while it waited for the master, say): the user asked to stop, nothing went wrong."""
    from rosx.client import state  # noqa: PLC0415 - the rospy API loads only when used
    from rosx.client.exceptions import ROSException  # noqa: PLC0415 - the rospy API loads only when used

    client = state.CLIENT
    return isinstance(error, ROSException) and client.shutdown_reason.startswith("signal-")


def _exit_status(code: object, err: TextIO) -> int:
    if code is None:
        return 0
    if isinstance(code, int):
        return code
    err.write(f"{code}\n")
    return 1


__all__ = ["SHIM_DIR", "prepare_imports", "run_script", "shim_environ"]
