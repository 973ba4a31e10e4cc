"""Starting Python nodes fast: a process that has rosx's ``rospy`` loaded forks them.

Most of a Python node's start-up is Python's: the interpreter, then ``import rospy`` and the
message types (about 0.2 s of CPU each). A launch of five nodes on two cores spends a second on
it. The launcher therefore starts, next to itself and at once, one helper process (``python -m
rosx.launch.run.zygote FD``) that imports all of that and waits; each Python node is then a
``fork`` of it that runs the node's script (`rosx.client.script.run_script`), in a session of
its own, with the node's environment, working folder, arguments and output. It is still one
process per node, with its own pid, signals and exit status; only the cost of loading Python is
paid once.

The helper is single-threaded (nothing it imports starts a thread), so forking it is safe. It
talks with the launcher over a socket (`ZygoteClient`), one JSON document a line:

* the launcher first says ``{"packages": {NAME: DIR, …} or null}``: its crawl of the package
  path (the helper's too), which the helper's type store then uses instead of crawling it
  again (hundreds of milliseconds on Debian's ``/usr/share``); the helper loads after that;
* the launcher asks ``{"id": N, "script": PATH, "args": [...], "env": {...}, "cwd": DIR,
  "stdout": FILE or null, "append": BOOL}``; the helper opens FILE, forks, and answers
  ``{"id": N, "pid": PID}`` (or ``{"id": N, "error": TEXT}``: FILE cannot be opened, or the
  fork failed). So a node's ``-stdout.log`` exists once the launcher says it started, as with
  ROS 1's roslaunch, whose child inherits the file already open;
* when a node ends, the helper (its parent) reaps it and says ``{"exit": PID, "code": CODE}``
  (a signal's death as its negative number, as `subprocess` reports it).

When the launcher goes away (the socket closes) the helper ends; nodes still running are the
launcher's to stop, as it does. Scripts whose environment changes what the helper loaded
(``ROS_PACKAGE_PATH``, ``PYTHONPATH``) or that have a ``launch-prefix`` are started the usual
way instead (`rosx.launch.run.monitor.LocalProcess`).
"""

from __future__ import annotations

import contextlib
import json
import os
import select
import signal
import socket
import subprocess
import sys
import threading
from typing import TYPE_CHECKING, Any

from rosx.launch.run.monitor import LocalProcess

if TYPE_CHECKING:
    from collections.abc import Callable, Mapping, Sequence
    from pathlib import Path

#: Variables that decide what the helper has loaded: a node must have the helper's values.
LOADED_FROM = ("ROS_PACKAGE_PATH", "PYTHONPATH")


def _preload(crawled: Mapping[str, str] | None) -> None:
    """Import what a rospy node imports, and the types every node uses; ``crawled`` is the
    launcher's crawl of the package path (the helper's own), which it then need not redo."""
    if crawled is not None:
        from pathlib import Path  # noqa: PLC0415 - pathlib is not needed at start-up

        from rosx.msg.store import share_package_index  # noqa: PLC0415 - the type store loads on first use
        from rosx.packages.crawl import split_package_path  # noqa: PLC0415 - the package index loads only when used
        from rosx.packages.index import PackageIndex  # noqa: PLC0415 - the package index loads only when used

        package_path = split_package_path(os.environ.get("ROS_PACKAGE_PATH"))
        found = {name: Path(directory) for name, directory in crawled.items()}
        share_package_index(PackageIndex(package_path, crawled=found))

    from rosx.client.script import prepare_imports  # noqa: PLC0415 - the rospy API loads only when used

    prepare_imports()
    import rospy  # type: ignore[import-not-found]  # noqa: F401, PLC0415 - rosx's, via the shim

    from rosx.msg.codec.classes import get_message_class  # noqa: PLC0415 - message classes load on first use

    for name in ("rosgraph_msgs/Log", "std_msgs/String", "geometry_msgs/Twist"):
        with contextlib.suppress(Exception):
            get_message_class(name)


def _open_stdout(request: Mapping[str, Any]) -> int | None:
    """The node's stdout log, opened as the request says (None: it keeps the helper's)."""
    if not request.get("stdout"):
        return None
    flags = os.O_WRONLY | os.O_CREAT | (os.O_APPEND if request["append"] else os.O_TRUNC)
    return os.open(request["stdout"], flags, 0o644)


def _child(
    request: Mapping[str, Any], stdout: int | None, inherited: Sequence[socket.socket]
) -> None:
    """In the fork: become the node, run its script, and exit with its status as a Python
    process exits (``atexit`` hooks and the node's own shutdown run); never returns."""
    code = 1
    try:
        signal.set_wakeup_fd(-1)
        for sock in inherited:
            sock.close()
        for sig in (signal.SIGTERM, signal.SIGCHLD, signal.SIGHUP):
            signal.signal(sig, signal.SIG_DFL)
        signal.signal(signal.SIGINT, signal.default_int_handler)
        os.setsid()
        os.environ.clear()
        os.environ.update(request["env"])
        os.chdir(request["cwd"])
        if stdout is not None:
            # A helper started without a stdout has no ``sys.stdout``, and the log may have
            # taken file descriptor 1 itself.
            if stdout != 1:
                os.dup2(stdout, 1)
                os.close(stdout)
            if sys.stdout is None:
                sys.stdout = open(1, "w", closefd=False)  # noqa: SIM115
        from rosx.client.script import run_script  # noqa: PLC0415 - the rospy API loads only when used

        code = run_script(request["script"], request["args"])
    except KeyboardInterrupt:
        code = 130
    except BaseException as error:  # the node must end with a status, never return here
        with contextlib.suppress(Exception):
            sys.stderr.write(f"{request.get('script')}: {error}\n")
    raise _NodeExit(code)


class _NodeExit(SystemExit):
    """Ends a forked node: unwinds out of the helper's loop to the interpreter's exit."""


def _send(control: socket.socket, message: Mapping[str, Any]) -> None:
    control.sendall((json.dumps(message) + "\n").encode())


def serve(fd: int) -> int:
    """The helper's loop on the control socket ``fd``; returns when the launcher is gone."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    control = socket.socket(fileno=fd)
    try:
        return _serve(control)
    except ConnectionError:
        # A launcher stopped early (Ctrl-C while the helper still loads) closes the socket
        # before the helper's next message: that is its way of saying it is gone.
        return 0


def _serve(control: socket.socket) -> int:
    lines = _Lines(control)
    first = lines.next()
    if first is None:
        return 0
    _preload(first.get("packages"))
    wake_read, wake_write = socket.socketpair()
    wake_write.setblocking(False)
    signal.set_wakeup_fd(wake_write.fileno(), warn_on_full_buffer=False)
    if sys.platform != "win32":  # the helper forks: POSIX only
        signal.signal(signal.SIGCHLD, lambda *_: None)
    _send(control, {"ready": os.getpid()})
    while True:
        for request in lines.buffered():
            stdout = None
            try:
                stdout = _open_stdout(request)
                pid = os.fork()
            except OSError as error:
                if stdout is not None:
                    os.close(stdout)
                _send(control, {"id": request["id"], "error": str(error)})
                continue
            if pid == 0:
                _child(request, stdout, (control, wake_read, wake_write))
            if stdout is not None:
                os.close(stdout)
            _send(control, {"id": request["id"], "pid": pid})
        ready, _, _ = select.select([control, wake_read], [], [])
        if wake_read in ready:
            with contextlib.suppress(BlockingIOError):
                wake_read.recv(4096)
            _reap(control)
        if control in ready and not lines.receive():
            return 0


class _Lines:
    """The launcher's messages, one JSON document a line."""

    def __init__(self, control: socket.socket) -> None:
        self.control = control
        self.buffer = b""

    def receive(self) -> bool:
        """Read what has come; False when the launcher has gone."""
        data = self.control.recv(1 << 16)
        self.buffer += data
        return bool(data)

    def buffered(self) -> list[dict[str, Any]]:
        """The complete messages read so far (taken)."""
        *lines, self.buffer = self.buffer.split(b"\n")
        return [json.loads(line) for line in lines]

    def next(self) -> dict[str, Any] | None:
        """The next message, waiting for it; None when the launcher has gone first."""
        while b"\n" not in self.buffer:
            if not self.receive():
                return None
        line, self.buffer = self.buffer.split(b"\n", 1)
        return dict(json.loads(line))


def _reap(control: socket.socket) -> None:
    while True:
        try:
            pid, status = os.waitpid(-1, os.WNOHANG)
        except ChildProcessError:
            return
        if pid == 0:
            return
        code = os.waitstatus_to_exitcode(status)
        with contextlib.suppress(OSError):
            _send(control, {"exit": pid, "code": code})


class ZygoteError(Exception):
    """The helper could not start a node (or is gone); the node is started the usual way."""


class ZygoteClient:
    """The launcher's side: start the helper, ask it for nodes, learn how they end.

    ``on_exit()`` is called (from a reader thread) after a node's exit is recorded;
    ``crawled`` is the launcher's crawl of the package path of ``environ`` (None: the helper
    crawls it).
    """

    def __init__(
        self,
        environ: Mapping[str, str],
        on_exit: Callable[[], object],
        crawled: Mapping[str, Path] | None = None,
    ) -> None:

        self.environ = dict(environ)
        self.on_exit = on_exit
        ours, theirs = socket.socketpair()
        self._socket = ours
        self.process = subprocess.Popen(
            [sys.executable, "-m", "rosx.launch.run.zygote", str(theirs.fileno())],
            env=self.environ,
            pass_fds=(theirs.fileno(),),
            start_new_session=True,
        )
        theirs.close()
        hello = {"packages": None if crawled is None else {k: str(v) for k, v in crawled.items()}}
        with contextlib.suppress(OSError):  # a helper gone at once is seen by the reader
            ours.sendall((json.dumps(hello) + "\n").encode())
        self._lock = threading.Lock()
        self._replies: dict[int, dict[str, Any]] = {}
        self._answered = threading.Condition(self._lock)
        self.exits: dict[int, int] = {}
        self._next = 0
        self._ready = False
        self._gone = False
        self._reader = threading.Thread(target=self._read, name="rosx-zygote", daemon=True)
        self._reader.start()

    def accepts(self, environ: Mapping[str, str]) -> bool:
        """Whether a node with ``environ`` can be forked from the helper."""
        from rosx.client.script import shim_environ  # noqa: PLC0415 - the rospy API loads only when used

        loaded = shim_environ(self.environ)
        return not self._gone and all(environ.get(k) == loaded.get(k) for k in LOADED_FROM)

    def _read(self) -> None:
        buffer = b""
        while True:
            try:
                data = self._socket.recv(1 << 16)
            except OSError:
                data = b""
            if not data:
                with self._lock:
                    self._gone = True
                    self._answered.notify_all()
                self.on_exit()
                return
            buffer += data
            while b"\n" in buffer:
                line, buffer = buffer.split(b"\n", 1)
                message = json.loads(line)
                with self._lock:
                    if "exit" in message:
                        self.exits[int(message["exit"])] = int(message["code"])
                    elif "ready" in message:
                        self._ready = True
                    else:
                        self._replies[int(message["id"])] = message
                    self._answered.notify_all()
                if "exit" in message:
                    self.on_exit()

    def start(
        self,
        script: str,
        args: Sequence[str],
        environ: Mapping[str, str],
        cwd: str,
        stdout: str | None,
        *,
        append: bool,
        timeout: float = 30.0,
    ) -> int:
        """Fork a node running ``script``; its pid.

        Raises:
            ZygoteError: the helper is gone or did not answer, or could not open ``stdout``
                or fork (the text says which).
        """
        with self._lock:
            self._next += 1
            ident = self._next
        request = {
            "id": ident,
            "script": script,
            "args": list(args),
            "env": dict(environ),
            "cwd": cwd,
            "stdout": stdout,
            "append": append,
        }
        try:
            self._socket.sendall((json.dumps(request) + "\n").encode())
        except OSError as error:
            raise ZygoteError(str(error)) from None
        with self._lock:
            if not self._answered.wait_for(
                lambda: ident in self._replies or self._gone, timeout=timeout
            ):
                raise ZygoteError("no answer")
            reply = self._replies.pop(ident, None)
        if reply is None or "pid" not in reply:
            raise ZygoteError(str(reply.get("error") if reply else "gone"))
        return int(reply["pid"])

    @property
    def gone(self) -> bool:
        """Whether the helper has ended."""
        with self._lock:
            return self._gone

    def exit_code(self, pid: int) -> int | None:
        """How node ``pid`` ended, once the helper has reaped it."""
        with self._lock:
            return self.exits.get(pid)

    def wait_ready(self, timeout: float) -> bool:
        """Wait until the helper has loaded everything (False: not within ``timeout``)."""
        with self._lock:
            return self._answered.wait_for(lambda: self._ready or self._gone, timeout=timeout)

    def close(self) -> None:
        """End the helper (nodes still running stay; the launcher stops them first)."""
        with contextlib.suppress(OSError):
            self._socket.shutdown(socket.SHUT_RDWR)
        self._socket.close()
        try:
            self.process.wait(5.0)
        except Exception:  # it must not outlive the launch
            self.process.kill()
            self.process.wait()
        self._reader.join(timeout=2.0)


class ForkedProcess(LocalProcess):
    """A `LocalProcess` running a Python script, forked by the helper (see the module).

    ``script_index`` is where the script's path is in the command line; what follows it (and
    ``__log:=``) are its arguments. When the helper cannot fork it, it starts as any process.
    """

    def __init__(self, *args: Any, zygote: ZygoteClient, script_index: int, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self.zygote = zygote
        self.script_index = script_index
        self.forked = False

    def start(self) -> None:
        """Fork the node from the helper, which has the Python modules loaded already; started as
        any process when the helper cannot take its environment or refuses."""
        argv = self.argv
        if not self.zygote.accepts(self.environ):
            self.forked = False
            super().start()
            return
        self.spawn_count += 1
        self.exit_code = self.time_of_death = None
        self.log_error = None
        with contextlib.suppress(OSError):
            self.cwd.mkdir(parents=True, exist_ok=True)
        stdout = self.stdout_path
        try:
            self.pid = self.zygote.start(
                argv[self.script_index],
                argv[self.script_index + 1 :],
                self.environ,
                str(self.cwd),
                None if stdout is None else str(stdout),
                append=self.respawn,
            )
        except ZygoteError:
            self.spawn_count -= 1
            self.forked = False
            super().start()
            return
        self.forked = True

    def _ended(self) -> tuple[bool, int | None]:
        code = self.zygote.exit_code(self.pid)
        if code is not None:
            return True, code
        if self.zygote.gone:  # no one to tell: look for the process itself
            try:
                os.kill(self.pid, 0)
            except ProcessLookupError:
                return True, None
        return False, None

    def poll(self) -> bool:
        """Whether the node still runs; records its exit code when it has ended."""
        if not self.forked:
            return super().poll()
        ended, code = self._ended()
        if not ended:
            return True
        self._record_death(code)
        return False

    def running(self) -> bool:
        """Whether the node still runs, without recording its death."""
        if not self.forked:
            return super().running()
        return not self._ended()[0]

    def signal(self, sig: signal.Signals) -> None:
        """Send ``sig`` to the node's process group (to the node alone before it leads one)."""
        if not self.forked:
            super().signal(sig)
            return
        if self._ended()[0]:
            return
        try:
            os.killpg(self.pid, sig)
        except (ProcessLookupError, PermissionError):  # not yet its own group leader
            with contextlib.suppress(ProcessLookupError):
                os.kill(self.pid, sig)

    def reap(self) -> None:
        """Kill what the node left running in its process group once it has ended."""
        if not self.forked:
            super().reap()
            return
        if self._ended()[0] and hasattr(os, "killpg"):
            with contextlib.suppress(ProcessLookupError, PermissionError):
                os.killpg(self.pid, signal.SIGKILL)  # children that outlived the node


if __name__ == "__main__":
    sys.exit(serve(int(sys.argv[1])))


__all__ = ["LOADED_FROM", "ForkedProcess", "ZygoteClient", "ZygoteError", "serve"]
