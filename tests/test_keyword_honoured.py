"""Keywords the keyword-use audit found accepted and ignored, now honoured as
code_aster honours them (each test fails on the behaviour before the audit)."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.function import Function
from asterlite.io.tables import xmgrace_lines
from asterlite.post.functions import cut
from asterlite.runtime.runner import run_deck

FORMULA_DECK = """\
DEBUT(CODE='OUI')
F = FORMULE(VALE='X - 2.0 * Y', NOM_PARA=('X', 'Y'))
TEST_FONCTION(VALEUR=_F(FONCTION=F, NOM_PARA=('Y', 'X'), VALE_PARA=(1.0, 5.0), VALE_CALC=3.0))
FIN()
"""


def test_test_fonction_orders_a_formula_point_by_nom_para(tmp_path):
    """NOM_PARA names the values of VALE_PARA for a FORMULE (code_aster's
    test_fonction_ops): Y=1, X=5 gives 3 (read in the formula's order: -9)."""
    deck = tmp_path / "formula.comm"
    deck.write_text(FORMULA_DECK)
    report = run_deck(deck, tmp_path / "out")
    assert report.status == "PASS", report.message


def test_cut_takes_an_abscissa_within_the_tolerance_as_the_bound():
    """INFO_FONCTION's window (code_aster's t_fonction.cut): a point within
    PRECISION of INST_FIN is the bound itself, not a point of its own."""
    func = Function([0.0, 0.5, 0.9995, 2.0], [0.0, 1.0, 2.0, 3.0])
    assert np.allclose(cut(func, 0.0, 1.0, 1.0e-3, "ABSOLU").abscissas, [0.0, 0.5, 1.0])
    assert np.allclose(cut(func, 0.0, 1.0, 1.0e-6, "ABSOLU").abscissas, [0.0, 0.5, 0.9995, 1.0])
    # RELATIF scales the tolerance by the bound
    assert np.allclose(cut(func, 0.0, 1.0, 1.0e-3, "RELATIF").abscissas, [0.0, 0.5, 1.0])


def test_grace_project_carries_the_curve_styles():
    """IMPR_FONCTION COURBE STYLE / COULEUR / MARQUEUR / FREQ_MARQUEUR go to
    the set's Grace attributes."""
    style = {"STYLE": 3, "COULEUR": 2, "MARQUEUR": 4, "FREQ_MARQUEUR": 5}
    lines = xmgrace_lines([(np.array([0.0, 1.0]), np.array([1.0, 2.0]), "c", style)])
    for expected in (
        "@s0 line linestyle 3",
        "@s0 line color 2",
        "@s0 symbol 4",
        "@s0 symbol skip 5",
    ):
        assert expected in lines
    plain = xmgrace_lines([(np.array([0.0, 1.0]), np.array([1.0, 2.0]), "c")])
    assert not [line for line in plain if "symbol" in line or "linestyle" in line]


def test_image_curves_follow_the_same_styles():
    from asterlite.post.plots import _curve_style

    options = _curve_style({"STYLE": 3, "COULEUR": 2, "MARQUEUR": 1, "FREQ_MARQUEUR": 10})
    assert options == {"linestyle": "--", "color": "red", "marker": "o", "markevery": 10}
    assert _curve_style({}) == {}


def test_grace_project_carries_the_graph_layout():
    """IMPR_FONCTION ECHELLE_X/Y, GRILLE_X/Y, BORNE_X/Y and SOUS_TITRE become
    Grace's axis scales, major ticks, world bounds and subtitle, as code_aster
    writes them (a logarithmic axis ticks by decades)."""
    layout = {
        "subtitle": "sub",
        "x_scale": "LIN",
        "x_grid": 0.5,
        "x_range": (0.0, 2.0),
        "y_scale": "LOG",
        "y_grid": None,
        "y_range": None,
    }
    lines = xmgrace_lines([(np.array([0.0, 1.0]), np.array([1.0, 2.0]), "c")], layout=layout)
    for expected in (
        '@subtitle "sub"',
        "@xaxis tick major 0.5",
        "@world xmin 0",
        "@world xmax 2",
        "@yaxes scale Logarithmic",
        "@yaxis tick major 10",
    ):
        assert expected in lines
    assert not [line for line in lines if "xaxes scale" in line or "world y" in line]


def test_image_curves_follow_the_graph_layout():
    pytest.importorskip("matplotlib")
    from asterlite.post.plots import curves_figure

    layout = {"x_scale": "LIN", "x_range": (0.0, 4.0), "y_scale": "LOG", "subtitle": "s"}
    figure = curves_figure(
        [(np.array([1.0, 2.0]), np.array([1.0, 100.0]), "c")], "t", layout=layout
    )
    axes = figure.axes[0]
    assert axes.get_yscale() == "log" and axes.get_xlim() == (0.0, 4.0)
    assert axes.get_title() == "t\ns"
