"""ROS 1's own repositories, for the tests that run their code against rosx (never copied into
this repository): each is found through an environment variable, and those tests skip without
it.

``UPSTREAM_ACTIONLIB`` names a copy of github:ros/actionlib, ``UPSTREAM_COMMON_TUTORIALS``
one of github:ros/common_tutorials: a checked-out work tree, or a bare git repository (its
``HEAD`` is used).
"""

from __future__ import annotations

import io
import os
import shutil
import subprocess
import tarfile
from pathlib import Path

import pytest


def upstream(repository: str) -> Path | None:
    """The copy of ``repository`` (``actionlib``, ``common_tutorials``) named by its variable."""
    value = os.environ.get(f"UPSTREAM_{repository.upper()}")
    return Path(value) if value and Path(value).is_dir() else None


def needs_upstream(repository: str) -> pytest.MarkDecorator:
    """Skip the test when there is no copy of ``repository``."""
    return pytest.mark.skipif(
        upstream(repository) is None,
        reason=f"set UPSTREAM_{repository.upper()} to a copy of github:ros/{repository}",
    )


def export(repository: str, folders: list[str], destination: Path) -> None:
    """Copy ``folders`` of ``repository``'s copy into ``destination``."""
    source = upstream(repository)
    assert source is not None
    destination.mkdir(parents=True, exist_ok=True)
    if (source / folders[0]).is_dir():
        for folder in folders:
            shutil.copytree(source / folder, destination / folder)
        return
    archive = subprocess.run(
        ["git", "--git-dir", str(source), "archive", "--format=tar", "HEAD", *folders],
        capture_output=True,
        check=True,
        timeout=60,
    )
    with tarfile.open(fileobj=io.BytesIO(archive.stdout)) as tar:
        if hasattr(tarfile, "data_filter"):
            tar.extractall(destination, filter="data")
        else:  # Python before 3.10.12: git's own archive, nothing to filter
            tar.extractall(destination)
