"""``package.xml``: reading a package manifest and checking it as catkin does (REP 127/140/149).

`read_manifest` parses the file and `Manifest.problems` lists what catkin_pkg would refuse, in
its words (``The package node must contain at least one "license" tag``…). `ManifestError`
carries them with the file's path, printed as catkin prints them::

    Error(s) in package '/home/u/catkin_ws/src/lab2/package.xml':
    The manifest contains invalid XML:
    mismatched tag: line 3, column 14
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from pathlib import Path

from rosx.record import Record

MANIFEST = "package.xml"

_NAME = re.compile(r"^[a-zA-Z0-9][a-zA-Z0-9_-]*$")
_CONVENTIONAL_NAME = re.compile(r"^[a-z][a-z0-9_-]*$")
_VERSION = re.compile(r"^[0-9]+\.[0-9]+\.[0-9]+$")
_CANONICAL_VERSION = re.compile(r"^(0|[1-9][0-9]*)\.(0|[1-9][0-9]*)\.(0|[1-9][0-9]*)$")
_EMAIL = re.compile(
    r"^[-a-zA-Z0-9_%+]+(\.[-a-zA-Z0-9_%+]+)*@[-a-zA-Z0-9%]+(\.[-a-zA-Z0-9%]+)*\.[a-zA-Z]{2,}$"
)

#: Dependency tags, by kind; ``depend`` counts as build, build_export and exec.
DEPEND_TAGS = (
    "buildtool_depend",
    "build_depend",
    "build_export_depend",
    "buildtool_export_depend",
    "exec_depend",
    "run_depend",
    "depend",
    "test_depend",
    "doc_depend",
)


class ManifestError(Exception):
    """A manifest catkin would refuse; ``str()`` is catkin's report."""

    def __init__(self, message: str, path: Path | str | None = None) -> None:
        super().__init__(message)
        self.message = message
        self.path = path

    def __str__(self) -> str:
        head = f"Error(s) in package '{self.path}':\n" if self.path else ""
        return head + self.message


class Person(Record):
    """A maintainer or author."""

    __match_args__ = ("name", "email")
    __slots__ = __match_args__
    name: str
    email: str | None

    def __init__(self, name: str, email: str | None) -> None:
        super().__init__(name=name, email=email)


class Manifest(Record):
    """What rosx needs of a ``package.xml``."""

    __match_args__ = (
        "path",
        "format",
        "name",
        "version",
        "description",
        "maintainers",
        "authors",
        "licenses",
        "depends",
        "metapackage",
    )
    __slots__ = __match_args__
    path: Path
    format: str
    name: str
    version: str
    description: str
    maintainers: tuple[Person, ...]
    authors: tuple[Person, ...]
    licenses: tuple[str, ...]
    depends: dict[str, tuple[str, ...]]
    metapackage: bool

    def __init__(
        self,
        *,
        path: Path,
        format: str,
        name: str,
        version: str,
        description: str,
        maintainers: tuple[Person, ...],
        authors: tuple[Person, ...],
        licenses: tuple[str, ...],
        depends: dict[str, tuple[str, ...]],
        metapackage: bool,
    ) -> None:
        super().__init__(
            path=path,
            format=format,
            name=name,
            version=version,
            description=description,
            maintainers=maintainers,
            authors=authors,
            licenses=licenses,
            depends=depends,
            metapackage=metapackage,
        )

    @property
    def directory(self) -> Path:
        """The package's folder (where its ``package.xml`` is)."""
        return self.path.parent

    def run_depends(self) -> list[str]:
        """What ``rospack depends1`` lists: exec dependencies (run_depend in format 1)."""
        tags = ("run_depend",) if self.format == "1" else ("exec_depend", "depend")
        return self._names(tags)

    def build_depends(self) -> list[str]:
        """What the package needs to be built: build and buildtool dependencies."""
        return self._names(("buildtool_depend", "build_depend", "depend"))

    def _names(self, tags: tuple[str, ...]) -> list[str]:
        names: list[str] = []
        for tag in DEPEND_TAGS:
            if tag in tags:
                names += [n for n in self.depends.get(tag, ()) if n not in names]
        return names

    def problems(self) -> tuple[list[str], list[str]]:
        """``(errors, warnings)`` as catkin_pkg's validation words them."""
        errors: list[str] = []
        warnings: list[str] = []
        if not re.match(r"^[1-9][0-9]*$", self.format):
            errors.append(
                'The "format" attribute of the package must contain a positive integer if present'
            )
        if not self.name:
            errors.append("Package name must not be empty")
        if not _NAME.match(self.name):
            errors.append(f'Package name "{self.name}" does not follow naming conventions')
        elif not _CONVENTIONAL_NAME.match(self.name):
            warnings.append(name_warning(self.name))
        if not self.version:
            errors.append("Package version must not be empty")
        elif not _VERSION.match(self.version):
            errors.append(f'Package version "{self.version}" does not follow version conventions')
        elif not _CANONICAL_VERSION.match(self.version):
            warnings.append(
                f'Package "{self.name}" does not follow the version conventions. It should not '
                "contain leading zeros (unless the number is 0)."
            )
        if not self.description:
            errors.append("Package description must not be empty")
        if not self.maintainers:
            errors.append(f"Package '{self.name}' must declare at least one maintainer")
        for person in self.maintainers:
            errors += _person_problems(person)
            if not person.email:
                errors.append("Maintainers must have an email address")
        if not self.licenses:
            errors.append('The package node must contain at least one "license" tag')
        if any(not text.strip() for text in self.licenses):
            errors.append("The license tag must neither be empty nor only contain whitespaces")
        for person in self.authors:
            errors += _person_problems(person)
        for tag, names in self.depends.items():
            if self.name in names:
                kind = {"depend": "build", "run_depend": "exec"}.get(tag, tag[: -len("_depend")])
                errors.append(
                    f'The package "{self.name}" must not "{kind}_depend" on a package with the '
                    "same name as this package"
                )
        return errors, warnings


def name_warning(name: str) -> str:
    """catkin's warning for a legal but unconventional package name."""
    return (
        f'Package name "{name}" does not follow the naming conventions. It should start with a '
        "lower case letter and only contain lower case letters, digits, underscores, and dashes."
    )


def _person_problems(person: Person) -> list[str]:
    if person.email is None or _EMAIL.match(person.email):
        return []
    return [f'Invalid email "{person.email}" for person "{person.name}"']


def _text(node: ET.Element) -> str:
    return (node.text or "").strip(" \n\r\t")


def _one(root: ET.Element, tag: str, path: Path) -> ET.Element:
    nodes = root.findall(tag)
    if len(nodes) != 1:
        raise ManifestError(f'The manifest must contain exactly one "{tag}" tag', path)
    return nodes[0]


def _people(root: ET.Element, tag: str, path: Path, *, email_required: bool) -> tuple[Person, ...]:
    people = []
    for node in root.findall(tag):
        email = node.get("email")
        if email is None and email_required:
            raise ManifestError(f'The "{tag}" tag must have the attribute "email"', path)
        people.append(Person(_text(node), email))
    return tuple(people)


def parse_manifest(text: str, path: Path) -> Manifest:
    """The manifest in ``text`` (read from ``path``), without validating its values.

    Raises:
        ManifestError: the XML is invalid, or a required tag is missing or repeated.
    """
    try:
        root = ET.fromstring(text)
    except ET.ParseError as error:
        raise ManifestError(f"The manifest contains invalid XML:\n{error}", path) from None
    if root.tag != "package":
        raise ManifestError('The manifest must contain a single "package" root tag', path)
    description = _one(root, "description", path)
    return Manifest(
        path=path,
        format=root.get("format", "1"),
        name=_text(_one(root, "name", path)),
        version=_text(_one(root, "version", path)),
        description="".join(description.itertext()).strip(),
        maintainers=_people(root, "maintainer", path, email_required=True),
        authors=_people(root, "author", path, email_required=False),
        licenses=tuple(_text(node) for node in root.findall("license")),
        depends={tag: tuple(_text(n) for n in root.findall(tag)) for tag in DEPEND_TAGS},
        metapackage=any(child.tag == "metapackage" for e in root.findall("export") for child in e),
    )


def read_manifest(directory: Path) -> Manifest:
    """The manifest of the package in ``directory``.

    Raises:
        ManifestError: it cannot be read or parsed.
    """
    path = directory / MANIFEST
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as error:
        raise ManifestError(f"The manifest cannot be read: {error}", path) from None
    return parse_manifest(text, path)


def check_manifest(manifest: Manifest) -> list[str]:
    """The manifest's warnings; `ManifestError` with every error when it has any."""
    errors, warnings = manifest.problems()
    if errors:
        raise ManifestError("\n".join(errors), manifest.path)
    return warnings


def package_in(directory: Path) -> str | None:
    """The name of the package whose folder ``directory`` is (its ``package.xml``), or None
    when it is no package's, or its manifest cannot be read (what rospack and roswtf take
    when run inside a package without naming one)."""
    try:
        return read_manifest(directory).name if (directory / "package.xml").is_file() else None
    except ManifestError:
        return None


__all__ = [
    "DEPEND_TAGS",
    "MANIFEST",
    "Manifest",
    "ManifestError",
    "Person",
    "check_manifest",
    "name_warning",
    "package_in",
    "parse_manifest",
    "read_manifest",
]
