"""Plots of a saved transient result: the friction_oscillator sample is run
once, saved to HDF5 and read back; each kind of figure is checked through
the matplotlib Figure it returns (labels, plotted data) and the file written."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
import pytest

from asterlite.cli import main
from asterlite.io.export import describe_run
from asterlite.io.result_store import load_tran_gene, save_tran_gene
from asterlite.post import plots
from asterlite.runtime.session import Session

SAMPLE = Path(__file__).resolve().parent.parent / "samples" / "friction_oscillator"
U0, JEU, FN = 3.0e-3, 0.9, 2.0 * 9.81  # the sample's release, gap and weight


@pytest.fixture(scope="module")
def store(tmp_path_factory) -> Path:
    folder = tmp_path_factory.mktemp("plots")
    session = Session(describe_run(SAMPLE / "friction_oscillator.export"), output_dir=folder)
    session.run_all()
    return save_tran_gene(folder / "friction.h5", session.namespace["RESUGENE"])


@pytest.fixture(scope="module")
def tran(store):
    return load_tran_gene(store)


def line_data(figure, index: int = 0) -> tuple[np.ndarray, np.ndarray]:
    line = figure.axes[0].lines[index]
    return np.asarray(line.get_xdata(), float), np.asarray(line.get_ydata(), float)


def assert_labelled(figure) -> None:
    axes = figure.axes[0]
    assert axes.get_xlabel() and axes.get_ylabel() and axes.get_title()


# ------------------------------------------------------------------ figures


def test_node_history_is_restituted_from_the_modal_basis(tran):
    figure = plots.node_history_figure(tran, "N1", "DX")
    assert_labelled(figure)
    assert "DX" in figure.axes[0].get_ylabel() and "time" in figure.axes[0].get_xlabel()
    times, values = line_data(figure)
    np.testing.assert_allclose(times, tran.times)
    np.testing.assert_allclose(values, tran.depl @ tran.basis.shapes[0])
    assert values[0] == pytest.approx(U0)
    # the first friction half swing: U0 - 2 C at pi / W0
    half_period = np.pi / np.sqrt(8000.0 / 2.0)
    assert np.interp(half_period, times, values) == pytest.approx(-2.26425e-3, rel=2e-3)


def test_node_history_of_the_velocity_field(tran):
    _, values = line_data(plots.node_history_figure(tran, "N1", "DX", field="VITE"))
    np.testing.assert_allclose(values, tran.vite @ tran.basis.shapes[0])


def test_impact_force_history(tran):
    figure = plots.shock_history_figure(tran, "FLOOR", "FN")
    assert_labelled(figure)
    assert "(N)" in figure.axes[0].get_ylabel()
    times, values = line_data(figure)
    np.testing.assert_allclose(times, tran.times)
    np.testing.assert_allclose(values, FN, rtol=1e-9)  # pressed by its weight throughout


def test_any_shock_quantity(tran):
    _, values = line_data(plots.shock_history_figure(tran, "FLOOR", "VT1"))
    np.testing.assert_array_equal(values, tran.shocks[0].fields["VT1"])


def test_orbit_in_the_plane_of_a_plan_y_obstacle(tran):
    figure = plots.orbit_figure(tran, "FLOOR")
    assert_labelled(figure)
    axes = figure.axes[0]
    assert "local y" in axes.get_xlabel() and "local z" in axes.get_ylabel()
    y, z = line_data(figure)
    shock = tran.shocks[0]
    np.testing.assert_array_equal(y, shock.fields["DYLOC"])
    np.testing.assert_array_equal(z, shock.fields["DZLOC"])
    walls = sorted(line.get_xdata()[0] for line in axes.lines[1:])
    assert walls == pytest.approx([-JEU, JEU])
    assert any(text.get_text() == "JEU = 0.9" for text in axes.texts)


def with_obstacle(tran, name: str, **parameters):
    """The sample's result with one more shock: the same history, another obstacle."""
    shock = dataclasses.replace(
        tran.shocks[0], name=name, parameters={**tran.shocks[0].parameters, **parameters}
    )
    return dataclasses.replace(tran, shocks=[*tran.shocks, shock])


def test_orbit_of_a_circular_obstacle_draws_the_circle_of_radius_jeu(tran):
    ring = with_obstacle(tran, "RING", OBSTACLE="CERCLE", JEU=0.5)
    figure = plots.orbit_figure(ring, "RING")
    y, z = line_data(figure, 1)
    np.testing.assert_allclose(np.hypot(y, z), 0.5)
    assert figure.axes[0].get_aspect() == 1.0


def test_orbit_of_a_discrete_obstacle_draws_its_polygon(tran):
    polar = [[0.0, 1.0], [90.0, 2.0], [180.0, 1.0], [270.0, 2.0]]
    square = with_obstacle(tran, "SQUARE", OBSTACLE="DISCRET")
    figure = plots.orbit_figure(square, "SQUARE", polar=polar)
    y, z = line_data(figure, 1)
    np.testing.assert_allclose(y, [1.0, 0.0, -1.0, 0.0, 1.0], atol=1e-12)
    np.testing.assert_allclose(z, [0.0, 2.0, 0.0, -2.0, 0.0], atol=1e-12)
    assert any(text.get_text() == "r_min = 1" for text in figure.axes[0].texts)


@pytest.mark.parametrize(
    "parameters, vertical, horizontal, radius",
    [
        ({"OBSTACLE": "PLAN_Z", "JEU": 0.2}, [], [-0.2, 0.2], None),
        ({"OBSTACLE": "BI_PLAN_Y", "DIST_1": 0.1, "DIST_2": 0.2}, [-0.3, 0.3], [], None),
        ({"OBSTACLE": "BI_CERCLE", "DIST_1": 0.1, "DIST_2": 0.2}, [], [], 0.3),
        ({"OBSTACLE": "BI_CERC_INT", "DIST_1": 0.1, "DIST_2": 0.5}, [], [], 0.4),
    ],
)
def test_obstacle_outlines(parameters, vertical, horizontal, radius):
    outline = plots.obstacle_outline(parameters)
    assert outline.vertical == pytest.approx(vertical)
    assert outline.horizontal == pytest.approx(horizontal)
    if radius is not None:
        (y, z), *_ = outline.curves
        np.testing.assert_allclose(np.hypot(y, z), radius)
    assert outline.gap_label


def test_two_node_orbits_are_relative(tran):
    pair = with_obstacle(tran, "PAIR", OBSTACLE="BI_CERCLE", DIST_1=0.1, DIST_2=0.2)
    figure = plots.orbit_figure(pair, "PAIR")
    y, _ = line_data(figure)
    np.testing.assert_array_equal(y, pair.shocks[-1].fields["DYREL"])
    assert "node 1 - node 2" in figure.axes[0].get_xlabel()


def test_wear_work_rate_per_support(tran):
    two = with_obstacle(tran, "COPY", OBSTACLE="PLAN_Y")
    figure = plots.wear_figure(two)
    assert_labelled(figure)
    bars = figure.axes[0].patches
    assert len(bars) == 2
    shock = tran.shocks[0].fields
    # FN is constant: the rate is FN times the time-averaged sliding speed, over
    # the intervals that start sliding (code_aster's PUIS_USURE)
    speed = np.abs(np.hypot(shock["VT1"], shock["VT2"]))
    sliding = np.asarray(shock["ADHERENCE"])[:-1] == 0
    assert sliding.any() and not sliding.all()  # the stick flag matters here
    pieces = (speed[1:] + speed[:-1]) * np.diff(tran.times)
    integral = np.sum(pieces[sliding]) / 2.0  # trapezoid rule
    expected = FN * integral / (tran.times[-1] - tran.times[0])
    assert [bar.get_height() for bar in bars] == pytest.approx([expected, expected], rel=1e-9)
    labels = [tick.get_text() for tick in figure.axes[0].get_xticklabels()]
    assert labels == ["FLOOR", "COPY"]


def test_figures_save_as_png_and_svg(tran, tmp_path):
    figure = plots.shock_history_figure(tran, "FLOOR")
    png = plots.save_figure(figure, tmp_path / "fn.png")
    svg = plots.save_figure(figure, tmp_path / "fn.svg")
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert "<svg" in svg.read_text()
    with pytest.raises(plots.PlotError, match="png or .svg"):
        plots.save_figure(figure, tmp_path / "fn.pdf")


@pytest.mark.parametrize(
    "call, message",
    [
        (lambda t: plots.node_history_figure(t, "N9", "DX"), "no node 'N9'"),
        (lambda t: plots.node_history_figure(t, "N1", "DRX"), "components: DX, DY, DZ"),
        (lambda t: plots.shock_history_figure(t, "WALL"), "shocks: FLOOR"),
        (lambda t: plots.shock_history_figure(t, "FLOOR", "FX"), "has no 'FX'"),
    ],
)
def test_unknown_names_are_clear_errors(tran, call, message):
    with pytest.raises(plots.PlotError, match=message):
        call(tran)


# -------------------------------------------------------------------- CLI


@pytest.mark.parametrize(
    "arguments, image",
    [
        (["--node", "N1", "--cmp", "DX"], "node.png"),
        (["--shock", "FLOOR", "--quantity", "FN"], "fn.svg"),
        (["--shock", "FLOOR", "--quantity", "orbit"], "orbit.png"),
        (["--quantity", "wear"], "wear.svg"),
    ],
)
def test_cli_plot_writes_the_image(store, tmp_path, arguments, image, capsys):
    target = tmp_path / image
    assert main(["plot", str(store), *arguments, "-o", str(target)]) == 0
    assert target.stat().st_size > 1000
    assert str(target) in capsys.readouterr().out


def test_cli_default_image_name_is_beside_the_store(store):
    assert main(["plot", str(store), "--shock", "FLOOR"]) == 0
    assert (store.parent / "friction_RESUGENE_FLOOR_FN.png").is_file()


@pytest.mark.parametrize(
    "arguments, message",
    [
        (["--shock", "WALL"], "no shock 'WALL'"),
        ([], "choose --node"),
        (["--name", "OTHER", "--shock", "FLOOR"], "no tran_gene named 'OTHER'"),
    ],
)
def test_cli_plot_errors_exit_2(store, arguments, message, capsys):
    assert main(["plot", str(store), *arguments]) == 2
    assert message in capsys.readouterr().err
