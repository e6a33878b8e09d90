"""AGRAF files (IMPR_FONCTION FORMAT='AGRAF') as code_aster's TraceAgraf
writes them: ranges widened by its 5 % margin, per-rank default colours and
markers, a complex function as two ordinate columns."""

from __future__ import annotations

import numpy as np

from asterlite.io import agraf


def graph():
    x = np.array([5.0, 10.0, 15.0, 20.0])
    return agraf.AgrafGraph(
        curves=[
            agraf.AgrafCurve([x, np.array([1.0, 3.0, 2.0, 0.0])], legend="F1"),
            agraf.AgrafCurve([x, np.array([0.5, 1.0, 1.5, 2.0]), np.zeros(4)], colour=14),
        ]
    )


def test_directives_give_ranges_with_the_margin_and_the_curves():
    text = agraf.directives(graph())
    # x in [5, 20]: 2.5 % of 15 at each end; y in [0, 3]
    assert "Min X : 4.625\nMax X : 20.375\n" in text
    # (code_aster's arithmetic, printed as Python prints floats)
    assert f"Min Y : {0.0 - 0.05 * 3.0 / 2.0!r}\nMax Y : {3.0 + 0.05 * 3.0 / 2.0!r}\n" in text
    assert "Titre :\nFrequence Grille X :0\nFrequence Grille Y :0\n" in text
    courbes = text.split("  COURBE:\n")[1:]
    assert len(courbes) == 3  # one per ordinate column
    assert "Couleur :0\n" in courbes[0] and "Legende :F1\n" in courbes[0]
    # COULEUR=14 cycles over 0..12; the default marker is the curve's rank
    assert "Couleur :1\n" in courbes[1] and "Marqueur :1\n" in courbes[1]
    assert "Ordonnees : [ 2, 3]" in courbes[2]
    assert text.count("DEFAUT_COURBE:") == 12


def test_data_blocks_one_per_curve(tmp_path):
    agraf.append_graph(tmp_path / "fort.25", tmp_path / "fort.26", graph())
    agraf.append_graph(tmp_path / "fort.25", tmp_path / "fort.26", graph())
    data = (tmp_path / "fort.25").read_text()
    assert data.count("#NOM DE LA FONCTION: F1\n") == 2
    assert "#NOM DE LA FONCTION: COURBE_1\n" in data
    assert "  5.00000E+00  1.00000E+00\n" in data
    assert "  2.00000E+01  2.00000E+00  0.00000E+00\n" in data
    assert (tmp_path / "fort.26").read_text().count("\nGRAPHIQUE:\n") == 2
