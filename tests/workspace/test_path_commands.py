"""The programs with ROS 1's command names (`rosx.workspace.path_commands`): in the user's
cache folder, one folder per install, written once and only when different."""

from __future__ import annotations

import os
from pathlib import Path

from rosx.workspace.path_commands import MODE, command_folder, command_script, write_commands


def test_the_folder_is_in_the_cache_folder_and_named_after_the_install(tmp_path: Path) -> None:
    home = {"HOME": str(tmp_path)}
    folder = command_folder(home, "/venv/bin/rosx")
    assert folder is not None and folder.parent == tmp_path / ".cache" / "rosx"
    assert folder.name.startswith("bin-") and len(folder.name) == len("bin-1a2b3c4d")
    assert command_folder(home, "/other/bin/rosx") != folder
    assert command_folder(home, "/venv/bin/rosx") == folder
    xdg = command_folder({**home, "XDG_CACHE_HOME": str(tmp_path / "xdg")}, "/venv/bin/rosx")
    assert xdg == tmp_path / "xdg" / "rosx" / folder.name
    # The XDG spec: a relative XDG_CACHE_HOME is ignored.
    assert command_folder({**home, "XDG_CACHE_HOME": "rel"}, "/venv/bin/rosx") == folder
    assert command_folder({"HOME": "relative"}, "/venv/bin/rosx") is None


def test_programs_are_written_once_and_only_the_given_names_stay(tmp_path: Path) -> None:
    folder = tmp_path / "bin-x"
    write_commands(folder, "/venv/bin/rosx", ["rostopic", "rosmsg-proto", "gone"])
    script = folder / "rostopic"
    assert script.read_text() == '#!/bin/sh\nexec /venv/bin/rosx rostopic "$@"\n'
    assert script.read_text() == command_script("/venv/bin/rosx", "rostopic")
    assert script.stat().st_mode & 0o7777 == MODE
    assert os.access(folder / "rosmsg-proto", os.X_OK)
    written = {p.name: (p.stat().st_ino, p.stat().st_mtime_ns) for p in folder.iterdir()}
    (folder / ".rostopic.123").write_text("another shell-init's file being written")

    write_commands(folder, "/venv/bin/rosx", ["rostopic", "rosmsg-proto"])
    assert {p.name for p in folder.iterdir()} == {"rostopic", "rosmsg-proto", ".rostopic.123"}
    for path in (script, folder / "rosmsg-proto"):
        assert (path.stat().st_ino, path.stat().st_mtime_ns) == written[path.name]

    script.write_text("#!/bin/sh\nexec /old/rosx rostopic\n")
    write_commands(folder, "/venv/bin/rosx", ["rostopic", "rosmsg-proto"])
    assert script.read_text() == command_script("/venv/bin/rosx", "rostopic")
    script.chmod(0o644)
    write_commands(folder, "/venv/bin/rosx", ["rostopic", "rosmsg-proto"])
    assert script.stat().st_mode & 0o7777 == MODE
