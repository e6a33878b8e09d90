"""Package discovery for setuptools; every other setting is in pyproject.toml.

catalogues/, commands/ and samples/ sit at the top of the checkout but ship
as ``asterlite.catalogues``, ``asterlite.commands`` and ``asterlite.samples``.
pyproject.toml's ``packages.find`` cannot add that prefix, and a hand-written
package list silently misses new subpackages (it once left out
``asterlite.legacy``), so the list is found here by walking the folders:
every folder under asterlite/, catalogues/ and commands/ holding Python code
is a package, with or without an ``__init__.py``.
"""

from pathlib import Path

from setuptools import find_namespace_packages, setup

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


setup(packages=packages(), package_dir=package_dir())
