"""``rosbag info``: a bag's summary, as ROS 1's text or YAML (`rosx.bag.info`)."""

from __future__ import annotations

from rosx.bag.errors import BagEncryptNotSupportedError, BagError, BagUnindexedError
from rosx.bag.info import format_text, format_yaml, lookup_key, summarize
from rosx.bag.reader import BagReader
from rosx_commands.cli import ToolParser
from rosx_commands.context import Environment, ExitStatus


def info(argv: list[str], env: Environment) -> int:
    """Run ``rosbag info ARGV…``."""
    parser = ToolParser(env, "rosbag", "rosbag info [options] BAGFILE1 [BAGFILE2 BAGFILE3 ...]")
    parser.description = "Summarize the contents of one or more bag files."
    parser.add_option(
        "-y",
        "--yaml",
        dest="yaml",
        default=False,
        action="store_true",
        help="print information in YAML format",
    )
    parser.add_option(
        "-k",
        "--key",
        dest="key",
        default=None,
        action="store",
        help="print information on the given key",
    )
    parser.add_option(
        "--freq",
        dest="freq",
        default=False,
        action="store_true",
        help="display topic message frequency statistics",
    )
    options, args = parser.parse(argv)
    if not args:
        parser.error("You must specify at least 1 bag file.")
    if options.key and not options.yaml:
        parser.error("You can only specify key when printing in YAML format.")
    for i, path in enumerate(args):
        try:
            with BagReader(path) as bag:
                summary = summarize(bag, path, freq=options.freq)
        except BagEncryptNotSupportedError as exc:
            env.err(f"ERROR: {exc}")
            continue
        except BagUnindexedError:
            env.err(f"ERROR bag unindexed: {path}.  Run rosbag reindex.")
            return ExitStatus.ERROR
        except (BagError, OSError) as exc:
            env.err(f"ERROR reading {path}: {exc}")
            return ExitStatus.ERROR
        if options.yaml:
            if options.key:
                text = lookup_key(summary, options.key)
                if text is None:
                    env.err(f'Error getting key "{options.key}"')
                else:
                    env.out(text)
            else:
                env.out(format_yaml(summary))
        else:
            env.out(format_text(summary))
        if i < len(args) - 1:
            env.out("---")
    return ExitStatus.OK
