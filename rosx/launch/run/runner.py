"""Running a launch plan: the core, the parameters, the nodes, and what roslaunch prints.

`LaunchRun.run` does what ROS 1's parent roslaunch does, in its order and with its words:

1. the run id (the running master's ``/run_id``, or a new one for a core it starts), the log
   folder (`rosx.workspace.logdir`) and ``... logging to …/roslaunch-<host>-<pid>.log``, the
   disk-usage check, the terminal title; then the launch files are loaded;
2. the roslaunch server (``started roslaunch server URI``), then the SUMMARY of parameters and
   nodes;
3. the master: the one at ``ROS_MASTER_URI`` (or at ``-p PORT``), or, when none answers, a core
   started in this process (``auto-starting new master``, ``process[master]…``,
   ``setting /run_id to …``, ``process[rosout-1]…``, ``started core service [/rosout]``);
4. ``<rosparam command="delete|dump">``, then the ``clear_params`` namespaces are cleared, then
   every parameter is set, before any node starts;
5. every node on this machine as its own process (`rosx.launch.run.monitor`), numbered after the
   core's (``process[ns/name-N]: started with pid [PID]``);
6. the processes are watched until Ctrl-C, SIGTERM, a required node's exit or the end of every
   node; then they are stopped newest first, the core last, and ``done`` is printed.

How a node is started: its command line is ROS 1's (`rosx.launch.process.node_command_line`,
which ``--args`` prints), except that a Python script runs with rosx's Python and ``rospy``
(the ``script_command`` given, as ``rosrun`` runs scripts). Every node gets
``ROSX_HEADLESS=1``: many nodes share the launcher's terminal, so none may take it over
(turtlesim_node logs instead of drawing its pond).

Errors that stop a launch before it starts anything are `LaunchFailedError`; ``str()`` is the text
after ``RLException: ``. Once the launcher's log is open, `LaunchRun.run` reports them itself as
roslaunch does: ``RLException: …`` and ``The traceback for the exception was written to the log
file`` on stderr, the traceback in the log.

``-v`` prints what ROS 1's prints while it reads the files: roscore.xml first (``... loading XML
file``, ``... executing command param [rosversion roslaunch]``, ``Added parameter``, ``Added core
node of type [rosout/rosout]``), then each file's parameters and nodes. What still differs from
Debian's ``roslaunch -v`` (compared on one file, a master started by each): roscore.xml is
rosx's own (``ROS_ETC_DIR``, else the one rosx ships, where Debian reads ``/etc/ros``) and its
``rosversion`` commands are not run (rosx's core sets the values itself: ``noetic``,
``1.16.0``, where Debian's packaging says ``Debian``, ``1.15.15``); the lines are rebuilt from
the loaded plan, so a parameter a file sets twice is listed once, where the file has it; URIs
name ``localhost`` unless ``ROS_HOSTNAME``/``ROS_IP`` say otherwise (ROS 1: the host name);
bold text and terminal titles are written only to a terminal (ROS 1 writes their escapes to
pipes and files too).
"""

from __future__ import annotations

import contextlib
import os
import shlex
import sys
from pathlib import Path
from typing import TYPE_CHECKING, Any

from rosx.launch.errors import LaunchError, ResourceNotFoundError
from rosx.launch.model import CORE_SOURCE
from rosx.launch.run.monitor import (
    DEFAULT_SIGINT_TIMEOUT,
    DEFAULT_SIGTERM_TIMEOUT,
    LocalProcess,
    ProcessMonitor,
)
from rosx.master.client import MasterClient, MasterError, MasterUnreachable
from rosx.master.defaults import master_uri as default_master_uri
from rosx.names.resolution import ns_join
from rosx.packages.crawl import split_package_path
from rosx.transport.address import advertised_host, http_uri, is_local_host
from rosx.wire.xmlrpc_http import parse_http_uri
from rosx.workspace import logdir
from rosx.workspace.executables import is_python_script
from rosx.workspace.programs import bundled_program, overlays

if TYPE_CHECKING:
    from collections.abc import Callable, Mapping, Sequence

    from rosx.launch.model import LaunchPlan, Node
    from rosx.launch.run.console import LaunchConsole
    from rosx.launch.run.zygote import ZygoteClient
    from rosx.packages.index import PackageIndex

#: The environment variable every launched node gets (see the module docstring).
HEADLESS = "ROSX_HEADLESS"
_CALLER = "/roslaunch"
#: The commands of roscore.xml's ``<param command=…>`` tags, by parameter.
_CORE_COMMANDS = {"/rosversion": "rosversion roslaunch", "/rosdistro": "rosversion -d"}
_CONNECT_TIMEOUT = 2.0


class LaunchFailedError(Exception):
    """The launch cannot go on; ``str()`` is what follows `prefix`: ``RLException: ``, or
    rospkg's ``Resource not found: `` for a package ``$(find)`` did not find."""

    def __init__(self, message: str, prefix: str = "RLException: ") -> None:
        super().__init__(message)
        self.prefix = prefix


class LaunchSettings:
    """roslaunch's options that change how a plan runs (its command-line switches)."""

    def __init__(
        self,
        *,
        port: int | None = None,
        wait_for_master: bool = False,
        local_only: bool = False,
        force_screen: bool = False,
        force_log: bool = False,
        force_required: bool = False,
        show_summary: bool = True,
        verbose: bool = False,
        skip_log_check: bool = False,
        titles: bool = True,
        sigint_timeout: float = DEFAULT_SIGINT_TIMEOUT,
        sigterm_timeout: float = DEFAULT_SIGTERM_TIMEOUT,
        shim_dirs: Sequence[Path] = (),
    ) -> None:
        self.port = port
        self.wait_for_master = wait_for_master
        self.local_only = local_only
        self.force_screen = force_screen
        self.force_log = force_log
        self.force_required = force_required
        self.show_summary = show_summary
        self.verbose = verbose
        self.skip_log_check = skip_log_check
        self.titles = titles
        self.sigint_timeout = sigint_timeout
        self.sigterm_timeout = sigterm_timeout
        #: The directories of the ROS modules rosx serves to Python nodes (``rospy``,
        #: ``rosbag``…), composed by the command above every layer that has one; the client
        #: layer's alone when empty.
        self.shim_dirs = tuple(shim_dirs)


def provided_program(
    package: str, node_type: str, index: PackageIndex | None = None
) -> list[str] | None:
    """The program rosx ships for ``package``/``node_type`` (turtlesim's nodes), if any: it is
    run instead of a system's same-named package on ``ROS_PACKAGE_PATH``, but not instead of a
    workspace's (`rosx.workspace.programs.overlays`), as ``rosrun`` does."""
    path = bundled_program(package, node_type)
    if path is None:
        return None
    if index is not None and overlays(index.path_packages.get(package), node_type):
        return None
    return [str(path)]


def master_uri(environ: Mapping[str, str], port: int | None) -> str:
    """The master a launch uses: ``-p PORT`` on this host, else ``ROS_MASTER_URI``."""
    if port is not None:
        return http_uri(advertised_host(environ), port)
    return default_master_uri(environ)


def _uri_host_port(uri: str) -> tuple[str, int]:
    try:
        host, port, _ = parse_http_uri(uri)
    except ValueError:
        raise LaunchFailedError(f"invalid ROS_MASTER_URI [{uri}]") from None
    return host, port


def _hostname_to_rosname(host: str) -> str:
    return "host_" + "".join(c if c.isascii() and c.isalnum() else "_" for c in host.lower())


def unify_clear_params(namespaces: Sequence[str]) -> list[str]:
    """The namespaces to clear, each ending with ``/``, those inside another dropped."""
    canon: list[str] = []
    for given in namespaces:
        name = given if given.endswith("/") else given + "/"
        if name not in canon:
            canon.append(name)
    kept = list(canon)
    for name in canon:
        if name == "/":
            continue
        parts = [p for p in name.split("/") if p]
        parents = ["/" + "".join(f"{q}/" for q in parts[:i]) for i in range(len(parts))]
        if any(parent in canon for parent in parents):
            kept.remove(name)
    return kept


class LaunchRun:
    """One run of a plan (see the module docstring).

    Args:
        load: Loads the launch files (with roscore's parameters, as roslaunch runs); called
            once the launcher's log is open, as roslaunch loads them.
        settings: The command line's switches.
        environ: The launcher's environment (copied into each node's).
        console: Where roslaunch's lines go.
        package_index: Where packages are (for the nodes' executables).
        script_command: The words that run a Python script with rosx's ``rospy`` (the script's
            path and arguments follow).
        title: The terminal title (the launch files, comma-separated).
    """

    def __init__(
        self,
        load: Callable[[], LaunchPlan],
        settings: LaunchSettings,
        environ: Mapping[str, str],
        console: LaunchConsole,
        *,
        package_index: PackageIndex,
        script_command: Sequence[str],
        title: str,
    ) -> None:
        self._load = load
        self.plan: LaunchPlan
        self.settings = settings
        self.environ = dict(environ)
        self.console = console
        self.package_index = package_index
        self.script_command = list(script_command)
        self.title = title
        self.uri = master_uri(environ, settings.port)
        self.monitor = ProcessMonitor(
            console,
            sigint_timeout=settings.sigint_timeout,
            sigterm_timeout=settings.sigterm_timeout,
        )
        self.core: Any = None
        self.run_id = ""
        self.log_dir: Path | None = None
        self._counter = 0
        self._master = MasterClient(self.uri, _CALLER, timeout=_CONNECT_TIMEOUT)
        #: Python nodes are forks of a process that has loaded rosx's rospy (see
        #: `rosx.launch.run.zygote`); False starts each as a new Python process (Windows cannot
        #: fork).
        self.fork_python_nodes = sys.platform != "win32"
        self.zygote: ZygoteClient | None = None

    # -- the run ---------------------------------------------------------------------------

    def _script_environ(self, environ: Mapping[str, str]) -> dict[str, str]:
        """``environ`` for a Python node: the shim directories first on ``PYTHONPATH``."""
        from rosx.client.script import SHIM_DIR, shim_environ  # noqa: PLC0415 - the rospy API loads only when used

        return shim_environ(environ, self.settings.shim_dirs or (SHIM_DIR,))

    def run(self) -> int:
        """Run the launch to its end; the exit status (0, as roslaunch, once it has started;
        1 when it could not start, the error reported and logged).

        Raises:
            LaunchFailedError: the launch could not start before its log was open (nothing is
                left running).
        """
        with self.monitor.signals():
            try:
                return self._run()
            except LaunchFailedError as error:
                if not self.console.logging:
                    raise
                self.console.error(f"{error.prefix}{error}")
                self.console.error("The traceback for the exception was written to the log file")
                self.console.log_traceback()
                return 1
            finally:
                if self.zygote is not None:
                    self.zygote.close()
                self._master.close()
                self.monitor.close()
                self.console.close()

    def _start_zygote(self) -> None:
        if not (self.plan.nodes and self.fork_python_nodes):
            return
        from rosx.launch.run.zygote import ZygoteClient  # noqa: PLC0415 - launch code loads only for launch files

        # Started before the core, so that it loads Python's side of the nodes meanwhile.
        environ = self._script_environ(self.environ)
        self.zygote = ZygoteClient(
            environ, on_exit=self.monitor.wake, crawled=self._crawled(environ)
        )

    def _load_plan(self) -> LaunchPlan:
        try:
            return self._load()
        except ResourceNotFoundError as error:
            text = self.package_index.not_found_text(error.located())
            raise LaunchFailedError(text, prefix="Resource not found: ") from error
        except LaunchError as error:
            raise LaunchFailedError(str(error)) from error

    def _crawled(self, environ: Mapping[str, str]) -> dict[str, Path] | None:
        """The package index's crawl, when it is of ``environ``'s package path (the nodes
        need it anyway, so it is done here once for the launcher and the helper)."""
        package_path = split_package_path(environ.get("ROS_PACKAGE_PATH"))
        if self.package_index.package_path != package_path:
            return None
        return self.package_index.path_packages

    def _run(self) -> int:
        from rosx.launch.printing import summary_text  # noqa: PLC0415 - launch code loads only for launch files
        from rosx.launch.run.server import LaunchServer  # noqa: PLC0415 - launch code loads only for launch files

        running = self._master.is_online()
        if self.settings.wait_for_master and not running:
            running = self._wait_for_master()
            if not running:
                return 0
        self.run_id = self._run_id(running)
        self._start_logging()
        self.console.title(self.title)
        self.plan = self._load_plan()
        self._check_plan()
        self._start_zygote()
        if self.settings.verbose:
            self._print_loading()
        server = LaunchServer(self.monitor, self.environ)
        server.start()
        try:
            self.console.bold(f"started roslaunch server {server.uri}")
            if self.settings.local_only:
                self.console.bold(
                    "LOCAL\nlocal only launch specified, will not launch remote nodes\nLOCAL\n"
                )
            if self.settings.show_summary:
                self.console.block(summary_text(self.plan))
            for warning in self.plan.warnings:
                self.console.error(f"WARNING: {warning}")
            try:
                started_core = self._launch_master(running)
                self._set_launch_uri(server.uri)
                if not self.monitor.stop_requested:
                    self._run_rosparam_commands()
                    self._load_parameters()
                if not self.monitor.stop_requested:
                    self._launch_nodes()
            except BaseException:
                self._shut_down(started_core=self.core is not None, print_done=False)
                raise
            return self._spin(started_core)
        finally:
            server.close()

    def _spin(self, started_core: bool) -> int:
        if not self.monitor.procs and not started_core:
            self.console.bold("No processes to monitor")
            self._shut_down(started_core=False, print_done=False)
            return 0
        if started_core:
            self.monitor.core_ended = lambda: self.core.wait(0) is not None
        self.monitor.spin()
        if started_core and self.core.wait(0) is not None:
            self._core_shut_down(self.core.wait(0))
        self._shut_down(started_core=started_core, print_done=True)
        return 0

    def _core_shut_down(self, message: str) -> None:
        """A ``shutdown`` call stopped the master: what ROS 1 prints when its master process
        (a required one) ends that way."""
        # rosmaster's words, misspelling included, for a call without a message.
        self.console.plain(f"shutdown request: {message}" if message else "shutdown requst")
        rule = "=" * 80
        log = f"\nlog file: {self.log_dir / 'master'}*.log" if self.log_dir else ""
        self.console.error(
            f"{rule}REQUIRED process [master] has died!\nprocess has finished cleanly{log}\n"
            f"Initiating shutdown!\n{rule}"
        )

    def _shut_down(self, *, started_core: bool, print_done: bool) -> None:
        self.monitor.stop_all()
        if started_core and self.core is not None:
            self.console.line("[rosout-1] killing on exit")
            self.console.line("[master] killing on exit")
            with contextlib.suppress(Exception):
                self.core.stop()
            self.core = None
        if self.monitor.shutdown_errors:
            errors = "\n".join(f" * {e}" for e in self.monitor.shutdown_errors)
            self.console.error(f"Shutdown errors:\n{errors}")
        self.console.line("shutting down processing monitor...")
        self.console.line("... shutting down processing monitor complete")
        if print_done:
            self.console.bold("done")

    # -- before the master -----------------------------------------------------------------

    def _check_plan(self) -> None:
        """Refuse what cannot run here before anything starts."""
        if self.settings.force_required:
            for node in self.plan.nodes:
                if node.respawn:
                    raise LaunchFailedError("respawn and required cannot both be set to true")
        if self.settings.local_only:
            return
        for node in self.plan.nodes:
            if not self._is_local(node):
                machine = self.plan.machines[node.machine or ""]
                raise LaunchFailedError(
                    f"{node.source}: <node> {node.resolved_name}: machine [{machine.name}] "
                    f"at [{machine.address}] is not this machine; rosx roslaunch starts nodes "
                    "on this machine only (--local skips the others)"
                )

    def _is_local(self, node: Node) -> bool:
        if not node.machine:
            return True
        machine = self.plan.machines.get(node.machine)
        return machine is None or is_local_host(machine.address)

    def _ask(self, method: str, *params: object) -> tuple[bool, Any]:
        """``method(*params)`` on the master: (True, its value), or (False, its status) when
        the master refuses; `LaunchFailedError` with ROS 1's text when it does not answer."""
        try:
            return True, self._master.call(method, *params, timeout=10.0)
        except MasterError as exc:
            return False, exc.status
        except MasterUnreachable as exc:
            raise self._unreachable(exc) from None

    def _unreachable(self, exc: MasterUnreachable) -> LaunchFailedError:
        return LaunchFailedError(f"ERROR: could not contact master [{self.uri}]: {exc}")

    def _wait_for_master(self) -> bool:
        self.console.line("roscore/master is not yet running, will wait for it to start")
        while not self.monitor.stop_requested:
            if self._master.is_online():
                self.console.line("master has started, initiating launch")
                return True
            self.monitor.sleep(0.1)
        return False

    def _run_id(self, running: bool) -> str:
        """The running master's ``/run_id``, or the run id of the core this launch starts."""
        if running:
            ok, value = self._ask("getParam", "/run_id")
            if ok and isinstance(value, str) and value:
                return value
            import uuid  # noqa: PLC0415 - uuid is not needed at start-up

            return str(uuid.uuid1())
        from rosx.core import Core  # noqa: PLC0415 - the master's code only when it starts

        _, port = _uri_host_port(self.uri)
        self.core = Core(port, self.environ)
        return str(self.core.run_id)

    def _start_logging(self) -> None:
        path = logdir.announce_run_log(
            self.environ,
            self.run_id,
            out=self.console.plain,
            err=self.console.error,
            check_disk=not self.settings.skip_log_check,
        )
        if path is not None:
            self.log_dir = path.parent
            self.console.open_log(path)

    def _print_loading(self) -> None:
        """``-v``: what roslaunch says as it reads each file (rebuilt from the plan: each
        file's parameters and nodes in the order of their tags, a node after its own)."""
        self._print_core_loading()
        for file in dict.fromkeys(self.plan.files):
            self.console.plain(f"... loading XML file [{file}]")
            params = [p for p in self.plan.params.values() if p.source.file == file]
            tags = [(float(p.source.line), f"Added parameter [{p.name}]") for p in params]
            for node in (n for n in self.plan.nodes if n.source.file == file):
                own = [p.source.line for p in params if p.name.startswith(node.resolved_name + "/")]
                kind = f"{node.package}/{node.type}"
                text = f"Added node of type [{kind}] in namespace [{node.namespace}]"
                tags.append((max([node.source.line, *own]) + 0.5, text))
            for _, text in sorted(tags, key=lambda tag: tag[0]):
                self.console.plain(text)

    def _print_core_loading(self) -> None:
        """``-v``: roslaunch reads roscore.xml first (from ``ROS_ETC_DIR``, rosx's own by
        default); rosx's core sets the same parameters without running ``rosversion``."""
        core = [p for p in self.plan.params.values() if p.source.file == CORE_SOURCE]
        if not core:
            return
        from rosx.workspace.environment import ROS_ETC_DIR  # noqa: PLC0415 - workspace code loads only when used

        etc = self.environ.get("ROS_ETC_DIR") or str(ROS_ETC_DIR)
        self.console.plain(f"... loading XML file [{Path(etc, 'roscore.xml')}]")
        for param in core:
            command = _CORE_COMMANDS.get(param.name)
            if command:
                self.console.plain(f"... executing command param [{command}]")
            self.console.plain(f"Added parameter [{param.name}]")
        self.console.plain("Added core node of type [rosout/rosout] in namespace [/]")

    # -- the master ------------------------------------------------------------------------

    def _launch_master(self, running: bool) -> bool:
        """Use the running master or start the core; whether this launch started it."""
        started = False
        if not running:
            host, port = _uri_host_port(self.uri)
            if not is_local_host(host):
                raise LaunchFailedError(f"ERROR: unable to contact ROS master at [{self.uri}]")
            self.console.line("auto-starting new master")
            self._start_core(port)
            started = True
        self.console.bold(f"ROS_MASTER_URI={self.uri}")
        self.console.title(f"{self.title} {self.uri}")
        if started:
            self.console.bold(f"setting /run_id to {self.run_id}")
            self._counter += 1
            self.console.bold(f"process[rosout-{self._counter}]: started with pid [{os.getpid()}]")
            self.console.line("started core service [/rosout]")
        else:
            self._check_run_id()
        return started

    def _start_core(self, port: int) -> None:
        from rosx.core import PortInUseError  # noqa: PLC0415 - the core loads only when one starts

        assert self.core is not None
        self.console.bold(f"process[master]: started with pid [{os.getpid()}]")
        try:
            self.core.start()
        except PortInUseError as exc:
            self.core = None
            if exc.another_master:  # one started since this launch looked
                raise LaunchFailedError(exc.message.removeprefix("RLException: ")) from None
            self.console.line(exc.message)
            raise LaunchFailedError(f"ERROR: could not contact master [{self.uri}]") from None

    def _check_run_id(self) -> None:
        ok, present = self._ask("hasParam", "/run_id")
        if ok and not present:
            self.console.bold(f"setting /run_id to {self.run_id}")
            self._ask("setParam", "/run_id", self.run_id)

    def _set_launch_uri(self, server_uri: str) -> None:
        host, port = _uri_host_port(server_uri)
        key = f"/roslaunch/uris/{_hostname_to_rosname(host)}__{port}"
        self._ask("setParam", key, server_uri)

    # -- parameters ------------------------------------------------------------------------

    def _run_rosparam_commands(self) -> None:
        from rosx.msg.text.yamlparams import dump_value  # noqa: PLC0415 - the text forms load on first use

        for step in self.plan.rosparam_commands:
            if step.command == "delete":
                self.console.plain(f"running rosparam delete {step.param}")
                ok, _ = self._ask("deleteParam", step.param)
                if not ok:
                    self.console.error(f"ERROR: parameter [{step.param}] is not set")
                continue
            self.console.plain(f"running rosparam dump {step.file} {step.param}")
            ok, value = self._ask("getParam", step.param)
            if not ok:
                self.console.error(f"ERROR: parameter [{step.param}] is not set")
                continue
            try:
                Path(step.file).write_text(dump_value(value), encoding="utf-8")
            except OSError as exc:
                self.console.error(f"ERROR: cannot write [{step.file}]: {exc.strerror}")

    def _load_parameters(self) -> None:
        clear = []
        for namespace in unify_clear_params(self.plan.clear_params):
            ok, present = self._ask("hasParam", namespace)
            if ok and present:
                clear.append(("deleteParam", (namespace,)))
        sets = [("setParam", (p.name, p.value)) for p in self.plan.params.values()]
        for what, calls in (("clear", clear), ("set", sets)):
            try:
                self._master.multicall(calls, timeout=60.0)
            except MasterError as exc:
                raise LaunchFailedError(f"Failed to {what} parameter: {exc.status}") from None
            except MasterUnreachable as exc:
                raise self._unreachable(exc) from None

    # -- nodes -----------------------------------------------------------------------------

    def _launch_nodes(self) -> None:
        for node in self.plan.nodes:
            if self.monitor.stop_requested:
                return
            if not self._is_local(node):
                continue  # --local: the others are skipped
            self._counter += 1
            process = self._node_process(node, self._counter)
            if process is not None and not self.monitor.start(process):
                self.console.error(f"local launch of {node.package}/{node.type} failed")

    def _node_process(self, node: Node, counter: int) -> LocalProcess | None:
        from rosx.launch.process import node_command_line, node_environment  # noqa: PLC0415 - launch code loads only for launch files

        try:
            index = self.package_index
            command = node_command_line(
                node, index, lambda package, kind: provided_program(package, kind, index)
            )
        except LaunchError as exc:
            text = str(exc)
            if isinstance(exc, ResourceNotFoundError):
                text = index.not_found_text(exc.located())
            kind = f"{node.package}/{node.type}"
            self.console.error(f"ERROR: cannot launch node of type [{kind}]: {text}")
            return None
        environ = node_environment(node, self.environ, self.uri)
        environ[HEADLESS] = "1"
        argv, executable = self._program(node, command)
        if executable is not None and is_python_script(executable):
            environ = self._script_environ(environ)
        name = ns_join(node.namespace, node.name)
        name = f"{name}-{counter}".lstrip("/")
        output = node.output
        if self.settings.force_screen:
            output = "screen"
        if self.settings.force_log:
            output = "log"
        options: dict[str, Any] = {
            "log_dir": self.log_dir,
            "log_output": output != "screen",
            "respawn": node.respawn,
            "respawn_delay": node.respawn_delay,
            "required": node.required or self.settings.force_required,
            "package": node.package,
            "runner": self._runner(node, executable),
        }
        cwd = self._cwd(node, executable)
        if self.zygote is not None and argv[: len(self.script_command)] == self.script_command:
            from rosx.launch.run.zygote import ForkedProcess  # noqa: PLC0415 - launch code loads only for launch files

            return ForkedProcess(
                name,
                argv,
                environ,
                cwd,
                zygote=self.zygote,
                script_index=len(self.script_command),
                **options,
            )
        return LocalProcess(name, argv, environ, cwd, **options)

    def _program(self, node: Node, command: list[str]) -> tuple[list[str], Path | None]:
        """The command line to run and the node's executable: a Python script's runs with
        ``script_command``."""
        prefix = len(shlex.split(node.launch_prefix)) if node.launch_prefix else 0
        if len(command) <= prefix:
            return command, None
        executable = Path(command[prefix])
        if is_python_script(executable):
            return [
                *command[:prefix],
                *self.script_command,
                str(executable),
                *command[prefix + 1 :],
            ], executable
        return command, executable

    def _runner(self, node: Node, executable: Path | None) -> tuple[int, int]:
        """Where `_program` put ``script_command`` in the command line, and its length."""
        if executable is None or not is_python_script(executable):
            return (0, 0)
        prefix = len(shlex.split(node.launch_prefix)) if node.launch_prefix else 0
        return (prefix, len(self.script_command))

    def _cwd(self, node: Node, executable: Path | None) -> Path:
        if node.cwd == "node" and executable is not None:
            return executable.parent
        return logdir.ros_home(self.environ)


__all__ = [
    "HEADLESS",
    "LaunchFailedError",
    "LaunchRun",
    "LaunchSettings",
    "master_uri",
    "provided_program",
    "unify_clear_params",
]
