"""Files of public repositories fetched beside the checkout, for the tests that run them.

Such repositories are never copied into this one: a test reads the file from the fetched
copy (a bare git mirror under ``ROSX_FETCHED``, ``/work/.mirror`` by default, one folder
``owner+name/repo`` per repository) and skips cleanly where there is none, as on CI.
"""

from __future__ import annotations

import io
import os
import shutil
import subprocess
import tarfile
from pathlib import Path

import pytest


def _mirror(repository: str) -> tuple[str, Path]:
    root = Path(os.environ.get("ROSX_FETCHED", "/work/.mirror"))
    mirror = root / repository.replace("/", "+") / "repo"
    git = shutil.which("git")
    if git is None or not mirror.is_dir():
        pytest.skip(f"{repository} has not been fetched (no {mirror})")
    return git, mirror


def fetched_tree(repository: str, folder: str, into: Path) -> Path:
    """The folder ``folder`` of the fetched ``repository``, written under ``into`` (as
    ``into/folder``); skips the test when that repository has not been fetched."""
    git, mirror = _mirror(repository)
    done = subprocess.run(
        [git, "--git-dir", str(mirror), "archive", "--format=tar", "HEAD", folder],
        capture_output=True,
        timeout=60,
        check=False,
    )
    if done.returncode != 0:
        pytest.skip(f"{folder} is not in the fetched {repository}")
    with tarfile.open(fileobj=io.BytesIO(done.stdout)) as archive:
        if hasattr(tarfile, "tar_filter"):  # Pythons since 3.10.12/3.11.4 ask for a filter
            archive.extractall(into, filter="tar")
        else:
            archive.extractall(into)
    return into / folder


def fetched_file(repository: str, path: str, into: Path) -> Path:
    """``path`` of the fetched ``repository`` (``owner/name``), written under ``into``; skips
    the test when that repository has not been fetched."""
    git, mirror = _mirror(repository)
    done = subprocess.run(
        [git, "--git-dir", str(mirror), "show", f"HEAD:{path}"],
        capture_output=True,
        timeout=60,
        check=False,
    )
    if done.returncode != 0:
        pytest.skip(f"{path} is not in the fetched {repository}")
    target = into / Path(path).name
    target.write_bytes(done.stdout)
    target.chmod(0o755)
    return target
