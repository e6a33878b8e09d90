"""asterlite's version, in a module of its own: the package's other modules
and the build (pyproject.toml) read it without importing the package's
public API."""

__version__ = "0.1.0"
