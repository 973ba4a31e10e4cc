"""``catkin_python_setup()``: a package's own Python modules (``setup.py``) importable from the
devel and install spaces, its scripts runnable, as catkin makes them; ``setup.py`` read without
running it, and what rosx cannot work out named with its line."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from rosx.workspace.setup_py import NotUnderstood, PythonSetup, read_setup_py
from tests.support.cli import Result, clean_environ, rosx
from tests.support.ros1 import needs_ros1

#: A setup.py as the ROS wiki's "Installing Python scripts and modules" has it.
SETUP_PY = """\
## Run by catkin_make (catkin_python_setup), not by hand.
from setuptools import setup
from catkin_pkg.python_setup import generate_distutils_setup

# name and version come from package.xml
setup_args = generate_distutils_setup(
    packages=['my_pkg'],
    package_dir={'': 'src'},
    scripts=['scripts/greet'],
)

setup(**setup_args)
"""

GREET = """\
#!/usr/bin/env python3
from my_pkg import GREETING
from my_pkg.words import shout

print(shout(GREETING))
"""


def _workspace(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """``catkin_create_pkg my_pkg rospy`` with a Python package, a script and ``setup.py``,
    ``catkin_python_setup()`` uncommented as the tutorial says."""
    src = tmp_path / "ws" / "src"
    src.mkdir(parents=True)
    monkeypatch.chdir(src)
    made = rosx("catkin_create_pkg", "my_pkg", "rospy", environ=clean_environ(PWD=str(src)))
    assert made.status == 0, made.err
    package = src / "my_pkg"
    cmakelists = package / "CMakeLists.txt"
    text = cmakelists.read_text()
    assert "\n# catkin_python_setup()\n" in text
    cmakelists.write_text(text.replace("\n# catkin_python_setup()\n", "\ncatkin_python_setup()\n"))
    (package / "setup.py").write_text(SETUP_PY)
    (package / "src" / "my_pkg").mkdir(parents=True)
    (package / "src" / "my_pkg" / "__init__.py").write_text('GREETING = "hello from my_pkg"\n')
    (package / "src" / "my_pkg" / "words.py").write_text(
        "def shout(text):\n    return text.upper() + '!'\n"
    )
    (package / "scripts").mkdir()
    (package / "scripts" / "greet").write_text(GREET)
    (package / "scripts" / "greet").chmod(0o755)
    return tmp_path / "ws"


def catkin_make(ws: Path, monkeypatch: pytest.MonkeyPatch, *targets: str) -> Result:
    monkeypatch.chdir(ws)
    return rosx("catkin_make", *targets, environ=clean_environ(PWD=str(ws)))


def bash(script: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    """``script`` in a bash with no ROS environment and no PYTHONPATH, as a new terminal."""
    env = clean_environ(HOME=str(cwd))
    for name in ("PYTHONPATH", "CMAKE_PREFIX_PATH", "ROSLISP_PACKAGE_DIRECTORIES"):
        env.pop(name, None)
    return subprocess.run(
        ["bash", "-c", script], cwd=cwd, env=env, capture_output=True, text=True, timeout=120,
        check=False,
    )  # fmt: skip


def used(ws: Path, python: Path) -> tuple[list[str], list[str], str]:
    """In a shell that sourced ``devel/setup.bash`` (``python3`` from ``python``): the lines of
    the script from ``devel/bin``, of ``rosrun``, and of the import; those expected; stderr."""
    done = bash(
        f"PATH={python}:$PATH\n. devel/setup.bash\ngreet\nrosrun my_pkg greet\n"
        "python3 -c 'import my_pkg, my_pkg.words as w; print(my_pkg.__path__[-1], w.__file__)'\n",
        ws,
    )
    source = ws / "src" / "my_pkg" / "src" / "my_pkg"
    expected = ["HELLO FROM MY_PKG!", "HELLO FROM MY_PKG!", f"{source} {source}/words.py"]
    return done.stdout.splitlines(), expected, done.stderr


def made(ws: Path) -> list[str]:
    """What ``catkin_python_setup()`` made in the devel space."""
    devel = ws / "devel"
    site = devel / "lib" / "python3" / "dist-packages"
    relays = sorted(p.relative_to(devel).as_posix() for p in site.rglob("*"))
    return relays + (["bin/greet"] if os.access(devel / "bin" / "greet", os.X_OK) else [])


def test_the_packages_modules_are_importable_after_sourcing_devel(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    ws = _workspace(tmp_path, monkeypatch)
    built = catkin_make(ws, monkeypatch)
    assert (built.status, built.err) == (0, "")
    assert made(ws) == [
        "lib/python3/dist-packages/my_pkg",
        "lib/python3/dist-packages/my_pkg/__init__.py",
        "bin/greet",
    ]
    lines, expected, stderr = used(ws, Path(sys.executable).parent)  # python3: rosx's
    assert lines == expected, stderr
    source = ws / "src" / "my_pkg" / "src" / "my_pkg"
    # The devel space reads the source: an edit is there without building again.
    (source / "words.py").write_text("def shout(text):\n    return text + '?'\n")
    again = bash(". devel/setup.bash\ngreet\n", ws)
    assert again.stdout == "hello from my_pkg?\n", again.stderr


def test_catkin_make_install_copies_the_modules_and_the_scripts(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    ws = _workspace(tmp_path, monkeypatch)
    built = catkin_make(ws, monkeypatch, "install")
    assert built.status == 0, built.err
    install = ws / "install"
    assert built.out.splitlines()[-3:] == [
        f"-- Installing: {install}/lib/python3/dist-packages/my_pkg/__init__.py",
        f"-- Installing: {install}/lib/python3/dist-packages/my_pkg/words.py",
        f"-- Installing: {install}/bin/greet",
    ]
    script = (install / "bin" / "greet").read_text()
    assert script == GREET.replace("#!/usr/bin/env python3", f"#!{sys.executable}")
    shutil.rmtree(ws / "src")  # the install space stands alone
    used = bash(". install/setup.bash\ngreet\n", ws)
    assert used.stdout == "HELLO FROM MY_PKG!\n", used.stderr


@pytest.mark.parametrize(
    ("edit", "error"),
    [
        (
            lambda p: (p / "setup.py").unlink(),
            "CMake Error at my_pkg/CMakeLists.txt:{line} (catkin_python_setup):\n"
            "  catkin_python_setup() called without 'setup.py' in project folder ' {package}'\n",
        ),
        (
            lambda p: (p / "scripts" / "greet").unlink(),
            "CMake Error at my_pkg/CMakeLists.txt:{line} (catkin_python_setup):\n"
            "  The script 'greet' as listed in 'setup.py' of 'my_pkg' doesn't exist\n",
        ),
        (
            lambda p: (p / "setup.py").write_text(
                SETUP_PY.replace("package_dir={'': 'src'}", "package_dir={'my_pkg': 'src/other'}")
            ),
            "CMake Error at my_pkg/CMakeLists.txt:{line} (catkin_python_setup):\n"
            "  The package name 'my_pkg' differs from the basename of the path 'src/other' in "
            "project 'my_pkg'\n",
        ),
        (
            lambda p: (p / "CMakeLists.txt").write_text(
                (p / "CMakeLists.txt")
                .read_text()
                .replace("catkin_python_setup()", "generate_messages()\ncatkin_python_setup()")
            ),
            "CMake Error at my_pkg/CMakeLists.txt:{line} (catkin_python_setup):\n"
            "  generate_messages() must be called after catkin_python_setup() in project "
            "'my_pkg'\n",
        ),
    ],
    ids=["no setup.py", "no script", "folder named otherwise", "after generate_messages"],
)
def test_catkins_errors_in_catkins_words(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, edit: object, error: str
) -> None:
    ws = _workspace(tmp_path, monkeypatch)
    package = ws / "src" / "my_pkg"
    edit(package)  # type: ignore[operator]
    lines = (package / "CMakeLists.txt").read_text().splitlines()
    line = lines.index("catkin_python_setup()") + 1
    built = catkin_make(ws, monkeypatch)
    assert (built.status, built.err) == (1, error.format(package=package, line=line))
    assert not (ws / "devel").exists()


def test_a_setup_py_rosx_cannot_work_out_is_named_with_its_line(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    ws = _workspace(tmp_path, monkeypatch)
    setup_py = ws / "src" / "my_pkg" / "setup.py"
    setup_py.write_text(
        SETUP_PY.replace("packages=['my_pkg']", "packages=os.listdir('src')").replace(
            "scripts=['scripts/greet'],", "scripts=['scripts/greet'], zip_safe=False,"
        )
    )
    built = catkin_make(ws, monkeypatch)
    assert built.status == 0
    assert built.err == (
        "CMake Warning at my_pkg/setup.py:7 (catkin_python_setup):\n"
        "  rosx reads setup.py without running it and cannot work out `os.listdir('src')`: "
        "the package's Python modules and scripts are not set up\n"
    )
    assert not (ws / "devel" / "bin" / "greet").exists()
    setup_py.write_text(SETUP_PY.replace("scripts=['scripts/greet'],", "zip_safe=False,"))
    unsupported = catkin_make(ws, monkeypatch)
    assert unsupported.err == (
        "*** Arguments ['zip_safe'] to setup() not supported in catkin devel space in setup.py "
        "of my_pkg\n"
    )


def _packages_below(tree: dict[str, list[str]]) -> object:
    return lambda where: tree.get(where, [])


@pytest.mark.parametrize(
    ("source", "packages", "package_dir", "scripts", "modules"),
    [
        (SETUP_PY, ["my_pkg"], {"": "src"}, ["scripts/greet"], []),
        (
            "from distutils.core import setup\n"
            "from catkin_pkg.python_setup import generate_distutils_setup as generate\n"
            "setup(**generate(packages=['a', 'a.b'], package_dir={'': 'src'}, py_modules=['m']))\n",
            ["a", "a.b"], {"": "src"}, [], ["m"],
        ),
        (
            "import setuptools\n"
            "setuptools.setup(name='my_pkg', version='0.0.0',\n"
            "    packages=setuptools.find_packages('src', exclude=['*.tests']),\n"
            "    package_dir={'': 'src'}, install_requires=requirements())\n",
            ["my_pkg", "my_pkg.io"], {"": "src"}, [], [],
        ),
        (
            "from setuptools import setup\n"
            "from catkin_pkg.python_setup import generate_distutils_setup\n"
            "d = generate_distutils_setup()\n"
            "d['packages'] = ['one']\n"
            "d['packages'] += ['two']\n"
            "SCRIPTS = ['bin/a']\n"
            "setup(scripts=SCRIPTS + ['bin/b'], **d)\n",
            ["one", "two"], {}, ["bin/a", "bin/b"], [],
        ),
    ],
    ids=["tutorial", "setup(**generate(...))", "find_packages", "assignments"],
)  # fmt: skip
def test_setup_py_is_read_as_catkin_reads_it(
    source: str,
    packages: list[str],
    package_dir: dict[str, str],
    scripts: list[str],
    modules: list[str],
) -> None:
    below = _packages_below({"src": ["my_pkg", "my_pkg.io", "my_pkg.io.tests"]})
    read = read_setup_py(source, "my_pkg", "0.0.0", below)  # type: ignore[arg-type]
    assert isinstance(read, PythonSetup), read
    assert (read.packages, read.package_dir, read.scripts, read.modules, read.version) == (
        packages, package_dir, scripts, modules, "0.0.0",
    )  # fmt: skip


@pytest.mark.parametrize(
    ("source", "line", "text"),
    [
        ("from setuptools import setup\nsetup(packages=find())\n", 2, "find()"),
        ("import json\nfrom setuptools import setup\nsetup(**json.load(open('a')))\n", 3,
         "json.load(open('a'))"),
        ("from setuptools import setup\nfor name in []:\n    pass\nsetup(packages=[name])\n", 2,
         "for name in []: pass"),
        ("from setuptools import setup\nsetup(packages=[f'{1}'])\n", 2, "f'{1}'"),
        ("print('no call')\n", 1, "no setup() call at the top level"),
        ("setup(\n", 1, "invalid syntax: '(' was never closed"),
    ],
)  # fmt: skip
def test_what_needs_running_code_is_not_guessed(source: str, line: int, text: str) -> None:
    read = read_setup_py(source, "my_pkg", "0.0.0", _packages_below({}))  # type: ignore[arg-type]
    assert read == NotUnderstood(line, text)


@needs_ros1
def test_the_devel_space_is_catkins(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    if not all(shutil.which(tool, path="/usr/bin") for tool in ("catkin_make", "cmake", "make")):
        pytest.skip("ROS 1's catkin (Debian's catkin, cmake, make) is not installed")
    ours = _workspace(tmp_path / "rosx", monkeypatch)
    theirs = _workspace(tmp_path / "ros1", monkeypatch)
    assert catkin_make(ours, monkeypatch).status == 0
    done = subprocess.run(
        ["/usr/bin/catkin_make"], cwd=theirs, capture_output=True, text=True, timeout=600,
        env={"PATH": "/usr/bin:/bin", "HOME": str(tmp_path), "ROS_PACKAGE_PATH": "/usr/share"},
        check=False,
    )  # fmt: skip
    assert done.returncode == 0, done.stderr

    assert made(ours) == made(theirs)
    for ws in (ours, theirs):
        lines, expected, stderr = used(ws, Path("/usr/bin"))  # python3: ROS 1's
        assert lines == expected, (ws, stderr)
