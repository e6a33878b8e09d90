"""Package discovery for setuptools; every other setting is in pyproject.toml.

catalogues/, commands/ and samples/ sit at the top of the checkout but ship
as ``asterlite.catalogues``, ``asterlite.commands`` and ``asterlite.samples``.
pyproject.toml's ``packages.find`` cannot add that prefix, and a hand-written
package list silently misses new subpackages (it once left out
``asterlite.legacy``), so the list is found here by walking the folders:
every folder under asterlite/, catalogues/ and commands/ holding Python code
is a package, with or without an ``__init__.py``.
"""

import os
import re
from pathlib import Path

from setuptools import Extension, find_namespace_packages, setup
from setuptools.command.build_ext import build_ext
from setuptools.command.editable_wheel import editable_wheel

ROOT = Path(__file__).resolve().parent
# checkout folder -> the package it ships as
MAPPED = {"catalogues": "asterlite.catalogues", "commands": "asterlite.commands"}
DATA_ONLY = {"samples": "asterlite.samples"}  # its subfolders are data, not packages
SKIPPED = ["__pycache__", "*.__pycache__"]


def code_packages(folder: str, name: str) -> list[str]:
    found = find_namespace_packages(where=str(ROOT / folder), exclude=SKIPPED)
    return [name] + [f"{name}.{package}" for package in found]


def packages() -> list[str]:
    found = code_packages("asterlite", "asterlite")
    for folder, name in MAPPED.items():
        found += code_packages(folder, name)
    return found + list(DATA_ONLY.values())


def package_dir() -> dict[str, str]:
    return {name: folder for folder, name in {**MAPPED, **DATA_ONLY}.items()}


# --- editable installs (pip install -e .) ----------------------------------
# setuptools maps catalogues/ -> asterlite.catalogues with a meta-path finder
# that it appends to sys.meta_path, after the PathFinder. From the folder that
# holds the checkout (a `git clone` makes it `asterlite/`), the PathFinder sees
# that folder, a directory without __init__.py, as a namespace package named
# asterlite and returns it first: `import asterlite` gave an empty module and
# `python3 -m asterlite` failed. A second .pth file moves the finder in front
# of the PathFinder, so that asterlite is this checkout's package from any
# working directory, always under the same path (numba's kernel cache is
# keyed by the sources' paths); also before PYTHONPATH: in an environment
# holding an editable install, asterlite is that checkout (another checkout
# gets an environment of its own). It is written only when setuptools chose
# its finder (a layout it installs by a plain path entry needs nothing).
FINDER_FIRST = """\
import sys

import {finder} as _finder

_first = getattr(_finder, "_EditableFinder", None)
if _first is not None:
    _finder.install()
    sys.meta_path[:] = [_first] + [f for f in sys.meta_path if f is not _first]
"""


class EditableFirst:
    """setuptools' editable strategy, plus the module and .pth that put its
    finder first (see above)."""

    def __init__(self, strategy, name: str):
        self.strategy, self.name = strategy, name

    def __enter__(self):
        self.strategy.__enter__()
        return self

    def __exit__(self, *exc):
        return self.strategy.__exit__(*exc)

    def __call__(self, wheel, files, mapping):
        self.strategy(wheel, files, mapping)
        finder = self.strategy.template_vars()[0]
        module = "__editable___" + re.sub(r"\W", "_", self.name) + "_first"
        wheel.writestr(f"{module}.py", FINDER_FIRST.format(finder=finder))
        # .pth files are read in name order: this one after setuptools' own
        wheel.writestr(f"__editable__.{self.name}.zz-first.pth", f"import {module}\n")


class EditableWheel(editable_wheel):
    def _select_strategy(self, name, tag, build_lib):
        strategy = super()._select_strategy(name, tag, build_lib)
        if hasattr(strategy, "template_vars"):  # setuptools' meta-path finder
            return EditableFirst(strategy, name)
        return strategy


# --- compiled time loops (asterlite.dynamics.native) -------------------------
# C++ built here so that no run waits for numba's compiler on the loops it
# covers. Same operations in the same order as the numba kernels: no fused
# multiply-add (GCC contracts by default on targets that have it), no
# fast-math; errno left out of sqrt does not change a value; hidden symbols so
# that the headers' functions are called directly and inlined, not through the
# PLT (the module's PyInit stays exported). Optional: without a C++ compiler
# the install goes on and the numba kernels serve.
# One extension module per .cpp file of the folder (``loops.cpp`` ->
# ``asterlite.dynamics.native._loops``), each from the shared headers.
NATIVE = ROOT / "asterlite" / "dynamics" / "native"
HEADERS = sorted(str(p.relative_to(ROOT)) for p in NATIVE.glob("*.hpp"))
NATIVE_MODULES = [
    Extension(
        f"asterlite.dynamics.native._{source.stem}",
        sources=[str(source.relative_to(ROOT))],
        depends=HEADERS,
        language="c++",
        extra_compile_args=[
            "-std=c++17",
            "-O3",
            "-funroll-loops",
            "-ffp-contract=off",
            "-fno-math-errno",
            "-fvisibility=hidden",
        ],
        optional=True,
    )
    for source in sorted(NATIVE.glob("*.cpp"))
]


class BuildExtensions(build_ext):
    """setuptools' build_ext, one compiler process per core (the modules are
    independent; pip gives no option for it).

    An editable install builds in a new temporary folder each time, so
    build_ext's own up-to-date test never holds: a module already in the
    checkout that is newer than its .cpp, every header and this file is
    reused as it is (``pip install -e .`` again compiles only what changed)."""

    def finalize_options(self):
        super().finalize_options()
        if not self.parallel:
            self.parallel = os.cpu_count() or 1

    def build_extension(self, ext):
        in_checkout = ROOT / self.get_ext_filename(ext.name)
        if self.editable_mode and _newer_than_sources(in_checkout, ext):
            target = self.get_ext_fullpath(ext.name)
            self.mkpath(os.path.dirname(target))
            # the time kept: setuptools then finds the checkout's copy up to date
            self.copy_file(str(in_checkout), target, preserve_times=True)
            return
        super().build_extension(ext)


def _newer_than_sources(module: Path, ext: Extension) -> bool:
    if not module.is_file():
        return False
    sources = [ROOT / name for name in [*ext.sources, *ext.depends]] + [Path(__file__)]
    built = module.stat().st_mtime
    return all(source.stat().st_mtime < built for source in sources)


setup(
    packages=packages(),
    package_dir=package_dir(),
    ext_modules=NATIVE_MODULES,
    cmdclass={"editable_wheel": EditableWheel, "build_ext": BuildExtensions},
)
