"""The README's Python API example, run as a newcomer runs it.

``git clone`` names the checkout ``asterlite``; from the folder holding it,
``import asterlite`` found that folder first (a directory without
``__init__.py``: a namespace package) instead of the editable install, whose
finder setuptools appends after the PathFinder: ``asterlite.run`` was an
AttributeError and ``python3 -m asterlite`` failed. setup.py now puts the
finder first. This test makes that layout (a checkout named ``asterlite``,
here a link to this one), installs it with ``pip install -e`` into a fresh
virtual environment, and runs the README's snippet from the parent folder.

It also checks what the snippet shows: a variant of the sample is NOOK
against the deck's VALE_CALC values (its results for MU = 0.15) while every
VALE_REFE check holds, and the run says so.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
import sysconfig
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent


def readme_snippet() -> str:
    text = (ROOT / "README.md").read_text()
    section = text[text.index("## Python API") :]
    return re.search(r"```python\n(.*?)```", section, re.S).group(1)


def clean_env() -> dict:
    env = {k: v for k, v in os.environ.items() if not k.startswith(("PYTHON", "VIRTUAL_ENV"))}
    env["ASTERLITE_PROGRESS"] = "0"
    return env


@pytest.fixture(scope="module")
def installed(tmp_path_factory):
    """(parent folder holding the checkout `asterlite`, the venv's python)."""
    base = tmp_path_factory.mktemp("newcomer")
    parent = base / "work"
    parent.mkdir()
    (parent / "asterlite").symlink_to(ROOT, target_is_directory=True)
    venv = base / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--without-pip", str(venv)], check=True)
    python = venv / "bin" / "python"
    purelib = subprocess.run(
        [str(python), "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"],
        capture_output=True,
        text=True,
        check=True,
    ).stdout.strip()
    # the dependencies (numpy, numba...) from this environment: a path entry, whose
    # .pth files (this checkout's own editable install) are not read
    Path(purelib, "asterlite_test_dependencies.pth").write_text(
        sysconfig.get_paths()["purelib"] + "\n"
    )
    command = [sys.executable, "-m", "pip", "--python", str(python), "install", "-q"]
    command += ["--no-deps", "-e", str(parent / "asterlite")]
    done = subprocess.run(command, capture_output=True, text=True, env=clean_env(), cwd=parent)
    if done.returncode != 0:
        if os.environ.get("CI", "").lower() == "true":
            pytest.fail(f"pip install -e failed:\n{done.stdout}\n{done.stderr}")
        pytest.skip(f"pip install -e failed (no package index?): {done.stderr[-500:]}")
    return parent, python


def run_in(folder: Path, python: Path, *args: str) -> subprocess.CompletedProcess:
    return subprocess.run(
        [str(python), *args], capture_output=True, text=True, cwd=folder, env=clean_env(),
        timeout=600,
    )  # fmt: skip


def test_import_from_the_folder_holding_the_clone(installed):
    parent, python = installed
    done = run_in(parent, python, "-c", "import asterlite; print(asterlite.__file__)")
    assert done.returncode == 0, done.stderr
    assert Path(done.stdout.strip()) == ROOT / "asterlite" / "__init__.py"
    done = run_in(parent, python, "-m", "asterlite", "--version")
    assert done.returncode == 0 and done.stdout.startswith("asterlite "), done.stderr


def test_readme_api_example_from_the_folder_holding_the_clone(installed):
    parent, python = installed
    done = run_in(parent, python, "-c", readme_snippet())
    assert done.returncode == 0, done.stderr[-3000:]
    assert "NOOK {'VALE_REFE': '4/4', 'VALE_CALC': '0/4'}" in done.stdout
    assert "instead of MU = 0.15 (friction_oscillator.comm:15)" in done.stdout
    assert "every VALE_REFE (independent reference) check holds" in done.stdout
