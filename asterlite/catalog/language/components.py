"""Component names of code_aster's nodal displacement fields, to judge a
``NOM_CMP`` before anything is computed.

code_aster stores ``DEPL``, ``VITE`` and ``ACCE`` (and their ``_ABSOLU``
forms) of a mechanical result as the physical quantity ``DEPL_R``; a
component outside it stops the command (``RECU_FONCTION(NOM_CMP='DQ')``).
The names are those of ``list_cmp_depl`` in code_aster's
``catalo/cataelem/Commons/physical_quantities.py`` (17 at 764b3a6d, with the
few 15 had and 17 no longer has), written as code_aster writes them:
``PRE[2]`` stands for ``PRE1``, ``PRE2``.
"""

from __future__ import annotations

import re
from functools import cache

DISPLACEMENT_FIELDS = frozenset(
    {"DEPL", "VITE", "ACCE", "DEPL_ABSOLU", "VITE_ABSOLU", "ACCE_ABSOLU"}
)

DEPL_R = """
DX DY DZ DRX DRY DRZ GRX GLIS PRES PRE[2] TEMP PHI DH H1X H1Y H1Z H1PRE1 H2X H2Y H2Z
H2PRE1 H3X H3Y H3Z H3PRE1 H4X H4Y H4Z LAGR K1 K2 K3 PRE_FLU LAG_FLI LAG_FLS LAGS_C
LAGS_F[2] LAG2_C LAG2_F[2] LAG3_C LAG3_F[2] PR2_FLU LA2_FLI LA2_FLS D1X D1Y D1Z D2X D2Y
D2Z D3X D3Y D3Z PR3_FLU LA3_FLI LA3_FLS LAG4_C LAG4_F[2] UI2 VI2 WI2 UI3 VI3 WI3 UI4 VI4
WI4 UI5 VI5 WI5 UI6 VI6 WI6 UO2 VO2 WO2 UO3 VO3 WO3 UO4 VO4 WO4 UO5 VO5 WO5 UO6 VO6 WO6 WO
WI1 WO1 GONF EPXX EPYY EPZZ EPXY EPXZ EPYZ D1 D2 D3 VARI LAG_GV V1[3] V2[3] V3[3] PRES1[3]
PRES2[3] PRES3[3] SIGN SITX SITY LH1 SIXX SIYY SIZZ SIXY DAMG PTOT PIX PIY PIZ DRGX DRGY
DRGZ HHO_CX[35] HHO_CY[35] HHO_CZ[35] HHO_FX[15] HHO_FY[15] HHO_FZ[15] HHO_VR[10]
HHO_LG[10] PINCH PSI HHO[60] HHO_U[6] HHO_V[6] HHO_W[6]
"""


@cache
def displacement_components() -> frozenset[str]:
    """Every component name of DEPL_R, the ``NAME[n]`` forms expanded."""
    names: set[str] = set()
    for word in DEPL_R.split():
        found = re.fullmatch(r"(\w+)\[(\d+)\]", word)
        if found is None:
            names.add(word)
        else:
            names.update(f"{found[1]}{i}" for i in range(1, int(found[2]) + 1))
    return frozenset(names)
