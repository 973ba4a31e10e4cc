"""``rosx complete CWORD WORD…``: the completions of a ROS command line, for bash and zsh.

The shell functions of `rosx.workspace.completion` pass the words of the line and the index of
the one being completed; this prints the candidates that start with it, each followed by a NUL.
What is offered follows rosbash: packages (``roscd``, ``rospack``, ``rosed``…, ``roscd``'s as
``pkg/`` and then ``pkg/sub/dir/``), a package's executables (``rosrun``), files (``rosed``,
``roscp``) and launch files (``roslaunch``, then the files' ``arg:=``), sub-commands and
options, the live graph's nodes, topics, services and parameters (asked of the master with a
short timeout: no master, no candidates), message and service types, and the YAML prototype of
a message after ``rostopic pub TOPIC TYPE`` or ``rosservice call SERVICE``. Nothing printed
means the shell's own file-name completion.

A <TAB> must answer at once, so the shell functions do not run ``rosx complete``: they start
Python for `main` alone, without ``site`` (the module path is given,
`rosx_commands.invocation.complete_command`). Package names, what most <TAB>s ask, come from
the package index's kept crawl, checked with ``os`` alone (`rosx.packages.kept`: never stale,
a package made a moment ago is offered), and rosx's own packages (`rosx.packages.bundled`);
nothing else is imported for them: no ``pathlib``, no ``re``, not the index. Only when the kept
crawl cannot tell does the index crawl (and keep its crawl for the next <TAB>).
"""

from __future__ import annotations

import os
import sys

TYPE_CHECKING = False
if TYPE_CHECKING:
    from collections.abc import Callable, Mapping, Sequence
    from pathlib import Path

    from rosx.msg.store import TypeStore
    from rosx.packages.index import PackageIndex
    from rosx_commands.context import Environment

#: Seconds the master has to answer a completion's question.
MASTER_TIMEOUT = 0.5

_SUBCOMMANDS = {
    "rospack": "help find list list-names list-duplicates langs depends depends-manifests "
    "depends1 depends-indent depends-msgsrv depends-why rosdep rosdep0 vcs vcs0 depends-on "
    "depends-on1 export plugins cflags-only-I cflags-only-other libs-only-L libs-only-l "
    "libs-only-other profile",
    "rosnode": "ping list info machine kill cleanup",
    "rosparam": "set get load dump delete list",
    "rostopic": "bw echo hz list pub type find info",
    "rosservice": "args call find info list type uri",
    "rosmsg": "show list md5 package packages",
    "rossrv": "show list md5 package packages",
    "rosbag": "check compress decompress filter fix help info play record reindex",
    "rosclean": "check purge",
    "rosmsg-proto": "msg srv",
    "rossrv-proto": "msg srv",
}

_OPTIONS = {
    ("rostopic", "pub"): "--rate --once --file --latch",
    ("rostopic", "bw"): "--window",
    ("rostopic", "echo"): "--bag --filter --nostr --noarr --clear --all offset",
    ("rostopic", "hz"): "--window --filter",
    ("rostopic", "list"): "--bag --verbose --host",
    ("rosbag", "check"): "--genrules --append --noplugins --help",
    ("rosbag", "compress"): "--output-dir --force --quiet --help",
    ("rosbag", "decompress"): "--output-dir --force --quiet --help",
    ("rosbag", "filter"): "--print --help",
    ("rosbag", "fix"): "--force --noplugins --help",
    ("rosbag", "info"): "--yaml --key --freq --help",
    ("rosbag", "play"): "--help --quiet --immediate --pause --queue --clock --hz --delay "
    "--rate --start --skip-empty --loop --keep-alive --try-future-version --topics --bags",
    ("rosbag", "record"): "--help --all --regex --exclude --quiet --output-prefix "
    "--output-name --split --size --duration --buffsize --limit --node --bz2",
    ("rosbag", "reindex"): "--help --force --quiet --output-dir",
}

_ROSLAUNCH_OPTIONS = (
    "--files --args --nodes --find-node --child --local --screen --server_uri --run_id --wait "
    "--port --core --pid --dump-params --skip-log-check --ros-args"
)


class _Line:
    """The command line being completed."""

    def __init__(self, words: list[str], cword: int, environ: Mapping[str, str]) -> None:
        self.words = words
        self.cword = cword
        self.current = words[cword] if cword < len(words) else ""
        self.environ = environ
        self._index: PackageIndex | None = None
        self._store: TypeStore | None = None

    def word(self, at: int) -> str:
        return self.words[at] if 0 <= at < len(self.words) else ""

    @property
    def index(self) -> PackageIndex:
        if self._index is None:
            from rosx.packages.index import PackageIndex  # noqa: PLC0415 - the package index loads only when used

            self._index = PackageIndex.from_environ(self.environ)
        return self._index

    def package_names(self) -> list[str]:
        """Every package's name, sorted (``rospack list-names``): from the kept crawl while it
        is unchanged, else from the index (which crawls)."""
        from rosx.packages.kept import listed_packages  # noqa: PLC0415 - the index's parts load only when used

        return list(listed_packages(self.environ) or self.index.packages)

    @property
    def master_uri(self) -> str:
        from rosx.master.defaults import master_uri  # noqa: PLC0415 - the master's address only to talk to one

        return master_uri(self.environ)

    @property
    def store(self) -> TypeStore:
        if self._store is None:
            from rosx.msg.store import TypeStore  # noqa: PLC0415 - the type store loads on first use

            self._store = TypeStore.from_environ(self.environ)
        return self._store

    def package_dir(self, name: str) -> str | None:
        """Package ``name``'s folder: from the kept crawl (what precedes it on the path
        checked), else from the index."""
        from rosx.packages.kept import kept_find  # noqa: PLC0415 - the index's parts load only when used

        found = kept_find(self.environ, name)
        if found is None and name in self.index.packages:
            found = str(self.index.packages[name])
        return found


def _walk_files(line: _Line, package: str) -> list[Path]:
    from pathlib import Path  # noqa: PLC0415 - a <TAB> for package names does without it

    from rosx.packages.crawl import libexec_dir  # noqa: PLC0415 - the package index loads only when used

    folder = line.package_dir(package)
    if folder is None:
        return []
    directory = Path(folder)
    found: list[Path] = []
    for root in [r for r in (libexec_dir(directory), directory) if r is not None]:
        for here, subdirs, files in os.walk(root, followlinks=True):
            subdirs[:] = sorted(
                d
                for d in subdirs
                if not d.startswith(".") and not (Path(here) == root and d == "build")
            )
            found += [Path(here) / f for f in sorted(files) if not f.startswith(".")]
    return found


def _executables(line: _Line, package: str) -> list[str]:
    """What ``rosrun PACKAGE`` can run: rosx's programs and the package's executable files."""
    from rosx.workspace.programs import program_names  # noqa: PLC0415 - rosrun's line only

    found = [p.name for p in _walk_files(line, package) if p.is_file() and os.access(p, os.X_OK)]
    return sorted({*found, *program_names(package)})


def _files(line: _Line, package: str, suffixes: tuple[str, ...] = ()) -> list[str]:
    names = [p.name for p in _walk_files(line, package) if not p.name.endswith((".o", ".a"))]
    return sorted({n for n in names if not suffixes or n.endswith(suffixes)})


def _locations(line: _Line) -> list[str]:
    """``roscd``/``rosls``: ``pkg/``, or the folders below ``pkg/sub/``."""
    current = line.current
    if "/" not in current:
        return [f"{name}/" for name in [*line.package_names(), "log"]]
    package, _, rest = current.partition("/")
    base = line.package_dir(package)
    if base is None:
        return []
    parent, _, _ = rest.rpartition("/")
    folder = os.path.join(base, parent) if parent else base  # noqa: PTH118 - a <TAB> does without pathlib
    try:
        names = sorted(e.name for e in os.scandir(folder) if e.is_dir() and e.name[:1] != ".")
    except OSError:
        return []
    head = f"{package}/{parent}/" if parent else f"{package}/"
    return [f"{head}{name}/" for name in names]


def _master_lists(line: _Line, what: str) -> list[str]:
    from rosx.graph.state import registrations  # noqa: PLC0415 - graph code loads only when asked for
    from rosx.master.client import MasterClient, MasterError  # noqa: PLC0415 - the master's code loads only to talk to one
    from rosx.transport.errors import TransportError  # noqa: PLC0415 - the network code loads only to talk

    master = MasterClient(line.master_uri, "/rosx_complete", timeout=MASTER_TIMEOUT)
    try:
        if what == "params":
            return sorted(str(n) for n in master.getParamNames())
        state = registrations(master)
    except (MasterError, TransportError, OSError):
        return []
    finally:
        master.close()
    if what == "topics":
        return state.topics
    if what == "services":
        return sorted(state.services)
    return state.nodes


def _topic_type(line: _Line, topic: str) -> str | None:
    from rosx.master.client import MasterClient, MasterError  # noqa: PLC0415 - the master's code loads only to talk to one
    from rosx.transport.errors import TransportError  # noqa: PLC0415 - the network code loads only to talk

    master = MasterClient(line.master_uri, "/rosx_complete", timeout=MASTER_TIMEOUT)
    try:
        return master.topic_types().get(topic)
    except (MasterError, TransportError, OSError):
        return None
    finally:
        master.close()


def _types(line: _Line, kind: str) -> list[str]:
    """rosbash's ``_msg_opts``/``_srv_opts``: ``pkg/`` while several packages match, else the
    package's types."""
    names = line.store.types(kind)
    current = line.current
    if "/" in current:
        package = current.partition("/")[0]
        return [n for n in names if n.partition("/")[0] == package]
    packages = sorted({n.partition("/")[0] for n in names if n.startswith(current)})
    if len(packages) > 1:
        return [f"{p}/" for p in packages]
    return [n for n in names if n.partition("/")[0] in packages]


def _proto(line: _Line, kind: str, name: str) -> list[str]:
    from rosx.msg.store import UnknownTypeError  # noqa: PLC0415 - the type store loads on first use
    from rosx.msg.text.prototype import prototype  # noqa: PLC0415 - the text forms load on first use

    store = line.store
    try:
        if kind == "srv":
            store.srv(name)
            name += "Request"
        return [f'"{prototype(name, store.msg)}"']
    except (UnknownTypeError, ValueError):
        return []


def _rosrun(line: _Line) -> list[str]:
    start = 1
    while line.word(start) in ("--prefix", "-p", "--debug", "-d") and start < line.cword:
        start += 2 if line.word(start) in ("--prefix", "-p") else 1
    if line.cword == start:
        if line.current.startswith("-"):
            return ["--prefix", "--debug"]
        from rosx.packages.bundled import provided_names  # noqa: PLC0415 - rosrun only

        return sorted({*line.package_names(), *provided_names()})
    if line.cword == start + 1:
        return _executables(line, line.word(start))
    return []


def _by_package(line: _Line, second: list[str]) -> list[str]:
    if line.cword == 1:
        return line.package_names()
    if line.cword == 2:
        return second
    return []


def _roslaunch(line: _Line) -> list[str]:
    if line.current.startswith("--"):
        return _ROSLAUNCH_OPTIONS.split()
    if line.cword == 1:
        try:
            here = os.listdir(line.environ.get("PWD") or ".")  # noqa: PTH208 - a <TAB> does without pathlib
        except OSError:
            here = []
        local = sorted(n for n in here if os.path.splitext(n)[1] in (".launch", ".test"))  # noqa: PTH122
        return [*line.package_names(), *local]
    first = line.word(1)
    if line.cword == 2 and not first.endswith((".launch", ".test")):
        return _files(line, first, (".launch", ".test"))
    return _launch_args(line)


def _launch_args(line: _Line) -> list[str]:
    from rosx.launch.errors import LaunchError  # noqa: PLC0415 - launch code loads only for launch files
    from rosx.launch.loader import load_launch, resolve_launch_arguments  # noqa: PLC0415 - launch code loads only for launch files

    given = [w for w in line.words[1 : line.cword] if ":=" not in w][:2]
    try:
        files, _ = resolve_launch_arguments(given, line.index)
        plan = load_launch(files, {}, line.environ, line.index, args_only=True, core_params={})
    except (LaunchError, OSError, ValueError):
        return []
    return [f"{name}:=" for name in plan.arg_docs]


def _rosnode(line: _Line) -> list[str]:
    sub = line.word(1)
    if line.cword == 2 and sub in ("ping", "list", "kill") and line.current.startswith("--"):
        return ["--all", "--help"]
    if (line.cword == 2 and sub in ("info", "ping", "list", "kill")) or (
        line.cword > 2 and sub == "kill"
    ):
        return _master_lists(line, "nodes")
    return []


def _rosparam(line: _Line) -> list[str]:
    sub = line.word(1)
    if (line.cword == 2 and sub in ("set", "get", "delete", "list")) or (
        line.cword == 3 and sub in ("load", "dump")
    ):
        return _master_lists(line, "params")
    return []


def _rostopic(line: _Line) -> list[str]:
    sub = line.word(1)
    if line.current.startswith("--"):
        return _OPTIONS.get(("rostopic", sub), "").split()
    if sub in ("bw", "echo", "hz", "list", "type", "info"):
        return [] if line.word(line.cword - 1) == "-b" else _master_lists(line, "topics")
    if sub == "find":
        return _types(line, "msg")
    if sub != "pub":
        return []
    position = 2
    while line.word(position).startswith("-") and position < line.cword:
        position += 2 if line.word(position) in ("-f", "-r") else 1
    if line.cword == position:
        return _master_lists(line, "topics")
    if line.cword == position + 1:
        known = _topic_type(line, line.word(position))
        return [known] if known else _types(line, "msg")
    if line.cword == position + 2:
        return _proto(line, "msg", line.word(position + 1))
    return []


def _rosservice(line: _Line) -> list[str]:
    sub = line.word(1)
    if line.cword == 2:
        if sub == "find":
            return _types(line, "srv")
        if sub in ("args", "call", "info", "list", "type", "uri"):
            return _master_lists(line, "services")
    if line.cword == 3 and sub == "call":
        return _service_proto(line, line.word(2))
    return []


def _service_proto(line: _Line, service: str) -> list[str]:
    from rosx.master.client import MasterClient, MasterError  # noqa: PLC0415 - the master's code loads only to talk to one
    from rosx.node.errors import ServiceError  # noqa: PLC0415 - the node runtime loads with the first node
    from rosx.node.service_client import probe_service  # noqa: PLC0415 - the node runtime loads with the first node
    from rosx.transport.errors import TransportError  # noqa: PLC0415 - the network code loads only to talk

    master = MasterClient(line.master_uri, "/rosx_complete", timeout=MASTER_TIMEOUT)
    try:
        header = probe_service(master, service, timeout=MASTER_TIMEOUT)
    except (ServiceError, MasterError, TransportError, OSError):
        return []
    finally:
        master.close()
    kind = header.get("type")
    return _proto(line, "srv", kind) if kind else []


def _rosmsg(line: _Line, kind: str) -> list[str]:
    if line.cword != 2:
        return []
    sub = line.word(1)
    if sub in ("show", "info", "users", "md5"):
        return _types(line, kind)
    if sub == "package":
        return line.package_names()
    return []


def candidates(line: _Line) -> list[str]:
    """Every candidate for the current word (before filtering by what is typed)."""
    command = os.path.basename(line.word(0))  # noqa: PTH119 - a <TAB> does without pathlib
    if command == "rosx" and line.cword == 1:
        from rosx_commands.tools import TOOLS  # noqa: PLC0415 - this tool's parts load only when used

        return [*TOOLS, "roscd", "rosls"]
    if command == "rosx":
        return candidates(_Line(line.words[1:], line.cword - 1, line.environ))
    if line.cword == 1 and command in _SUBCOMMANDS:
        return _SUBCOMMANDS[command].split()
    sub = line.word(1)
    match command:
        case "roscd" | "rosls":
            return _locations(line) if line.cword == 1 else []
        case "rospack" | "catkin_create_pkg" | "rosversion":
            return line.package_names()
        case "rosrun":
            return _rosrun(line)
        case "rosed" | "roscp":
            return _by_package(line, _files(line, line.word(1)) if line.cword == 2 else [])
        case "roslaunch":
            return _roslaunch(line)
        case "rosnode":
            return _rosnode(line)
        case "rosparam":
            return _rosparam(line)
        case "rostopic":
            return _rostopic(line)
        case "rosservice":
            return _rosservice(line)
        case "rosmsg":
            return _rosmsg(line, "msg")
        case "rossrv":
            return _rosmsg(line, "srv")
        case "rosmsg-proto" | "rossrv-proto":
            return _types(line, sub) if line.cword == 2 and sub in ("msg", "srv") else []
        case "rosbag":
            if line.current.startswith("--"):
                return _OPTIONS.get(("rosbag", sub), "").split()
            return []
        case "roswtf":
            return ["--all", "--no-plugins", "--offline"] if line.current.startswith("--") else []
    return []


def complete(argv: Sequence[str], env: Environment) -> int:
    """Print the candidates for ``complete CWORD WORD…``, each followed by a NUL."""
    return _complete(argv, env.environ, env.stdout.write, env.err)


def main() -> None:
    """``rosx complete`` for a shell's <TAB>, in a Python started for it alone (see the module's
    docstring): the words after ``-c`` are the command's."""
    sys.exit(_complete(sys.argv[1:], os.environ, sys.stdout.write, _print_error))


def _print_error(text: str) -> None:
    sys.stderr.write(text + "\n")


def _complete(
    argv: Sequence[str],
    environ: Mapping[str, str],
    write: Callable[[str], object],
    error: Callable[[str], None],
) -> int:
    # Exit statuses as numbers: the <TAB>'s Python does not load the tools' enum.
    args = list(argv)
    if not args or not args[0].isdigit():
        error("usage: rosx complete CWORD WORD...")
        return 2
    line = _Line(args[1:], int(args[0]), environ)
    try:
        found = candidates(line)
    except Exception:
        return 1
    typed = line.current
    shown = list(dict.fromkeys(c for c in found if c.startswith((typed, '"'))))
    write("".join(f"{c}\0" for c in shown))
    return 0


__all__ = ["candidates", "complete", "main"]
