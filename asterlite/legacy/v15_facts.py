"""What code_aster 15 and older had that today's code_aster has not, as
data: the keywords that named mesh nodes and cells (today's take groups),
keyword paths removed after 15, and the behaviours whose results changed
after 15. :mod:`asterlite.legacy.v15` translates with them and
:mod:`asterlite.legacy.version` detects a deck's version from them."""

from __future__ import annotations

NODE = {"NOEUD": "GROUP_NO"}
CELL = {"MAILLE": "GROUP_MA"}
NODE_CELL = {**NODE, **CELL}
# command -> factor keyword (None: the command's own level) -> {old keyword: group keyword}
ENTITY_KEYWORDS: dict[str, dict[str | None, dict[str, str]]] = {
    "AFFE_MODELE": {"AFFE": NODE_CELL},
    "AFFE_CARA_ELEM": {
        **{f: CELL for f in ("POUTRE", "BARRE", "COQUE", "CABLE", "MASSIF", "ORIENTATION")},
        **{f: NODE_CELL for f in ("DISCRET", "DISCRET_2D")},
    },
    "CALC_CHAR_SEISME": {None: NODE},
    "TEST_RESU": {
        "RESU": NODE_CELL,
        "CHAM_NO": NODE,
        "CHAM_ELEM": NODE_CELL,
        "CARTE": CELL,
    },
    "DYNA_LINE": {"EXCIT": NODE},
    "RECU_FONCTION": {None: CELL},
    "DYNA_VIBRA": {"EXCIT": NODE},
}
# (command, keyword path) of other forms only code_aster 15 and older had
REMOVED_AFTER_15 = (
    # test-case identification: code_aster 17 takes CODE='OUI' (and reads a mapping as it)
    ("DEBUT", "CODE", "NIV_PUB_WEB"),
    ("POURSUITE", "CODE", "NIV_PUB_WEB"),
    ("DYNA_VIBRA", "COMPORTEMENT", "FNOR_CRIT"),
    ("DYNA_VIBRA", "COMPORTEMENT", "FNOR_POST_FL"),
)

# Behaviours that changed results after code_aster 15, read from its sources
# (ehmoussi/code_aster, 2020) against today's (ZOHAIUB/code_aster): behaviour ->
# (first, last) version that computed it. The commands ask
# :func:`asterlite.legacy.v15.computes`.
OLD_BEHAVIOURS = {
    # CREA_MAILLAGE/LINE_QUAD (cmlqnd): the new mid-edge nodes were named PREF_NOEUD
    # followed by PREF_NUME, PREF_NUME + 1... (defaults 'NS' and 1) in the order they
    # were made; code_aster 17 gives every node its number only
    "LINE_QUAD_NODES_NAMED_BY_PREFIX": (0, 15),
    # DYNA_VIBRA GENE NEWMARK (intnewm, since 13.0): the right-hand side of the step
    # t_n -> t_n+1 took the forces of t_n, evaluated after the previous step's update;
    # code_aster 17 evaluates the external force at t_n+1
    "NEWMARK_FORCE_AT_STEP_START": (13, 15),
    # POST_GENE_PHYS (since 13.0): the static correction flag was read from the 7th
    # slot of the result's .DESC (dismdy) while DYNA_VIBRA set the 5th (mdrecf), so
    # DEPL/VITE/ACCE came without the correction of MODE_CORR; the correction vectors
    # existing (.IPSD) made the result count as multi-supported, so *_ABSOLU fields
    # had the correction added as the support motion
    "POST_GENE_PHYS_RELATIVE_WITHOUT_CORR_STAT": (13, 15),
    # TEST_RESU/GENE on a tran_gene (trgene, the same since 2005): NUME_ORDRE=n tested
    # the n-th archived instant (.DISC(n)); code_aster 17 looks the order number up
    "TEST_RESU_GENE_NUME_ORDRE_AS_POSITION": (0, 15),
    # POST_DYNA_MODA_T/CHOC OPTION='USURE' (statch): the window INST_INIT..INST_FIN
    # became archive indices by truncation, int((t - t0)/dt); code_aster 17's pochoc
    # keeps the instants from the first one at or after INST_INIT
    "POST_DYNA_MODA_T_WINDOW_BY_TRUNCATION": (0, 15),
    # DYNA_VIBRA DIS_CHOC with RIGI_TAN and no AMOR_TAN (dtmprep_noli_choc, 13.0 to 15):
    # the "optimal" AMOR_TAN from the mode of largest generalized mass, its AMOR_DIA
    # (2 xi omega) taken for xi, not floored at 0; code_aster 17 picks the mode by its
    # tangential motion at the contact, divides by 2 omega and floors at 0
    # (asterlite.dynamics.model.optimal_tangential_damping_v15)
    "AMOR_TAN_DEFAULT_MAX_MODAL_MASS": (13, 15),
    # DYNA_TRAN_MODAL/DYNA_VIBRA ADAPT_ORDRE2 (mdadap, until the dtm rewrite of 13.0):
    # growth after five calm steps, archiving at the nearest computed step on a
    # PAS_MAXI x PAS_ARCH grid (asterlite.dynamics.scheme_adapt_ordre2_v11)
    "ADAPT_ORDRE2_MDADAP": (0, 12),
}
