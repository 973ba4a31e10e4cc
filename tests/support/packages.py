"""Making catkin packages for the workspace tests."""

from __future__ import annotations

from pathlib import Path

MANIFEST = """\
<?xml version="1.0"?>
<package format="2">
  <name>{name}</name>
  <version>0.0.0</version>
  <description>The {name} package</description>
  <maintainer email="me@todo.todo">me</maintainer>
  <license>TODO</license>
  <buildtool_depend>catkin</buildtool_depend>
{depends}</package>
"""


def package(src: Path, name: str, *depends: str) -> Path:
    directory = src / name
    directory.mkdir(parents=True)
    lines = "".join(f"  <depend>{d}</depend>\n" for d in depends)
    (directory / "package.xml").write_text(MANIFEST.format(name=name, depends=lines))
    return directory
