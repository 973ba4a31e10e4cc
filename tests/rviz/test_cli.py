"""``rosx rviz``'s command line: a bad config is one line naming the file, exit status 1; the
view needs a terminal; ``rosrun rviz rviz`` is the same program."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.support.cli import rosx, rosx_process


@pytest.mark.parametrize(
    ("text", "problem"),
    [
        ("Visualization Manager:\n  Displays:\n  - Class: rviz/Grid\n Name: x\n", " (line 4): "),
        ("just words\n", ": not an rviz config (no 'Visualization Manager')"),
    ],
)
def test_a_bad_config_is_one_line_naming_the_file(
    tmp_path: Path, text: str, problem: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    (tmp_path / "bad.rviz").write_text(text)
    monkeypatch.chdir(tmp_path)
    result = rosx("rviz", "-d", "bad.rviz")
    assert (result.status, result.out) == (1, "")
    (line,) = result.err.splitlines()
    assert line.startswith("rviz: cannot load bad.rviz")
    assert problem in line


def test_rosrun_rviz_rviz_is_rosx_rviz(tmp_path: Path) -> None:
    (tmp_path / "bad.rviz").write_text("[1, 2]\n")
    result = rosx_process("rosrun", "rviz", "rviz", "-d", str(tmp_path / "bad.rviz"))
    assert result.status == 1
    assert result.err == (
        f"rviz: cannot load {tmp_path / 'bad.rviz'}: not an rviz config "
        "(no 'Visualization Manager')\n"
    )


def test_a_missing_config_names_it() -> None:
    result = rosx("rviz", "--display-config", "no/such.rviz")
    assert (result.status, result.err) == (1, "rviz: cannot load no/such.rviz: no such file\n")


def test_the_view_needs_a_terminal(tmp_path: Path) -> None:
    result = rosx("rviz", "-f", "odom", environ={"HOME": str(tmp_path)})
    assert (result.status, result.err) == (2, "rviz: error: the view needs a terminal\n")


def test_help_names_the_options() -> None:
    result = rosx("rviz", "-h")
    assert result.status == 0
    assert "-d CONFIG, --display-config=CONFIG" in result.out
    assert "-f FRAME, --fixed-frame=FRAME" in result.out
