"""A message package written for a test: every kind of field, and the files of a package."""

from __future__ import annotations

from pathlib import Path

EVERY_KIND = """\
int8 SMALL=-3
string GREETING=hello # not a comment
bool b
bool[] bs
bool[3] bf
char c
char[] cs
char[4] cf
uint8[] u8
uint8[5] u8f
int8[] i8
byte by
float32 f
float64[9] f9
string s
string[] ss
string[2] sf
time t
time[] ts
duration d
duration[2] df
Sub sub
Sub[] subs
Sub[2] subf
Header h
uint64 u64
"""


def make_package(
    root: Path, name: str, msgs: dict[str, str], srvs: dict[str, str] | None = None
) -> Path:
    package = root / name
    (package / "msg").mkdir(parents=True)
    (package / "package.xml").write_text(f"<package><name>{name}</name></package>\n")
    for short, text in msgs.items():
        (package / "msg" / f"{short}.msg").write_text(text)
    if srvs:
        (package / "srv").mkdir()
        for short, text in srvs.items():
            (package / "srv" / f"{short}.srv").write_text(text)
    return root
