"""What ``rosbag info`` prints about a bag: ROS 1's text, its YAML form, and one key of it.

`summarize` reads what the index says (and, for frequencies, every index record) into a
`Summary`; `format_text` and `format_yaml` lay it out as ROS 1's rosbag does, to the byte:
aligned ``field: value`` rows, sizes in KB/MB…, times in local time with two decimals, the
topic table with message counts and (``--freq``) median frequencies; `lookup_key` gives one
key of the YAML form (``rosbag info -y -k topics``), printed the way ROS 1 prints it.
"""

from __future__ import annotations

import itertools
import re
import time
from typing import TYPE_CHECKING, Any, NamedTuple

if TYPE_CHECKING:
    from rosx.bag.reader import BagReader


class TopicRow(NamedTuple):
    """One topic: its type (its first connection's), message and connection counts,
    median frequency (``None`` unless asked for and known)."""

    topic: str
    type: str
    messages: int
    connections: int
    frequency: float | None


class Summary(NamedTuple):
    """Everything ``rosbag info`` shows about one bag."""

    path: str
    version: str
    size: int
    indexed: bool
    start: float
    end: float
    messages: int
    #: compression → (chunks, uncompressed bytes, compressed bytes)
    compressions: dict[str, tuple[int, int, int]]
    chunk_count: int
    types: list[tuple[str, str]]
    topics: list[TopicRow]


def to_sec(ns: int) -> float:
    """ROS 1's ``Time.to_sec()`` of ``ns`` (rounded as it rounds: seconds + nanoseconds/1e9)."""
    secs, nsecs = divmod(ns, 1_000_000_000)
    return float(secs) + float(nsecs) / 1e9


def summarize(bag: BagReader, path: str, *, freq: bool = False) -> Summary:
    """What ``rosbag info`` shows about ``bag`` (opened from ``path``)."""
    compressions: dict[str, tuple[int, int, int]] = {}
    for index in range(len(bag.chunks)):
        header = bag.chunk_header(index)
        count, raw, stored = compressions.get(header.compression, (0, 0, 0))
        compressions[header.compression] = (
            count + 1,
            raw + header.size,
            stored + header.data_size,
        )
    types: dict[str, str] = {}
    for conn in bag.connections.values():
        types.setdefault(conn.type, conn.md5sum)
    topics = []
    for topic in sorted({c.topic for c in bag.connections.values()}):
        conns = [c for c in bag.connections.values() if c.topic == topic]
        ids = {c.id for c in conns}
        frequency = _median_frequency(bag, ids) if freq else None
        topics.append(TopicRow(topic, conns[0].type, bag.message_count(ids), len(conns), frequency))
    start = bag.start_time or 0
    end = bag.end_time or 0
    return Summary(
        path=path,
        version="2.0",
        size=bag.size,
        indexed=True,
        start=to_sec(start),
        end=to_sec(end),
        messages=bag.message_count(),
        compressions=compressions,
        chunk_count=len(bag.chunks),
        types=sorted(types.items()),
        topics=topics,
    )


def _median_frequency(bag: BagReader, conns: set[int]) -> float | None:
    stamps = [to_sec(t) for t, _, _, _ in bag.entries(conns)]
    if len(stamps) < 2:
        return None
    periods = sorted(b - a for a, b in itertools.pairwise(stamps))
    half = len(periods) // 2
    median = periods[half] if len(periods) % 2 else (periods[half - 1] + periods[half]) / 2
    return 1.0 / median if median > 0.0 else None


# -- ROS 1's units ----------------------------------------------------------------------------


def human_size(size: float) -> str:
    """``23.4 KB``: ROS 1's sizes (always at least KB)."""
    for suffix in ("KB", "MB", "GB", "TB", "PB", "EB", "ZB", "YB"):
        size /= 1024.0
        if size < 1024.0:
            return f"{size:.1f} {suffix}"
    return "-"


def human_frequency(freq: float) -> str:
    """``50.0 Hz``, ``1.2 kHz``."""
    for suffix in ("Hz", "kHz", "MHz", "GHz", "THz", "PHz", "EHz", "ZHz", "YHz"):
        if freq < 1000.0:
            return f"{freq:.1f} {suffix}"
        freq /= 1000.0
    return "-"


def local_time(secs: float) -> str:
    """``Nov 24 2026 03:36:20.92``: local time with hundredths."""
    fraction = f"{secs - int(secs):.2f}"[1:]
    return time.strftime("%b %d %Y %H:%M:%S", time.localtime(secs)) + fraction


def _duration(duration: float) -> str:
    secs = duration % 60
    mins = int(duration / 60)
    hours = int(mins / 60)
    if hours > 0:
        return "%dhr %d:%02ds (%ds)" % (hours, mins % 60, secs, duration)  # noqa: UP031
    if mins > 0:
        return "%d:%02ds (%ds)" % (mins, secs, duration)  # noqa: UP031
    return f"{duration:.1f}s"


def _has_data(s: Summary) -> bool:
    return s.chunk_count > 0


# -- text -------------------------------------------------------------------------------------


def format_text(s: Summary) -> str:
    """``rosbag info BAG``'s text (without the final newline)."""
    rows: list[tuple[str, str]] = [("path", s.path), ("version", s.version)]
    if not _has_data(s):
        rows.append(("size", human_size(s.size)))
        return _layout(rows)
    duration = s.end - s.start
    rows += [
        ("duration", _duration(duration)),
        ("start", f"{local_time(s.start)} ({s.start:.2f})"),
        ("end", f"{local_time(s.end)} ({s.end:.2f})"),
        ("size", human_size(s.size)),
        ("messages", str(s.messages)),
    ]
    rows += _compression_rows(s, duration)
    width_type = max((len(t) for t, _ in s.types), default=0)
    for i, (name, md5) in enumerate(s.types):
        rows.append(("types" if i == 0 else "", f"{name:<{width_type}} [{md5}]"))
    if s.topics:
        width_topic = max(len(r.topic) for r in s.topics)
        width_count = max(len(str(r.messages)) for r in s.topics)
        freqs = [human_frequency(r.frequency) for r in s.topics if r.frequency is not None]
        width_freq = max((len(f) for f in freqs), default=0)
        for i, r in enumerate(s.topics):
            unit = "msgs" if r.messages > 1 else "msg "
            text = f"{r.topic:<{width_topic}}   {r.messages:>{width_count}} {unit}"
            if r.frequency is not None:
                text += f" @ {human_frequency(r.frequency):>{width_freq}}"
            else:
                text += "   " + " " * width_freq
            text += f" : {r.type:<{width_type}}"
            if r.connections > 1:
                text += f" ({r.connections} connections)"
            rows.append(("topics" if i == 0 else "", text))
    return _layout(rows)


def _compression_rows(s: Summary, duration: float) -> list[tuple[str, str]]:
    if not s.compressions:
        return [("compression", "none")]
    ranked = sorted(((n, c) for c, (n, _, _) in s.compressions.items()), reverse=True)
    parts = []
    for count, name in ranked:
        if name != "none":
            _, raw, stored = s.compressions[name]
            parts.append(f"{name} [{count}/{s.chunk_count} chunks; {100.0 * stored / raw:.2f}%]")
        else:
            parts.append(f"{name} [{count}/{s.chunk_count} chunks]")
    rows = [("compression", ", ".join(parts))]
    if all(name == "none" for name in s.compressions):
        return rows
    raw_total = sum(raw for _, raw, _ in s.compressions.values())
    stored_total = sum(stored for _, _, stored in s.compressions.values())
    raw_text, stored_text = human_size(raw_total), human_size(stored_total)
    width = max(len(raw_text), len(stored_text))
    if duration > 0:
        raw_rate, stored_rate = (
            human_size(raw_total / duration),
            human_size(stored_total / duration),
        )
        rate = max(len(raw_rate), len(stored_rate))
        ratio = 100.0 * stored_total / raw_total
        rows.append(("uncompressed", f"{raw_text:>{width}} @ {raw_rate:>{rate}}/s"))
        rows.append(
            ("compressed", f"{stored_text:>{width}} @ {stored_rate:>{rate}}/s ({ratio:.2f}%)")
        )
    else:
        rows.append(("uncompressed", f"{raw_text:>{width}}"))
        rows.append(("compressed", f"{stored_text:>{width}}"))
    return rows


def _layout(rows: list[tuple[str, str]]) -> str:
    width = max(len(field) for field, _ in rows) + 1
    lines = [f"{(field + ':') if field else '':<{width}} {value}" for field, value in rows]
    return "\n".join(lines).rstrip()


# -- YAML -------------------------------------------------------------------------------------


def format_yaml(s: Summary) -> str:
    """``rosbag info -y BAG``'s text (ending with a newline)."""
    lines = [f"path: {s.path}", f"version: {s.version}"]
    if not _has_data(s):
        lines += [f"size: {s.size}", "indexed: False"]
        return "\n".join(lines) + "\n"
    lines += [
        f"duration: {s.end - s.start:.6f}",
        f"start: {s.start:.6f}",
        f"end: {s.end:.6f}",
        f"size: {s.size}",
        f"messages: {s.messages}",
        "indexed: True",
    ]
    if not s.compressions:
        lines.append("compression: none")
    else:
        ranked = sorted(((n, c) for c, (n, _, _) in s.compressions.items()), reverse=True)
        lines.append(f"compression: {ranked[0][1]}")
        if not all(name == "none" for name in s.compressions):
            lines.append(f"uncompressed: {sum(r for _, r, _ in s.compressions.values())}")
            lines.append(f"compressed: {sum(c for _, _, c in s.compressions.values())}")
    lines.append("types:")
    for name, md5 in s.types:
        lines += [f"    - type: {name}", f"      md5: {md5}"]
    lines.append("topics:")
    for r in s.topics:
        lines += [
            f"    - topic: {r.topic}",
            f"      type: {r.type}",
            f"      messages: {r.messages}",
        ]
        if r.connections > 1:
            lines.append(f"      connections: {r.connections}")
        if r.frequency is not None:
            lines.append(f"      frequency: {r.frequency:.4f}")
    return "\n".join(lines) + "\n"


def _yaml_scalar(text: str) -> Any:
    """A plain YAML scalar as a YAML loader would type it (enough for info's values)."""
    if text in ("True", "False"):
        return text == "True"
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            continue
    return text


def _yaml_tree(s: Summary) -> dict[str, Any]:
    tree: dict[str, Any] = {}
    current: list[dict[str, Any]] | None = None
    for line in format_yaml(s).splitlines():
        if line.startswith("    - "):
            key, _, value = line[6:].partition(": ")
            assert current is not None
            current.append({key: _yaml_scalar(value)})
        elif line.startswith("      "):
            key, _, value = line[6:].partition(": ")
            assert current is not None
            current[-1][key] = _yaml_scalar(value)
        elif line.endswith(":"):
            current = tree[line[:-1]] = []
        else:
            key, _, value = line.partition(": ")
            tree[key] = _yaml_scalar(value)
    return tree


_KEY = re.compile(r"[A-Za-z_]\w*|\.[A-Za-z_]\w*|\[-?\d+\]")


def lookup_key(s: Summary, key: str) -> str | None:
    """``rosbag info -y -k KEY``'s text, or None when the key does not exist."""
    parts = _KEY.findall(key)
    if "".join(parts) != key or not parts or parts[0].startswith(("[", ".")):
        return None
    value: Any = _yaml_tree(s)
    for part in parts:
        name = part.lstrip(".")
        try:
            value = value[int(part[1:-1])] if part.startswith("[") else value[name]
        except (KeyError, IndexError, TypeError):
            return None
    return _print_value(value)


def _print_value(value: Any, indent: int = 0) -> str:
    pad = "  " * indent
    if isinstance(value, list):
        return "".join(f"{pad}- {_print_value(item, indent + 1)}\n" for item in value)
    if isinstance(value, dict):
        items = [f"{k}: {v}" for k, v in value.items()]
        return ("\n" + pad).join(items)
    return pad + str(value)


__all__ = ["Summary", "TopicRow", "format_text", "format_yaml", "lookup_key", "summarize"]
