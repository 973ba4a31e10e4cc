"""Launch files written for a test and read into a plan: the package manifest, the fixtures' types."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from rosx.launch import LaunchPlan

PACKAGE_XML = """<?xml version="1.0"?>
<package format="2"><name>{name}</name><version>0.0.1</version>
<description>d</description><maintainer email="a@b.c">m</maintainer><license>BSD</license>
</package>
"""

#: Writes a file below the test's folder and returns its path.
Write = Callable[[str, str], Path]
#: Reads launch text (written to ``main.launch``) into a plan.
Load = Callable[..., LaunchPlan]
