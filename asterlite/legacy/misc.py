"""Small legacy forms of the front-end commands.

- ``LIRE_MAILLAGE()`` without FORMAT read an ASTER text mesh before
  code_aster 13 (the default is MED today): when the file on the unit is
  not a MED (HDF5) file, ``FORMAT='ASTER'`` is written out.
- ``DEBUT(CODE=_F(NOM=...))`` (test-case identification) is ``CODE='OUI'``.
"""

from __future__ import annotations

from asterlite.io.input_files import InputFileError, read_head
from asterlite.legacy import v15
from asterlite.legacy.base import NOT_LITERAL, Env, Translation, lit

HDF5_SIGNATURE = b"\x89HDF\r\n\x1a\n"
DEFAULT_MESH_UNIT = 20


def _is_text_mesh(path) -> bool:
    try:
        head = read_head(path, 8, "mesh")
    except (OSError, InputFileError):
        return False
    return head != HDF5_SIGNATURE


def is_legacy_lire_maillage(kwargs: dict, env: Env) -> bool:
    return _format_missing(kwargs, env) or any(v15.mesh_creations(kwargs, env))


def _format_missing(kwargs: dict, env: Env) -> bool:
    if "FORMAT" in kwargs or env.unit_path is None:
        return False
    unit = lit(kwargs.get("UNITE", DEFAULT_MESH_UNIT))
    if unit is NOT_LITERAL or not isinstance(unit, int):
        return False
    path = env.unit_path(unit)
    return path is not None and _is_text_mesh(path)


def translate_lire_maillage(kwargs: dict, env: Env) -> Translation:
    """FORMAT written out on a text mesh; the groups standing for the nodes and
    cells a legacy deck names created on the mesh read (a DEFI_GROUP after it)."""
    out = dict(kwargs)
    if _format_missing(kwargs, env):
        env.note(
            "LIRE_MAILLAGE without FORMAT on an ASTER text mesh (legacy default 'ASTER')",
            "LIRE_MAILLAGE(FORMAT='ASTER')",
        )
        out = {"FORMAT": "ASTER", **kwargs}
    groups = v15.mesh_groups_call(kwargs, env)
    return Translation("LIRE_MAILLAGE", out, env.notes, after=[groups] if groups else [])


def is_legacy_start(kwargs: dict, env: Env) -> bool:
    code = kwargs.get("CODE")
    return isinstance(code, dict) or (
        isinstance(code, (list, tuple)) and any(isinstance(c, dict) for c in code)
    )


def translate_start(kwargs: dict, env: Env) -> Translation:
    env.note(f"{env.command}(CODE=_F(NOM=...))", f"{env.command}(CODE='OUI')", None, "CODE")
    out = {k: ("OUI" if k == "CODE" else v) for k, v in kwargs.items()}
    return Translation(env.command, out, env.notes)
