"""The package index's cache under ``ROS_HOME``: used while the tree is as it was, never stale.

A package added, removed, renamed in its manifest or hidden by ``CATKIN_IGNORE`` a moment ago
is seen by the next command (rospack's cache may answer from 60 s before).
"""

from __future__ import annotations

import shlex
import shutil
import subprocess
from pathlib import Path

import pytest

from rosx.packages import cache as package_cache
from rosx.packages.cache import cache_file, cached_packages
from rosx.packages.crawl import find_packages
from rosx.packages.index import PackageIndex
from rosx.packages.kept import kept_find, listed_packages, root_text
from tests.support.cli import clean_environ, rosx
from tests.support.packages import package


@pytest.fixture
def trusting(monkeypatch: pytest.MonkeyPatch) -> None:
    """Crawls are kept even when they saw times of a moment ago (this file system, unlike some,
    has times to the nanosecond): the tests change the tree right after a crawl."""
    monkeypatch.setattr(package_cache, "RACY_SECONDS", 0.0)


@pytest.fixture
def tree(tmp_path: Path, trusting: None) -> tuple[list[Path], Path]:
    """Two roots (a workspace and a system-like folder with packages deep down) and an empty
    ``ROS_HOME``."""
    src = tmp_path / "ws" / "src"
    package(src, "lab2", "rospy")
    package(src / "group", "deep_pkg")
    system = tmp_path / "share"
    package(system, "roscpp")
    (system / "doc" / "bash").mkdir(parents=True)
    (system / "doc" / "bash" / "README").write_text("not a package\n")
    package(system / "doc", "lab2")  # shadowed by the workspace's
    home = tmp_path / "ros_home"
    return [src, system, tmp_path / "not_yet"], home


def fresh(roots: list[Path], home: Path) -> dict[str, Path]:
    """What a new process's index finds (the cache in ``home``), checked against a crawl."""
    found = cached_packages(roots, home)
    assert found == find_packages(roots)
    return found


def test_the_crawl_is_kept_under_ros_home_and_answers_the_same(
    tree: tuple[list[Path], Path], monkeypatch: pytest.MonkeyPatch
) -> None:
    roots, home = tree
    first = fresh(roots, home)
    assert sorted(first) == ["deep_pkg", "lab2", "roscpp"]
    assert first["lab2"] == roots[0] / "lab2"
    assert cache_file(home, roots).is_file()
    crawls: list[object] = []

    def crawl(*args: object) -> dict[str, Path]:
        crawls.append(args)
        return {}

    monkeypatch.setattr(package_cache, "find_packages", crawl)
    assert cached_packages(roots, home) == first
    assert crawls == []  # answered from the cache: nothing crawled


def kept(roots: list[Path], home: Path) -> None:
    """The tree crawled and kept, so that the next answer comes from the cache unless the
    change made next is seen."""
    cache_file(home, roots).unlink(missing_ok=True)
    fresh(roots, home)
    assert cache_file(home, roots).is_file()


def test_a_change_made_a_moment_ago_is_seen_at_once(tree: tuple[list[Path], Path]) -> None:
    roots, home = tree
    src, system, later = roots
    kept(roots, home)
    made = package(src / "group", "made_now")
    assert "made_now" in fresh(roots, home)
    kept(roots, home)
    shutil.rmtree(made)
    assert "made_now" not in fresh(roots, home)
    kept(roots, home)
    manifest = src / "lab2" / "package.xml"
    manifest.write_text(manifest.read_text().replace("<name>lab2</name>", "<name>lab3</name>"))
    found = fresh(roots, home)
    assert found["lab3"] == src / "lab2" and found["lab2"] == system / "doc" / "lab2"
    kept(roots, home)
    (src / "group" / "CATKIN_IGNORE").touch()
    assert "deep_pkg" not in fresh(roots, home)
    kept(roots, home)
    package(later, "on_a_new_root")
    assert "on_a_new_root" in fresh(roots, home)
    kept(roots, home)
    package(system / "doc" / "bash", "deep_in_the_system")
    assert "deep_in_the_system" in fresh(roots, home)


def test_a_crawl_that_saw_fresh_times_is_not_kept(tmp_path: Path) -> None:
    """Within a file system's time resolution a second change could leave a time unmoved."""
    package(tmp_path / "src", "just_made")
    roots, home = [tmp_path / "src"], tmp_path / "home"
    assert "just_made" in fresh(roots, home)
    assert not cache_file(home, roots).exists()


def test_a_cache_that_cannot_be_read_or_written_is_no_cache(
    tree: tuple[list[Path], Path],
) -> None:
    roots, home = tree
    home.parent.joinpath("blocked").write_text("a file where ROS_HOME should be\n")
    assert sorted(fresh(roots, home.parent / "blocked")) == ["deep_pkg", "lab2", "roscpp"]
    fresh(roots, home)
    cache_file(home, roots).write_bytes(b"\x00garbage")
    assert sorted(fresh(roots, home)) == ["deep_pkg", "lab2", "roscpp"]


def test_rospack_keeps_its_crawl_in_ros_home(tree: tuple[list[Path], Path]) -> None:
    roots, home = tree
    path = ":".join(str(r) for r in roots)
    env = clean_environ(ROS_PACKAGE_PATH=path, ROS_HOME=str(home))
    found = rosx("rospack", "find", "deep_pkg", environ=env)
    assert (found.status, found.out) == (0, f"{roots[0]}/group/deep_pkg\n")
    assert cache_file(home, roots).is_file()
    package(roots[0], "new_pkg")
    assert rosx("rospack", "find", "new_pkg", environ=env).out == f"{roots[0]}/new_pkg\n"
    index = PackageIndex.from_environ(env)
    assert index.path_packages == find_packages(roots)


def index(roots: list[Path], home: Path) -> PackageIndex:
    """A new process's index of ``roots`` (its crawl kept in ``home``)."""
    return PackageIndex(roots, cache_folder=home)


def test_one_package_is_found_checking_what_comes_before_it(
    tree: tuple[list[Path], Path],
) -> None:
    """The first of a name wins: what the crawl met after a package cannot move it, what it
    met before can (a package of that name made in front of it, another renamed to it)."""
    roots, home = tree
    src, system, _ = roots
    kept(roots, home)
    package(system / "zz_later", "late_pkg")  # after roscpp and lab2 in the crawl's order
    assert index(roots, home).find("lab2") == src / "lab2"
    found = index(roots, home)
    assert found.find("roscpp") == system / "roscpp"
    assert (
        "late_pkg" in found.packages and found.find("late_pkg") == system / "zz_later" / "late_pkg"
    )
    kept(roots, home)
    package(src, "roscpp")  # in front of the system's
    assert index(roots, home).find("roscpp") == src / "roscpp"
    kept(roots, home)
    manifest = src / "group" / "deep_pkg" / "package.xml"
    manifest.write_text(manifest.read_text().replace("deep_pkg", "lab2"))
    assert index(roots, home).find("lab2") == src / "group" / "deep_pkg"  # "group" < "lab2"
    kept(roots, home)
    assert index(roots, home).directories("lab2") == [src / "group" / "deep_pkg"]


# -- what rospack list, rospack find and a <TAB> read without the index ----------------------


def environ_of(roots: list[Path], home: Path) -> dict[str, str]:
    return clean_environ(ROS_PACKAGE_PATH=":".join(str(r) for r in roots), ROS_HOME=str(home))


def test_the_kept_crawl_answers_as_the_index_while_it_holds(
    tree: tuple[list[Path], Path],
) -> None:
    """`rosx.packages.kept` reads the kept crawl with os alone: the index's list and the
    index's find, and no answer (the index then crawls) once what they depend on changed."""
    roots, home = tree
    src, system, _ = roots
    env = environ_of(roots, home)
    assert listed_packages(env) is None and kept_find(env, "lab2") is None  # nothing kept yet
    kept(roots, home)
    whole = index(roots, home)
    assert listed_packages(env) == {name: str(d) for name, d in whole.packages.items()}
    assert "turtlesim" in whole.packages  # rosx's own, after the path's
    for name in ("lab2", "deep_pkg", "roscpp", "turtlesim"):
        assert kept_find(env, name) == str(whole.find(name))
    assert kept_find(env, "nowhere") is None
    package(system / "zz_later", "late_pkg")  # after the workspace in the crawl's order
    assert kept_find(env, "lab2") == str(src / "lab2")  # nothing before it changed
    assert kept_find(env, "roscpp") is None  # its own folder changed: the index answers
    assert kept_find(env, "turtlesim") is None  # the path could now hide rosx's own
    assert listed_packages(env) is None


@pytest.mark.parametrize(
    "entry", ["/usr/share", "/usr/share/", "//net/share", "///usr//share/./", "ws/src", "./ws", "."]
)
def test_the_kept_crawl_names_its_roots_as_pathlib_writes_them(entry: str) -> None:
    assert root_text(entry) == str(Path(entry))


def tab(environ: dict[str, str], *words: str) -> list[str]:
    """What a shell's <TAB> offers after ``words``: the Python the shell functions start."""
    from rosx_commands.invocation import complete_command

    argv = [*shlex.split(complete_command()), str(len(words) - 1), *words]
    done = subprocess.run(
        argv, env=environ, capture_output=True, text=True, timeout=60, check=False
    )
    assert done.returncode == 0, done.stderr
    return [c for c in done.stdout.split("\0") if c]


def test_a_tab_offers_a_package_made_a_moment_ago(tree: tuple[list[Path], Path]) -> None:
    roots, home = tree
    src = roots[0]
    env = environ_of(roots, home)
    kept(roots, home)
    assert tab(env, "roscd", "la") == ["lab2/"]
    package(src, "lab3")
    assert tab(env, "roscd", "la") == ["lab2/", "lab3/"]
    assert tab(env, "rosrun", "lab") == ["lab2", "lab3"]
    kept(roots, home)
    shutil.rmtree(src / "lab3")
    assert tab(env, "rospack", "find", "la") == ["lab2"]
