"""Launch files written to a temporary folder, read with a package index of one package."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from rosx.launch import LaunchPlan, load_launch
from rosx.launch.run.command import run_command
from rosx.packages.index import PackageIndex
from tests.support.launch_plan import PACKAGE_XML, Load, Write


@pytest.fixture
def write(tmp_path: Path) -> Write:
    def write(relative: str, text: str) -> Path:
        path = tmp_path / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
        return path

    return write


@pytest.fixture
def index(tmp_path: Path, write: Write) -> PackageIndex:
    """A package ``demo`` (with an executable ``scripts/run``) on the package path."""
    write("pkgs/demo/package.xml", PACKAGE_XML.format(name="demo"))
    script = write("pkgs/demo/scripts/run", "#!/bin/sh\n")
    script.chmod(0o755)
    return PackageIndex([tmp_path / "pkgs"])


@pytest.fixture
def load(write: Write, index: PackageIndex) -> Load:
    def load(
        text: str,
        cli_args: dict[str, str] | None = None,
        environ: dict[str, str] | None = None,
        **options: Any,
    ) -> LaunchPlan:
        path = write("main.launch", text)
        options.setdefault("anonymous", lambda name: f"{name}_ANON")
        options.setdefault("with_core", False)
        options.setdefault("run", run_command)
        return load_launch(
            [str(path)], cli_args or {}, environ or {"CORPUS": "c"}, index, **options
        )

    return load
