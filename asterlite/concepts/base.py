"""Base class of every concept, and the placeholder used by ``asterlite check``."""

from __future__ import annotations

from typing import ClassVar

from asterlite.lang.values import DeckCallable, Unknown


class Concept:
    """A named result of a command, bound in the deck namespace.

    Subclasses set ``aster_types`` (code_aster type names, most specific
    first) and extend ``deck_methods`` with the methods a deck may call.
    """

    aster_types: ClassVar[tuple[str, ...]] = ()
    deck_methods: ClassVar[frozenset[str]] = frozenset({"getName"})

    name: str | None = None

    @property
    def aster_type(self) -> str:
        return self.aster_types[0] if self.aster_types else type(self).__name__

    def getName(self) -> str:  # noqa: N802 - code_aster's method name
        return self.name or ""

    def satisfies(self, type_name: str) -> bool:
        # "assd" is code_aster's name for any concept
        return type_name == "assd" or type_name in self.aster_types

    def __repr__(self) -> str:
        return f"<{type(self).__name__} {self.name or '?'}>"


# code_aster types that stand for a family: a concept of a member type also
# satisfies the family name (catalogues type some keywords by family).
RESULT_TYPES = (
    "mode_meca",
    "mode_meca_c",
    "mode_flamb",
    "mode_gene",
    "dyna_trans",
    "dyna_harmo",
    "evol_elas",
    "evol_noli",
    "mult_elas",
    "harm_gene",
    "acou_harmo",
    "mode_acou",
    "comb_fourier",
    "fourier_elas",
    "evol_ther",
    "mode_empi",
)
FAMILIES = {
    **{name: ("resultat_sdaster",) for name in RESULT_TYPES},
    "mode_meca_c": ("mode_meca", "resultat_sdaster"),
    "table_fonction": ("table_sdaster",),
    "table_container": ("table_sdaster",),
    "matr_asse_depl_r": ("matr_asse",),
    "matr_asse_depl_c": ("matr_asse",),
    "matr_asse_gene_r": ("matr_asse_gene",),
    "matr_asse_gene_c": ("matr_asse_gene",),
    "cham_no_sdaster": ("cham_gd_sdaster",),
    "cham_elem": ("cham_gd_sdaster",),
    "carte_sdaster": ("cham_gd_sdaster",),
}


class _UnknownMethod(DeckCallable):
    def deck_call(self, args, kwargs, site):
        return Unknown


def with_families(type_name: str) -> tuple[str, ...]:
    """A type name followed by the family names it belongs to."""
    return (type_name, *FAMILIES.get(type_name, ()))


class Placeholder(Concept, DeckCallable):
    """Stands for a concept that ``asterlite check`` does not compute.

    It carries the type the catalogue declares for the command's result so
    later calls can still be type-checked. Its methods, calling it (a
    formula) and indexing it (a table) give Unknown.
    """

    def deck_getattr(self, name: str):
        return _UnknownMethod()

    def deck_call(self, args, kwargs, site):
        return Unknown

    def __getitem__(self, key):
        # TAB["VALE_R", 1] on a table check mode did not compute
        return Unknown

    def __init__(self, aster_type: str, produced_by: str = ""):
        self.aster_types = with_families(aster_type)
        self.produced_by = produced_by


class AnyPlaceholder(Placeholder):
    """Stands for a concept of a type ``asterlite check`` cannot tell."""

    def __init__(self, produced_by: str = ""):
        super().__init__("*", produced_by)

    def satisfies(self, type_name: str) -> bool:
        return True
