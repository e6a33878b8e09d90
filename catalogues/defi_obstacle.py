"""DEFI_OBSTACLE: the shape of the obstacle a DIS_CHOC nonlinearity strikes.

``CERCLE``, ``PLAN_Y`` and ``PLAN_Z`` need no values (a circle of radius
``JEU`` or two planes at ``+/-JEU``); ``DISCRET`` is a polygon given in
polar coordinates (angle in degrees, radius) by ``VALE``; ``BI_*`` shapes
move with both nodes of a node-to-node shock. The result is a
``table_fonction`` as in code_aster.
"""

from asterlite.catalog import OPER, SIMP

DEFI_OBSTACLE = OPER(
    nom="DEFI_OBSTACLE",
    sd_prod="table_fonction",
    reentrant="n",
    fr="Define the shape of a shock obstacle",
    TYPE=SIMP(
        statut="f",
        typ="TXM",
        defaut="CERCLE",
        into=(
            "CERCLE",
            "PLAN_Y",
            "PLAN_Z",
            "DISCRET",
            "BI_CERCLE",
            "BI_PLAN_Y",
            "BI_PLAN_Z",
            "BI_CERC_INT",
        ),
    ),
    VALE=SIMP(statut="f", typ="R", max="**", fr="Polar facets: (angle in degrees, radius) pairs"),
    VERIF=SIMP(statut="f", typ="TXM", defaut="FERME"),
)
