"""The package index: which ROS packages exist and where, as ``rospack`` answers them.

Packages are the directories holding a ``package.xml`` on ``ROS_PACKAGE_PATH`` (crawled as
rospack crawls it, `rosx.packages.crawl`), then the packages shipped with rosx: Noetic's core
(``roscpp``, ``rospy``, ``std_msgs``, ``catkin``…, with their ``package.xml`` dependencies, so
``rospack depends`` answers as on Noetic), the tutorials' packages and turtlesim. A few
packages whose types the message layer knows without a directory (``actionlib``, ``bond``)
count as known when depended on, without a directory for ``rospack find``: the index sits below
the message layer, so the caller passes that test as ``provides`` (``rospack`` passes the type
store's ``has_package``). Dependencies that are not known at all are skipped silently, as
rospack skips system dependencies.

The type store (`rosx.msg.store`) finds packages' ``msg/`` and ``srv/`` folders through this
index, and ``rospack``, ``rosrun``, ``roscd`` through it too: one crawl of the package path,
kept between processes under ``ROS_HOME`` and never trusted stale (`rosx.packages.cache`).
"""

from __future__ import annotations

import contextlib
from functools import cached_property

from rosx.packages.crawl import bundled_packages, split_package_path

TYPE_CHECKING = False
if TYPE_CHECKING:
    from collections.abc import Callable, Iterable, Mapping
    from pathlib import Path

    from rosx.packages.cache import KeptCrawl
    from rosx.packages.manifest import Manifest


class PackageNotFoundError(LookupError):
    """No package of that name; ``str()`` is rospack's text."""

    def __init__(self, name: str) -> None:
        super().__init__(f"[rospack] Error: package '{name}' not found")
        self.name = name


def ros_path_lines(package_path: Iterable[str | Path]) -> list[str]:
    """``ROS path [N]=DIR`` for each directory of ``package_path``: how rospkg, rosmsg and
    roslaunch say where a package was looked for."""
    return [f"ROS path [{number}]={path}" for number, path in enumerate(package_path)]


class PackageIndex:
    """The packages visible from one package path."""

    def __init__(
        self,
        package_path: list[Path],
        provides: Callable[[str], bool] | None = None,
        *,
        crawled: Mapping[str, Path] | None = None,
        cache_folder: Path | None = None,
    ) -> None:
        """Index the packages on ``package_path``.

        Args:
            package_path: the entries of ``ROS_PACKAGE_PATH``, searched in order.
            provides: tells whether a package without a directory is provided anyway (by the
                message layer's standard types); none by default.
            crawled: what a crawl of ``package_path`` just found (`path_packages`), when another
                process has done it for this one; crawled on first use otherwise.
            cache_folder: where the crawl is kept between processes (``ROS_HOME``,
                `rosx.packages.cache`); None: crawled by each process.
        """
        self.package_path = package_path
        self._provides = provides
        self._cache_folder = cache_folder
        self._manifests: dict[str, Manifest] = {}
        if crawled is not None:
            self.__dict__["path_packages"] = dict(crawled)  # the cached_property's value

    @classmethod
    def from_environ(
        cls, environ: Mapping[str, str], provides: Callable[[str], bool] | None = None
    ) -> PackageIndex:
        """The index of ``environ``'s ``ROS_PACKAGE_PATH``, its crawl kept in ``ROS_HOME``."""
        from rosx.cache import ros_home  # noqa: PLC0415 - the one place that knows ROS_HOME

        return cls(
            split_package_path(environ.get("ROS_PACKAGE_PATH")),
            provides,
            cache_folder=ros_home(environ),
        )

    @cached_property
    def _kept(self) -> KeptCrawl:
        from rosx.packages.cache import KeptCrawl  # noqa: PLC0415 - crawling or not

        return KeptCrawl(self.package_path, self._cache_folder)

    @cached_property
    def path_packages(self) -> dict[str, Path]:
        """The packages found on the package path alone, by name."""
        return self._kept.packages()

    @cached_property
    def packages(self) -> dict[str, Path]:
        """Every package with a directory, by name; the package path wins over rosx's own."""
        found = dict(self.path_packages)
        for name, directory in bundled_packages().items():
            found.setdefault(name, directory)
        return dict(sorted(found.items()))

    def on_path(self, name: str) -> Path | None:
        """The directory of package ``name`` on the package path alone, if it is there: asked
        of the cache for this one package while the whole crawl is not needed
        (`rosx.packages.cache.KeptCrawl.find`: what precedes it on the path checked only)."""
        if "path_packages" not in self.__dict__:
            found = self._kept.find(name)
            if found is not None:
                return found
        return self.path_packages.get(name)

    def find(self, name: str) -> Path:
        """The directory of package ``name``; `PackageNotFoundError` if it has none."""
        directory = self.on_path(name) or bundled_packages().get(name)
        if directory is None:
            raise PackageNotFoundError(name)
        return directory

    def not_found_text(self, name: str) -> str:
        """What rospkg says of package ``name`` not found: the name, then each ``ROS path
        [N]=DIR`` of the package path searched (`ros_path_lines`)."""
        return "\n".join([name, *ros_path_lines(self.package_path)])

    def directories(self, name: str) -> list[Path]:
        """Where package ``name``'s files are looked for: the package path's directory, then
        rosx's own of that name. A package on the path shadows rosx's only for the files it
        has (a message-only ``turtlesim`` leaves rosx's launch files reachable)."""
        found = [d for d in (self.on_path(name), bundled_packages().get(name)) if d]
        return list(dict.fromkeys(found))

    def is_known(self, name: str) -> bool:
        """Whether ``name`` is a package: with a directory, or one rosx provides."""
        if self.on_path(name) is not None or name in bundled_packages():
            return True
        return self._provides is not None and self._provides(name)

    def manifest(self, name: str) -> Manifest | None:
        """The manifest of ``name``; None for a package rosx provides without one."""
        cached = self._manifests.get(name)
        if cached is None:
            directory = self.on_path(name) or bundled_packages().get(name)
            if directory is None:
                if self.is_known(name):
                    return None
                raise PackageNotFoundError(name)
            from rosx.packages.manifest import read_manifest  # noqa: PLC0415 - XML on first use

            cached = self._manifests[name] = read_manifest(directory)
        return cached

    def depends1(self, name: str) -> list[str]:
        """The known run dependencies of ``name``, in manifest order."""
        manifest = self.manifest(name)
        if manifest is None:
            return []
        return [dep for dep in manifest.run_depends() if self.is_known(dep)]

    def depends(self, name: str) -> list[str]:
        """Every known run dependency of ``name``, recursively, dependencies first."""
        from rosx.packages.manifest import ManifestError  # noqa: PLC0415 - XML on first use

        order: list[str] = []
        visiting: set[str] = {name}

        def visit(package: str) -> None:
            for dep in self.depends1(package):
                if dep in visiting or dep in order:
                    continue
                visiting.add(dep)
                # A broken manifest further down is rospack's warning, not this answer's.
                with contextlib.suppress(ManifestError):
                    visit(dep)
                order.append(dep)

        visit(name)
        return order

    def depends_on1(self, name: str) -> list[str]:
        """The packages with a directory that run-depend on ``name`` directly."""
        from rosx.packages.manifest import ManifestError  # noqa: PLC0415 - XML on first use

        users = []
        for package in self.packages:
            try:
                if name in self.depends1(package):
                    users.append(package)
            except ManifestError:
                continue
        return users


__all__ = ["PackageIndex", "PackageNotFoundError", "bundled_packages", "ros_path_lines"]
