"""Package manifests under fuzz: ``package.xml`` read, checked and followed as rospack does.

Manifests made of package.xml's own tags (name, version, description, maintainer with and
without email, license, every kind of dependency, export), with random text and random bytes,
are parsed and checked as catkin checks them (`parse_manifest`, `check_manifest`): a manifest or
a `ManifestError` with catkin's report. Packages with such manifests, depending on each other in
cycles, are found and followed by the package index (``rospack find/depends/depends1/
depends-on1``): names or `ManifestError`, never another exception. XML entities that expand a
billionfold are refused within `MEMORY_BOUND`.
"""

from __future__ import annotations

import contextlib
import tempfile
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given
from hypothesis import strategies as st

from rosx.packages.index import PackageIndex, PackageNotFoundError
from rosx.packages.manifest import DEPEND_TAGS, ManifestError, check_manifest, parse_manifest
from tests.support.fuzz import MEMORY_BOUND, fuzz_settings, no_hang, peak_allocation

pytestmark = pytest.mark.fuzz

_PACKAGES = ("alpha", "beta", "gamma")
_TEXTS = st.one_of(
    st.sampled_from(
        [
            *["alpha", "beta", "gamma", "", " ", "1.0.0", "01.2.3", "1.0", "Bad Name", "a-b"],
            *["é", "me@example.com", "x@y", "a" * 70 + "@" + "b." * 40, "BSD", "<", "&amp;"],
            "&bad;",
        ]
    ),
    st.text(alphabet="abcxyz0129 .-_@&;<>/\"'=", max_size=16),
)
_TAGS = st.sampled_from(
    [
        *["name", "version", "description", "maintainer", "author", "license", "url", "export"],
        *DEPEND_TAGS,
        *["metapackage", "unknown"],
    ]
)


@st.composite
def manifests(draw: st.DrawFn) -> str:
    parts = []
    for _ in range(draw(st.integers(0, 10))):
        tag = draw(_TAGS)
        attributes = ""
        if tag in ("maintainer", "author") and draw(st.booleans()):
            attributes = f' email="{draw(_TEXTS)}"'
        inner = draw(_TEXTS)
        if tag == "export" and draw(st.booleans()):
            inner = "<metapackage/>"
        parts.append(f"<{tag}{attributes}>{inner}</{tag}>")
    root = draw(st.sampled_from(["package", "package", "package", "pkg"]))
    fmt = draw(st.sampled_from(["", ' format="2"', ' format="3"', ' format="x"', ' format="0"']))
    prolog = draw(st.sampled_from(["", '<?xml version="1.0"?>\n', "junk"]))
    ending = draw(st.sampled_from([f"</{root}>", "", f"</{root}><{root}/>"]))
    return f"{prolog}<{root}{fmt}>{''.join(parts)}{ending}"


texts = st.one_of(manifests(), st.text(max_size=200))


@fuzz_settings(250)
@given(text=texts)
def test_manifests_are_read_and_checked_or_refused(text: str) -> None:
    try:
        with no_hang():
            check_manifest(parse_manifest(text, Path("/src/p/package.xml")))
    except ManifestError as error:
        assert str(error).startswith("Error(s) in package '/src/p/package.xml':\n")


@pytest.fixture(scope="module")
def folder() -> Any:
    with tempfile.TemporaryDirectory() as name:
        yield Path(name)


@fuzz_settings(60)
@given(texts=st.lists(texts, min_size=len(_PACKAGES), max_size=len(_PACKAGES)))
def test_the_index_follows_any_manifests(folder: Path, texts: list[str]) -> None:
    with tempfile.TemporaryDirectory(dir=folder) as name:
        root = Path(name)
        for package, text in zip(_PACKAGES, texts, strict=True):
            (root / package).mkdir()
            (root / package / "package.xml").write_text(text)
        index = PackageIndex([root])
        with no_hang():
            for package in (*_PACKAGES, "nowhere"):
                with contextlib.suppress(PackageNotFoundError):
                    index.find(package)
                for query in (index.depends1, index.depends, index.depends_on1):
                    try:
                        assert all(isinstance(dep, str) for dep in query(package))
                    except ManifestError as error:
                        assert str(error)
                    except PackageNotFoundError:
                        pass


_BILLION_LAUGHS = (
    '<?xml version="1.0"?><!DOCTYPE package [<!ENTITY a "aaaaaaaaaa">'
    + "".join(f'<!ENTITY {chr(98 + i)} "{("&" + chr(97 + i) + ";") * 10}">' for i in range(9))
    + "]><package><name>&j;</name></package>"
)


def test_entities_that_expand_a_billionfold_are_refused() -> None:
    refused: list[ManifestError] = []

    def parse() -> None:
        try:
            parse_manifest(_BILLION_LAUGHS, Path("package.xml"))
        except ManifestError as error:
            refused.append(error)

    assert peak_allocation(parse) < MEMORY_BOUND
    assert len(refused) == 1
