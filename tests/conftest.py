"""Test-session setup: rosx under test sees no ROS environment unless a test gives it one.

CI exports the ROS 1 reference's variables (``ROS_PACKAGE_PATH`` …) for the whole run; tests that
run ROS 1 pass them explicitly (``tests.support.ros1.ros1_environ``), and everything else must not
depend on them.
"""

from __future__ import annotations

import os

import pytest


def pytest_configure(config: pytest.Config) -> None:
    for name in [n for n in os.environ if n.startswith("ROS_")]:
        del os.environ[name]
