"""``rosbag filter``, ``check``, ``compress``, ``decompress``, ``reindex``, ``fix``, and the
encryption commands rosx does not provide, with ROS 1's options and messages.

The commands that rewrite bags in place keep the original as ``NAME.orig.bag`` (``-f`` replaces
an old backup; ``--output-dir`` writes elsewhere instead), as ROS 1's do.
"""

from __future__ import annotations

import io
import os
import shutil
import time
from pathlib import Path
from typing import TYPE_CHECKING, Any

from rosx.bag.edit import (
    backup_path,
    bag_file_problem,
    changed_types,
    copy_messages,
    data_size,
    recompress,
    uncompressed_size,
)
from rosx.bag.errors import BagEncryptNotSupportedError, BagError, BagUnindexedError
from rosx.bag.info import human_size
from rosx.bag.reader import BagReader
from rosx_commands.cli import ToolParser
from rosx_commands.context import Environment, ExitStatus

if TYPE_CHECKING:
    from collections.abc import Callable


def _parser(env: Environment, usage: str, description: str) -> ToolParser:
    parser = ToolParser(env, "rosbag", usage)
    parser.description = description
    return parser


def _file_options(parser: ToolParser) -> None:
    parser.add_option(
        "--output-dir",
        action="store",
        dest="output_dir",
        help="write to directory DIR",
        metavar="DIR",
    )
    parser.add_option(
        "-f",
        "--force",
        action="store_true",
        dest="force",
        help="force overwriting of backup file if it exists",
    )
    parser.add_option(
        "-q", "--quiet", action="store_true", dest="quiet", help="suppress noncritical messages"
    )


def _open(env: Environment, path: str) -> BagReader | None:
    try:
        return BagReader(path)
    except BagEncryptNotSupportedError as exc:
        env.err(f"ERROR: {exc}")
    except BagUnindexedError:
        env.err(f"ERROR bag unindexed: {path}.  Run rosbag reindex.")
    except (BagError, OSError) as exc:
        env.err(f"ERROR reading {path}: {exc}")
    return None


class _Meter:
    """ROS 1's progress line for a file being written: ``0%`` when it starts, ``100%`` with the
    elapsed time when done; the path padded to the terminal's width (80 when not a terminal)."""

    def __init__(self, env: Environment, path: str, total: int) -> None:
        self.env = env
        self.total = total
        self.began = time.monotonic()
        width = self._width() - 37
        self.path = path if len(path) <= width else "..." + path[-width + 3 :]
        self.width = width
        if total > 0:
            size = human_size(total)
            self._write(f"{self.path:<{width}}   0% {'0.0 KB':>8} / {size:>8} --:-- ETA")
        else:
            self._write(self._done_text())

    def _width(self) -> int:
        try:
            columns = os.get_terminal_size(self.env.stdout.fileno()).columns
        except (AttributeError, OSError, ValueError, io.UnsupportedOperation):
            columns = 0
        if columns <= 0:
            try:
                columns = int(self.env.environ.get("COLUMNS", "0"))
            except ValueError:
                columns = 0
        return columns if columns > 0 else 80

    def _done_text(self) -> str:
        elapsed = int(time.monotonic() - self.began)
        done = f"{human_size(self.total):>19} {elapsed // 60:02d}:{elapsed % 60:02d}"
        return f"{self.path:<{self.width}} 100% {done}    "

    def _write(self, text: str) -> None:
        self.env.stdout.write(f"\r {text}")
        self.env.stdout.flush()

    def finish(self) -> None:
        self._write(self._done_text() + "\n")


def _in_place(
    env: Environment,
    paths: list[str],
    options: Any,
    operation: Callable[[str, str], None],
    *,
    copy_first: bool,
    check: Callable[[str], bool],
    measure: Callable[[str], int],
) -> int:
    status = ExitStatus.OK
    for path in paths:
        if not check(path):
            status = ExitStatus.ERROR  # ROS 1's exits 0 or crashes (README.md)
            continue
        out = (
            path if options.output_dir is None else str(Path(options.output_dir) / Path(path).name)
        )
        source = path
        if out == path:
            backup = str(backup_path(path))
            if not options.force and Path(backup).exists():
                if not options.quiet:
                    env.err(f"Skipping {path}. Backup path {backup} already exists.")
                continue
            try:
                if copy_first:
                    shutil.copy(path, backup)
                else:
                    Path(path).replace(backup)
            except OSError as exc:
                verb = "copying" if copy_first else "moving"
                env.err(f"ERROR {verb} {path} to {backup}: {exc}")
                status = ExitStatus.ERROR
                continue
            source = backup
        elif copy_first:
            shutil.copy(path, out)
        try:
            meter = None if options.quiet else _Meter(env, out, measure(source))
            operation(source, out)
        except (BagError, OSError) as exc:
            env.err(f"ERROR operating on {path}: {exc}")
            status = ExitStatus.ERROR
            continue
        if meter is not None:
            meter.finish()
    return status


# -- the commands -----------------------------------------------------------------------------


def _compression(argv: list[str], env: Environment, *, compress: bool) -> int:
    name = "compress" if compress else "decompress"
    parser = _parser(
        env,
        f"rosbag {name} [options] BAGFILE1 [BAGFILE2 ...]",
        f"{name.capitalize()} one or more bag files.",
    )
    _file_options(parser)
    if compress:
        parser.add_option(
            "-j",
            "--bz2",
            action="store_const",
            dest="compression",
            help="use BZ2 compression",
            const="bz2",
            default="bz2",
        )
        parser.add_option(
            "--lz4",
            action="store_const",
            dest="compression",
            help="use lz4 compression",
            const="lz4",
        )
    options, args = parser.parse(argv)
    if not args:
        parser.error("You must specify at least one bag file.")
    compression = options.compression if compress else "none"

    def operation(source: str, out: str) -> None:
        recompress(source, out, compression)

    def check(path: str) -> bool:
        bag = _open(env, path)
        if bag is None:
            return False
        bag.close()
        return True

    return _in_place(
        env, args, options, operation, copy_first=False, check=check, measure=uncompressed_size
    )


def compress(argv: list[str], env: Environment) -> int:
    """Run ``rosbag compress ARGV…``."""
    return _compression(argv, env, compress=True)


def decompress(argv: list[str], env: Environment) -> int:
    """Run ``rosbag decompress ARGV…``."""
    return _compression(argv, env, compress=False)


def reindex(argv: list[str], env: Environment) -> int:
    """Run ``rosbag reindex ARGV…``: rebuild the index of bags whose writer never closed them."""
    from rosx.bag.reindex import reindex as rebuild  # noqa: PLC0415 - bag code loads only for bags

    parser = _parser(
        env, "rosbag reindex [options] BAGFILE1 [BAGFILE2 ...]", "Reindexes one or more bag files."
    )
    _file_options(parser)
    options, args = parser.parse(argv)
    if not args:
        parser.error("You must specify at least one bag file.")

    def operation(source: str, out: str) -> None:
        report = rebuild(out)
        said = (
            f"{out}: kept {_count(report.messages, 'message')} in {_count(report.chunks, 'chunk')}"
        )
        if report.dropped_bytes:
            said += f"; dropped {report.dropped_bytes} bytes, damaged or cut short"
        if report.dropped_messages:
            said += f"; left out {_count(report.dropped_messages, 'damaged message')}"
        env.err(said)

    def check(path: str) -> bool:
        problem = bag_file_problem(path)
        if problem is not None:
            env.err(f"ERROR reading {path}: {problem}")
        return problem is None

    return _in_place(env, args, options, operation, copy_first=True, check=check, measure=data_size)


def _count(number: int, thing: str) -> str:
    return f"{number} {thing}{'' if number == 1 else 's'}"


def filter_bag(argv: list[str], env: Environment) -> int:
    """Run ``rosbag filter INBAG OUTBAG EXPRESSION``."""
    from rosx.bag.types import message_class  # noqa: PLC0415 - bag code loads only for bags
    from rosx.bag.writer import BagWriter  # noqa: PLC0415 - bag code loads only for bags
    from rosx.msg.codec.rostime import Time  # noqa: PLC0415 - message classes load on first use

    parser = _parser(
        env,
        "rosbag filter [options] INBAG OUTBAG EXPRESSION\n\n"
        "EXPRESSION can be any Python-legal expression.\n\n"
        "The following variables are available:\n"
        " * topic: name of topic\n"
        " * m: message\n"
        " * t: time of message (t.secs, t.nsecs)",
        "Filter the contents of the bag.",
    )
    parser.add_option(
        "-p",
        "--print",
        action="store",
        dest="verbose_pattern",
        default=None,
        metavar="PRINT-EXPRESSION",
        help="Python expression to print for verbose debugging. Uses same "
        "variables as filter-expression",
    )
    options, args = parser.parse(argv)
    if not args:
        parser.error("You must specify an in bag, an out bag, and an expression.")
    if len(args) == 1:
        parser.error("You must specify an out bag and an expression.")
    if len(args) == 2:
        parser.error("You must specify an expression.")
    if len(args) > 3:
        parser.error("Too many arguments.")
    inbag, outbag, expression = args
    if not Path(inbag).is_file():
        env.err(f"Cannot locate input bag file [{inbag}]")
        return ExitStatus.USAGE
    if os.path.realpath(inbag) == os.path.realpath(outbag):
        env.err(f"Cannot use same file as input and output [{inbag}]")
        return 3
    try:
        test = compile(expression, "<filter>", "eval")
        show = (
            compile(options.verbose_pattern, "<print>", "eval") if options.verbose_pattern else None
        )
    except SyntaxError as exc:
        env.err(f"ERROR: invalid expression: {exc.msg}")
        return ExitStatus.ERROR
    source = _open(env, inbag)
    if source is None:
        return ExitStatus.ERROR
    meter = _Meter(env, outbag, uncompressed_size(inbag))

    def keep(conn: Any, stamp: int, data: bytes) -> bool:
        names = {
            "topic": conn.topic,
            "m": message_class(conn)().deserialize(data),
            "t": Time(stamp // 1_000_000_000, stamp % 1_000_000_000),
        }
        matched = bool(eval(test, names))
        if show is not None:
            env.out(f"{'MATCH' if matched else 'NO MATCH'} {eval(show, names)}")
        return matched

    try:
        with source, BagWriter(outbag) as writer:
            copy_messages(source, writer, keep)
    except Exception as exc:  # the user's expression may raise anything
        env.err(f"ERROR: {type(exc).__name__}: {exc}")
        return ExitStatus.ERROR
    meter.finish()
    return ExitStatus.OK


def check(argv: list[str], env: Environment) -> int:
    """Run ``rosbag check BAG``: whether every recorded type matches this system's."""
    from rosx.msg.codec.classes import get_message_class  # noqa: PLC0415 - message classes load on first use

    parser = _parser(
        env,
        "rosbag check BAG [-g RULEFILE] [EXTRARULES1 EXTRARULES2 ...]",
        "Determine whether a bag is playable in the current system, or if it can be migrated.",
    )
    parser.add_option(
        "-g",
        "--genrules",
        action="store",
        dest="rulefile",
        default=None,
        help="generate a rulefile named RULEFILE",
    )
    parser.add_option(
        "-a",
        "--append",
        action="store_true",
        dest="append",
        help="append to the end of an existing rulefile after loading it",
    )
    parser.add_option(
        "-n",
        "--noplugins",
        action="store_true",
        dest="noplugins",
        help="do not load rulefiles via plugins",
    )
    options, args = parser.parse(argv)
    if not args:
        parser.error("You must specify a bag file to check.")
    if options.append and options.rulefile is None:
        parser.error("Cannot specify -a without also specifying -g.")
    if options.rulefile is not None:
        env.err("rosx does not generate migration rules (-g); checking only.")
    bag = _open(env, args[0])
    if bag is None:
        return ExitStatus.ERROR

    def current_md5(msg_type: str) -> str | None:
        try:
            return get_message_class(msg_type)._md5sum
        except Exception:  # unknown here: it plays with the definition the bag recorded
            return None

    try:
        with bag:
            changed = changed_types(bag, current_md5)
    except BagError as exc:  # a damaged chunk: what ROS 1 calls an unindexed bag
        env.err(f"ERROR reading {args[0]}: {exc}.  Run rosbag reindex.")
        return ExitStatus.ERROR
    if not changed:
        env.out("Bag file does not need any migrations.")
        return ExitStatus.OK
    env.out("The following migrations need to occur:")
    for msg_type, md5 in changed:
        env.out(f" * From: {msg_type} [{md5}]")
        env.out("   To:   Unknown")
    env.out("rosx does not migrate messages (no migration rules); rosbag fix cannot convert them.")
    return ExitStatus.ERROR


def fix(argv: list[str], env: Environment) -> int:
    """Run ``rosbag fix``: message migration is not supported by rosx; say so."""
    parser = _parser(
        env,
        "rosbag fix INBAG OUTBAG [EXTRARULES1 EXTRARULES2 ...]",
        "Repair the messages in a bag file so that it can be played in the current system.",
    )
    parser.add_option(
        "-n",
        "--noplugins",
        action="store_true",
        dest="noplugins",
        help="do not load rulefiles via plugins",
    )
    parser.add_option(
        "--force",
        action="store_true",
        dest="force",
        help="proceed with migrations, even if not all rules defined",
    )
    _, args = parser.parse(argv)
    if len(args) < 1:
        parser.error("You must pass input and output bag files.")
    if len(args) < 2:
        parser.error("You must pass an output bag file.")
    env.err(
        "rosx does not support rosbag fix: it has no message migration rules. Bags whose "
        "types changed still play and read with the definitions they recorded."
    )
    return ExitStatus.ERROR


def _encryption(argv: list[str], env: Environment, name: str) -> int:
    parser = _parser(
        env,
        f"rosbag {name} [options] BAGFILE1 [BAGFILE2 ...]",
        f"{name.capitalize()} one or more bag files.",
    )
    _file_options(parser)
    parser.parse(argv)
    env.err(f"rosx does not support encrypted bags: rosbag {name} is not available.")
    return ExitStatus.ERROR


def encrypt(argv: list[str], env: Environment) -> int:
    """``rosbag encrypt``: not supported by rosx."""
    return _encryption(argv, env, "encrypt")


def decrypt(argv: list[str], env: Environment) -> int:
    """``rosbag decrypt``: not supported by rosx."""
    return _encryption(argv, env, "decrypt")
