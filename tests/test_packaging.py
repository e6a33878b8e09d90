"""The package as users get it: the wheel holds every module and data file of
the checkout, installs into a fresh virtual environment and runs the bundled
sample from outside the checkout; the README's commands are the ones CI runs."""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
import sysconfig
import tomllib
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
# checkout folder -> where it lands in the wheel
SHIPPED = {
    "asterlite": "asterlite",
    "catalogues": "asterlite/catalogues",
    "commands": "asterlite/commands",
    "samples": "asterlite/samples",
}
BUILD_INPUTS = ("pyproject.toml", "setup.py", "README.md")
# files a later engineer might add: the package-data patterns must cover them
PROBES = {"catalogues/probe_added.json": "{}", "catalogues/tables/probe.txt": "1 2\n"}


def shipped_files(root: Path) -> set[str]:
    """Every file of the checkout that belongs in the wheel, as a wheel path."""
    found = set()
    for folder, target in SHIPPED.items():
        for path in (root / folder).rglob("*"):
            if path.is_file() and "__pycache__" not in path.parts and path.suffix != ".pyc":
                found.add(f"{target}/{path.relative_to(root / folder).as_posix()}")
    return found


def copy_sources(target: Path) -> Path:
    """The checkout's package sources, without build leftovers, plus the probes."""
    ignore = shutil.ignore_patterns("__pycache__", "*.pyc", "*.egg-info", "build")
    for name in BUILD_INPUTS:
        shutil.copy2(ROOT / name, target / name)
    for folder in SHIPPED:
        shutil.copytree(ROOT / folder, target / folder, ignore=ignore)
    for name, text in PROBES.items():
        (target / name).parent.mkdir(parents=True, exist_ok=True)
        (target / name).write_text(text)
    return target


def can_build_without_isolation() -> bool:
    """setuptools >= 68 with a bdist_wheel (its own from 70.1, else the wheel package)."""
    try:
        import setuptools
    except ImportError:
        return False
    version = tuple(int(p) for p in re.findall(r"\d+", setuptools.__version__)[:2])
    if version < (68, 0):
        return False
    try:
        import wheel  # noqa: F401
    except ImportError:
        return version >= (70, 1)
    return True


def build_wheel(source: Path, dist: Path) -> Path:
    """``python -m build`` when installed, else pip wheel (without build isolation
    when the installed setuptools can, else with it: pip fetches setuptools)."""
    try:
        import build  # noqa: F401

        command = [sys.executable, "-m", "build", "--wheel", "--no-isolation", "-o", str(dist)]
        if not can_build_without_isolation():
            command.remove("--no-isolation")
    except ImportError:
        command = [sys.executable, "-m", "pip", "wheel", "--no-deps", "-w", str(dist)]
        if can_build_without_isolation():
            command.append("--no-build-isolation")
    done = subprocess.run(
        [*command, str(source)], cwd=source, capture_output=True, text=True, timeout=600
    )
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    (wheel,) = dist.glob("asterlite-*.whl")
    return wheel


def clean_environment(home: Path, venv: Path) -> dict[str, str]:
    """No PYTHONPATH, no user site, the venv first on PATH."""
    keep = {k: os.environ[k] for k in ("LANG", "LC_ALL", "TMPDIR") if k in os.environ}
    return {
        **keep,
        "HOME": str(home),
        "PATH": f"{venv / 'bin'}:/usr/local/bin:/usr/bin:/bin",
        "PYTHONNOUSERSITE": "1",
        "ASTERLITE_PROGRESS": "0",
    }


def make_venv(venv: Path) -> Path:
    """A virtual environment that sees this interpreter's packages (the
    dependencies) but not the checkout: --system-site-packages covers a system
    interpreter; inside a virtual environment its site-packages is added by a
    .pth line, which (unlike a site directory) runs none of its .pth files, so
    the editable install of the checkout stays out."""
    subprocess.run(
        [sys.executable, "-m", "venv", "--system-site-packages", str(venv)], check=True, timeout=300
    )
    python = venv / "bin" / "python"
    if sys.prefix != sys.base_prefix:
        site = subprocess.run(
            [str(python), "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"],
            capture_output=True, text=True, check=True,
        ).stdout.strip()  # fmt: skip
        ours = {sysconfig.get_paths()["purelib"], sysconfig.get_paths()["platlib"]}
        Path(site, "_asterlite_test_dependencies.pth").write_text("\n".join(sorted(ours)) + "\n")
    return python


@pytest.mark.slow
def test_wheel_holds_the_checkout_installs_and_runs_outside_it(tmp_path):
    (tmp_path / "source").mkdir()
    source = copy_sources(tmp_path / "source")
    wheel = build_wheel(source, tmp_path / "dist")
    names = set(zipfile.ZipFile(wheel).namelist())
    expected = shipped_files(source)
    assert expected >= shipped_files(ROOT)  # the copy holds the whole checkout
    missing = sorted(expected - names)
    assert not missing, f"not in the wheel: {missing[:20]}"
    assert not [n for n in names if "__pycache__" in n or n.endswith(".pyc")]
    assert not [n for n in names if n.split("/")[0] in ("catalogues", "commands", "samples")]

    venv, home = tmp_path / "venv", tmp_path / "home"
    home.mkdir()
    python = make_venv(venv)
    env = clean_environment(home, venv)

    def run(*command, timeout=900):
        return subprocess.run(
            [str(c) for c in command], cwd=home, env=env, capture_output=True, text=True,
            timeout=timeout, stdin=subprocess.DEVNULL,
        )  # fmt: skip

    done = run(python, "-m", "pip", "install", "--no-deps", "--no-index", wheel, timeout=300)
    assert done.returncode == 0, done.stderr[-3000:]
    imports = "import asterlite, asterlite.legacy, asterlite.dynamics.laws"
    where = run(python, "-c", f"{imports}; print(asterlite.__file__)")
    assert where.returncode == 0, where.stderr[-3000:]
    installed = Path(where.stdout.strip()).parent
    assert installed.is_relative_to(venv), f"asterlite imported from {installed}"

    asterlite = venv / "bin" / "asterlite"
    assert run(asterlite, "--version").stdout.strip().startswith("asterlite ")
    sample = installed / "samples" / "friction_oscillator"
    checked = run(asterlite, "check", sample / "friction_oscillator.comm")
    assert checked.returncode == 0, checked.stdout + checked.stderr
    ran = run(asterlite, "run", sample / "friction_oscillator.export", "-o", home / "out", "-q")
    assert ran.returncode == 0, ran.stdout[-3000:] + ran.stderr[-3000:]
    assert '"status": "PASS"' in (home / "out" / "summary.json").read_text()


# ------------------------------------------------------------------ fast checks


def readme_commands() -> list[str]:
    """The one-line commands of the README's first two bash blocks."""
    blocks = re.findall(r"```bash\n(.*?)\n```", (ROOT / "README.md").read_text(), re.S)
    return blocks[:2]


def test_readme_commands_use_a_virtual_environment():
    install, tests = readme_commands()
    for command in (install, tests):
        assert "\n" not in command
        assert command.startswith(
            "python3 -m venv .venv && . .venv/bin/activate && pip install -e "
        )
    sample = "samples/friction_oscillator/friction_oscillator.export"
    # every loop is compiled C++ by pip: the sample runs at once, nothing to warm up
    assert install.endswith(
        f"pip install -e . && asterlite run {sample} -o out/friction_oscillator"
    )
    # the tests compare the C++ loops with numba's results kept as fingerprints:
    # numba's loops are not compiled first
    assert tests.endswith('pip install -e ".[test]" && python3 -m pytest -q -n 2 --dist loadgroup')


def test_ci_runs_exactly_the_readme_test_command():
    script = (ROOT / ".ci" / "run").read_text()
    _, tests = readme_commands()
    assert f"README_TEST_COMMAND='{tests}'" in script
    assert 'eval "$README_TEST_COMMAND" || exit 1' in script


def test_slow_tests_are_not_deselected_by_default():
    """CI runs plain ``pytest -q``: nothing may drop the slow packaging test."""
    config = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["pytest"]["ini_options"]
    assert "not slow" not in config.get("addopts", "")
    command = [sys.executable, "-m", "pytest", "--collect-only", "-q", "-p", "no:cacheprovider"]
    done = subprocess.run(
        [*command, __file__], cwd=ROOT, capture_output=True, text=True, timeout=300
    )
    assert "test_wheel_holds_the_checkout_installs_and_runs_outside_it" in done.stdout
    assert not re.search(r"\d+ deselected", done.stdout), done.stdout[-500:]


def test_extras_split_the_heavy_dependencies():
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    core = " ".join(project["dependencies"])
    for heavy in ("dask", "distributed", "pyarrow", "matplotlib", "pandas", "xarray"):
        assert heavy not in core
    extras = project["optional-dependencies"]
    assert any("dask[distributed]" in d for d in extras["sweep"])
    assert any("pyarrow" in d for d in extras["sweep"])
    assert any("matplotlib" in d for d in extras["plot"])
    assert extras["test"][0] == "asterlite[all]" and "sweep" in extras["all"][0]
    assert (
        "packages" not in tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]
    )


def test_setup_finds_every_package_of_the_checkout(monkeypatch):
    import importlib.util

    import setuptools

    captured = {}
    monkeypatch.setattr(setuptools, "setup", lambda **kw: captured.update(kw))
    spec = importlib.util.spec_from_file_location("asterlite_setup", ROOT / "setup.py")
    spec.loader.exec_module(importlib.util.module_from_spec(spec))
    packages, package_dir = set(captured["packages"]), captured["package_dir"]
    for folder in ("catalogues", "commands", "samples"):
        name = f"asterlite.{folder}"
        assert package_dir[name] == folder and name in packages
    for init in (ROOT / "asterlite").rglob("__init__.py"):
        relative = init.parent.relative_to(ROOT).as_posix().replace("/", ".")
        assert relative in packages
    assert {
        "asterlite.legacy",
        "asterlite.dynamics.laws",
        "asterlite.dynamics.physical",
    } <= packages
