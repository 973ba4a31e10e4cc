"""Every module of roslaunch's plan is under the import contracts that keep it free of I/O.

`rosx.launch.run` runs a plan; everything else in `rosx.launch` is the plan, listed by name in
pyproject.toml's two "roslaunch's plan" contracts. A new plan module must be added there.
"""

from __future__ import annotations

from pathlib import Path

import pytest

tomllib = pytest.importorskip("tomllib", reason="Python 3.11's TOML reader")
ROOT = Path(__file__).resolve().parents[2]


def _plan_modules() -> set[str]:
    launch = ROOT / "rosx" / "launch"
    found = set()
    for path in launch.iterdir():
        if path.name in ("run", "__init__.py", "__pycache__"):
            continue
        if path.suffix == ".py" or (path / "__init__.py").is_file():
            found.add(f"rosx.launch.{path.stem}")
    return found


def test_the_contracts_name_every_module_of_the_plan() -> None:
    config = tomllib.loads((ROOT / "pyproject.toml").read_text())
    contracts = config["tool"]["importlinter"]["contracts"]
    plan = [c for c in contracts if c["name"].startswith("roslaunch's plan")]
    assert len(plan) == 2
    for contract in plan:
        assert set(contract["source_modules"]) == _plan_modules(), contract["name"]
