"""The processes of a launch: started, watched, restarted and stopped as ROS 1's roslaunch does.

A `LocalProcess` is one program (a node) with its roslaunch name (``g/talk-2``), command line,
environment, working folder and output: the terminal (``output="screen"``) or
``<run folder>/<name>-stdout.log`` (stderr always reaches the terminal, as in ROS 1). Each runs
in its own session and process group, so the terminal's Ctrl-C reaches only the launcher, which
then stops every node itself.

`ProcessMonitor` owns them. Its rules are ROS 1's (``roslaunch.pmon``, ``nodeprocess``); what
follows an exit is decided by the table of `rosx.launch.run.policy`, this module does it:

* a process that exits is reported once: ``[NAME] process has finished cleanly`` (bold) or
  ``[NAME] process has died [pid P, exit code C, cmd …].`` (red), each with its log file line;
* ``respawn``: it starts again ``respawn_delay`` seconds after it died
  (``[NAME] restarting process``);
* ``required``: its exit ends the launch (``REQUIRED process [NAME] has died!`` …
  ``Initiating shutdown!`` between two lines of ``=``);
* when every process has ended, none waits for a restart and nothing else keeps the launch
  alive (a core it started), the launch ends (``all processes on machine have died, roslaunch
  will exit``);
* SIGINT, SIGTERM and SIGHUP end it.

Stopping goes through the remaining processes in reverse order: ``[NAME] killing on exit`` and
SIGINT to each one's process group, then, for those still running after ``sigint_timeout``
seconds (15 by default), ``[NAME] escalating to SIGTERM``, and after ``sigterm_timeout`` more
(2 by default) ``[NAME] escalating to SIGKILL``. The signals go to all at once, so a launch of
many nodes stops in one timeout, not one per node. No process is left behind.

The monitor runs in the thread that calls `ProcessMonitor.spin`; in the main thread it also
installs the signal handlers (and restores the previous ones when it returns).
"""

from __future__ import annotations

import contextlib
import errno
import os
import select
import signal
import socket
import subprocess
import sys
import time
from typing import TYPE_CHECKING

from rosx.launch.run.policy import (
    Action,
    Ending,
    launch_ends,
    next_wake,
    on_exit,
    report_style,
    respawn_due,
)
from rosx.signals import handling

if TYPE_CHECKING:
    from collections.abc import Callable, Iterator, Sequence
    from pathlib import Path
    from typing import IO

    from rosx.launch.run.console import LaunchConsole

#: ROS 1's defaults (``roslaunch.nodeprocess``), in seconds.
DEFAULT_SIGINT_TIMEOUT = 15.0
DEFAULT_SIGTERM_TIMEOUT = 2.0

_STOP_SIGNALS = tuple(
    getattr(signal, name) for name in ("SIGINT", "SIGTERM", "SIGHUP") if hasattr(signal, name)
)
#: What ends a process that ignored SIGTERM (Windows has no SIGKILL; its SIGTERM cannot be caught).
_KILL = signal.SIGTERM if sys.platform == "win32" else signal.SIGKILL
#: Longest sleep between two looks at the processes when no signal wakes the monitor.
_IDLE = 0.5


class FatalLaunchError(Exception):
    """A process cannot be started and will not start by trying again; ``str()`` says why."""


class LocalProcess:
    """One program of the launch; `start` may run again for a respawn.

    Args:
        name: roslaunch's process name, ``<namespace/name>-<n>`` without the leading ``/``.
        argv: The command line (without ``__log:=``, which `start` adds for a node).
        environ: The process's whole environment.
        cwd: The folder it runs in.
        log_dir: The run's log folder (for ``__log:=`` and ``-stdout.log``), or None.
        log_output: True: stdout goes to ``<log_dir>/<name>-stdout.log``; False: the terminal.
        respawn: Start it again when it exits.
        respawn_delay: Seconds between an exit and the restart.
        required: Its exit ends the launch.
        is_node: Pass ``__log:=`` (programs that are not ROS nodes do not get it).
        package: The package the program is from.
        runner: Where in ``argv`` the words that run a Python script start, and how many they
            are: left out where the command is shown (ROS 1 runs the script itself).
    """

    def __init__(
        self,
        name: str,
        argv: Sequence[str],
        environ: dict[str, str],
        cwd: Path,
        *,
        log_dir: Path | None,
        log_output: bool,
        respawn: bool = False,
        respawn_delay: float = 0.0,
        required: bool = False,
        is_node: bool = True,
        package: str = "",
        runner: tuple[int, int] = (0, 0),
    ) -> None:
        self.name = name
        self.package = package
        self.runner = runner
        self.base_argv = list(argv)
        self.environ = environ
        self.cwd = cwd
        self.log_dir = log_dir
        self.log_output = log_output
        self.respawn = respawn
        self.respawn_delay = respawn_delay
        self.required = required
        self.is_node = is_node
        self.popen: subprocess.Popen[bytes] | None = None
        self.pid = -1
        self.exit_code: int | None = None
        self.time_of_death: float | None = None
        self.spawn_count = 0
        #: ROS 1's error when the last start could not open the stdout log, else None.
        self.log_error: str | None = None

    @property
    def log_name(self) -> str:
        """The name's ``/`` made ``-``: the stem of the process's log files."""
        return self.name.replace("/", "-")

    @property
    def argv(self) -> list[str]:
        """The command line as run, ``__log:=`` included for a node with a log folder."""
        if self.is_node and self.log_dir is not None:
            kept = [arg for arg in self.base_argv if not arg.startswith("__log:=")]
            return [*kept, f"__log:={self.log_dir / (self.log_name + '.log')}"]
        return list(self.base_argv)

    @property
    def stdout_path(self) -> Path | None:
        """Where stdout is logged (appended to across respawns); None: the terminal."""
        if not self.log_output or self.log_dir is None:
            return None
        return self.log_dir / f"{self.log_name}-stdout.log"

    def _stdout(self) -> IO[bytes] | int | None:
        """The stdout log, opened (None: the terminal). As in ROS 1, a log that cannot be
        opened does not keep the process from starting: `log_error` says why, and its output
        is dropped (ROS 1 gives it a pipe that nobody reads)."""
        self.log_error = None
        path = self.stdout_path
        if path is None:
            return None
        try:
            return path.open("ab" if self.respawn else "wb")
        except OSError as exc:
            self.log_error = f"[{self.name}] ERROR: unable to configure logging [{exc}]"
            return subprocess.DEVNULL

    def start(self) -> None:
        """Start the program.

        Raises:
            FatalLaunchError: it cannot be run (ROS 1's texts: missing program, no ``#!``…).
        """
        self.spawn_count += 1
        self.exit_code = self.time_of_death = None
        argv = self.argv
        with contextlib.suppress(OSError):
            self.cwd.mkdir(parents=True, exist_ok=True)
        stdout = self._stdout()
        try:
            self.popen = subprocess.Popen(
                argv,
                cwd=self.cwd,
                env=self.environ,
                stdout=stdout,
                close_fds=True,
                start_new_session=True,
            )
        except OSError as exc:
            self.popen = None
            self._record_death(1)
            raise FatalLaunchError(_launch_failure(self.name, argv, exc)) from None
        finally:
            if stdout is not None and not isinstance(stdout, int):
                stdout.close()
        self.pid = self.popen.pid

    def poll(self) -> bool:
        """Whether the process is running; records its exit code and time of death."""
        if self.popen is None:
            return False
        code = self.popen.poll()
        if code is None:
            return True
        self._record_death(code)
        return False

    def _record_death(self, code: int | None) -> None:
        """Note the exit ``code`` (None: unknown) and the time of death, once a death."""
        if self.time_of_death is None:
            self.exit_code = code
            self.time_of_death = time.monotonic()

    def running(self) -> bool:
        """Whether the process has been started and has not ended (records nothing)."""
        return self.popen is not None and self.popen.poll() is None

    @property
    def shown_argv(self) -> list[str]:
        """`argv` as ROS 1 would run it: a Python script's path first, not the words that run
        it with rosx's Python (`runner`)."""
        start, count = self.runner
        argv = self.argv
        return [*argv[:start], *argv[start + count :]]

    def exit_description(self) -> str:
        """ROS 1's words for how the process ended, with its log files."""
        command = " ".join(self.shown_argv)
        if self.exit_code is None:
            text = f"process has died without exit code [pid {self.pid}, cmd {command}]."
        elif self.exit_code != 0:
            text = f"process has died [pid {self.pid}, exit code {self.exit_code}, cmd {command}]."
        else:
            text = "process has finished cleanly"
        if self.log_dir is not None:
            text += f"\nlog file: {self.log_dir / self.log_name}*.log"
        return text

    def signal(self, sig: signal.Signals) -> None:
        """Send ``sig`` to the process's group (it leads its own)."""
        if self.popen is None or self.popen.returncode is not None:
            return
        try:
            os.killpg(self.popen.pid, sig)
        except ProcessLookupError:
            pass
        except PermissionError:  # the group is gone and its id was taken: the leader only
            with contextlib.suppress(ProcessLookupError):
                self.popen.send_signal(sig)

    def reap(self) -> None:
        """Wait for an ended process and for what is left of its group."""
        if self.popen is None:
            return
        self.popen.poll()
        if self.popen.returncode is not None and hasattr(os, "killpg"):
            with contextlib.suppress(ProcessLookupError, PermissionError):
                os.killpg(self.popen.pid, signal.SIGKILL)  # children that outlived the node


def _launch_failure(name: str, argv: Sequence[str], exc: OSError) -> str:
    if exc.errno == errno.ENOEXEC:
        return (
            f"Unable to launch [{name}]. \n"
            "If it is a script, you may be missing a '#!' declaration at the top."
        )
    if exc.errno == errno.ENOENT:
        return (
            f"Roslaunch got a '{exc.strerror}' error while attempting to run:\n"
            f"{' '.join(argv)}\n"
            "Please make sure that all the executables in this command exist and have\n"
            "executable permission. This is often caused by a bad launch-prefix."
        )
    return f"unable to launch [{' '.join(argv)}]: {exc.strerror}"


class _Wakeup:
    """A socket pair the signal machinery writes to, so a sleeping monitor wakes at once."""

    def __init__(self) -> None:
        self.reader, self.writer = socket.socketpair()
        self.reader.setblocking(False)
        self.writer.setblocking(False)

    def wait(self, timeout: float) -> None:
        with contextlib.suppress(InterruptedError, OSError, ValueError):
            ready, _, _ = select.select([self.reader], [], [], max(timeout, 0.0))
            if ready:
                with contextlib.suppress(BlockingIOError):
                    self.reader.recv(4096)

    def poke(self) -> None:
        with contextlib.suppress(OSError):
            self.writer.send(b"\0")

    def close(self) -> None:
        self.reader.close()
        self.writer.close()


class ProcessMonitor:
    """Starts, watches, restarts and stops the processes of one launch (see the module)."""

    def __init__(
        self,
        console: LaunchConsole,
        *,
        sigint_timeout: float = DEFAULT_SIGINT_TIMEOUT,
        sigterm_timeout: float = DEFAULT_SIGTERM_TIMEOUT,
    ) -> None:
        self.console = console
        self.sigint_timeout = sigint_timeout
        self.sigterm_timeout = sigterm_timeout
        self.procs: list[LocalProcess] = []
        #: The processes that ended for good, oldest first.
        self.dead: list[LocalProcess] = []
        self._respawns: list[LocalProcess] = []
        self._wakeup = _Wakeup()
        self._stop_requested = False
        #: Whether the core this launch started was asked to shut down (None: it started
        #: none). A core keeps the launch going when every node has ended.
        self.core_ended: Callable[[], bool] | None = None
        self.shutdown_errors: list[str] = []

    def start(self, process: LocalProcess) -> bool:
        """Register ``process`` and start it; False (with ROS 1's error) if it could not be
        run. One that ran and has already exited has started: `spin` reports its exit."""
        self.procs.append(process)
        try:
            process.start()
        except FatalLaunchError as exc:
            self.console.error(str(exc))
            self.procs.remove(process)
            return False
        if process.log_error is not None:
            self.console.error(process.log_error)
        self.console.bold(f"process[{process.name}]: started with pid [{process.pid}]")
        return True

    def wake(self) -> None:
        """Make the monitor look at its processes now (any thread)."""
        self._wakeup.poke()

    def sleep(self, seconds: float) -> None:
        """Sleep up to ``seconds``; a signal ends the sleep early."""
        self._wakeup.wait(seconds)

    def request_stop(self) -> None:
        """End `spin` soon (any thread, or a signal handler)."""
        self._stop_requested = True
        self._wakeup.poke()

    @contextlib.contextmanager
    def signals(self) -> Iterator[None]:
        """While inside, SIGINT, SIGTERM and SIGHUP stop the launch and SIGCHLD wakes the
        monitor (only in the main thread; elsewhere nothing changes)."""
        try:
            old_fd = signal.set_wakeup_fd(self._wakeup.writer.fileno(), warn_on_full_buffer=False)
        except ValueError:  # not the main thread
            yield
            return
        try:
            with (
                handling(_STOP_SIGNALS, self._on_stop_signal),
                handling((signal.SIGCHLD,), _on_child),
            ):
                yield
        finally:
            signal.set_wakeup_fd(old_fd)

    def _on_stop_signal(self, signum: int) -> None:
        self._stop_requested = True

    def spin(self) -> None:
        """Watch the processes until the launch ends (the rules: `rosx.launch.run.policy`)."""
        while not self._stop_requested:
            ended = self._check_processes()
            core_started = self.core_ended is not None
            ending = launch_ends(
                stop_requested=self._stop_requested,
                core_started=core_started,
                core_ended=core_started and not self._stop_requested and self._core_ended(),
                ended_for_good=ended,
                running=len(self.procs),
                respawning=len(self._respawns),
            )
            if ending is Ending.ALL_DIED:
                self.console.line("all processes on machine have died, roslaunch will exit")
            if ending is not None:
                break
            self._restart_due()
            self._wakeup.wait(self._next_wake())

    def _core_ended(self) -> bool:
        return self.core_ended is not None and self.core_ended()

    @property
    def stop_requested(self) -> bool:
        """Whether a signal or `request_stop` asked the launch to end."""
        return self._stop_requested

    def _check_processes(self) -> bool:
        """Report the processes that ended; whether any ended for good (a required one's end
        also asks the launch to stop)."""
        ended = False
        for process in list(self.procs):
            if process in self._respawns or process.poll():
                continue
            description = process.exit_description()
            for action in on_exit(required=process.required, respawn=process.respawn):
                if action is Action.REPORT_REQUIRED:
                    rule = "=" * 80
                    self.console.error(
                        f"{rule}REQUIRED process [{process.name}] has died!\n{description}\n"
                        f"Initiating shutdown!\n{rule}"
                    )
                elif action is Action.STOP_LAUNCH:
                    self._stop_requested = True
                    return True
                elif action is Action.REPORT:
                    if report_style(process.exit_code) == "error":
                        self.console.error(f"[{process.name}] {description}")
                    else:
                        self.console.bold(f"[{process.name}] {description}")
                elif action is Action.RESPAWN:
                    self._respawns.append(process)
                else:  # Action.FORGET
                    process.reap()
                    self.procs.remove(process)
                    self.dead.append(process)
                    ended = True
        return ended

    def _restart_due(self) -> None:
        now = time.monotonic()
        for process in list(self._respawns):
            if self._stop_requested:
                return
            died = process.time_of_death if process.time_of_death is not None else now
            if not respawn_due(died, process.respawn_delay, now):
                continue
            self._respawns.remove(process)
            self.console.line(f"[{process.name}] restarting process")
            process.reap()
            try:
                process.start()
            except FatalLaunchError as exc:
                self.console.error(str(exc))
                self.procs.remove(process)
                continue
            if process.log_error is not None:
                self.console.error(process.log_error)
            self.console.bold(f"process[{process.name}]: started with pid [{process.pid}]")

    def _next_wake(self) -> float:
        now = time.monotonic()
        deaths = [
            (now if p.time_of_death is None else p.time_of_death, p.respawn_delay)
            for p in self._respawns
        ]
        return next_wake(deaths, now, _IDLE)

    def stop_all(self) -> None:
        """Stop every remaining process, newest first (see the module); never raises."""
        remaining = list(reversed(self.procs))
        for process in remaining:
            self.console.line(f"[{process.name}] killing on exit")
            process.signal(signal.SIGINT)
        running = self._wait(remaining, self.sigint_timeout)
        for process in running:
            self.console.error(f"[{process.name}] escalating to SIGTERM")
            process.signal(signal.SIGTERM)
        running = self._wait(running, self.sigterm_timeout)
        for process in running:
            self.console.error(f"[{process.name}] escalating to SIGKILL")
            self.shutdown_errors.append(
                f"process[{process.name}, pid {process.pid}]: required SIGKILL. "
                "May still be running."
            )
            process.signal(_KILL)
        self._wait(running, self.sigterm_timeout)
        for process in remaining:
            process.reap()
        self.procs.clear()
        self._respawns.clear()

    def _wait(self, processes: list[LocalProcess], timeout: float) -> list[LocalProcess]:
        """Wait up to ``timeout`` seconds for ``processes`` to end; those still running."""
        deadline = time.monotonic() + timeout
        running = [p for p in processes if p.running()]
        while running:
            left = deadline - time.monotonic()
            if left <= 0:
                break
            self._wakeup.wait(min(left, 0.05))
            running = [p for p in running if p.running()]
        return running

    def close(self) -> None:
        """Release the wake-up sockets."""
        self._wakeup.close()


def _on_child(signum: int) -> None:
    """SIGCHLD: nothing to do here; the wake-up byte makes the monitor look."""


__all__ = [
    "DEFAULT_SIGINT_TIMEOUT",
    "DEFAULT_SIGTERM_TIMEOUT",
    "FatalLaunchError",
    "LocalProcess",
    "ProcessMonitor",
]
