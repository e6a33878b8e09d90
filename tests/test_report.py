"""The run report: ``asterlite run --report`` and ``asterlite report OUTDIR``.

The page is checked as data (sections, self-containment, the folder's
bookkeeping) and as a picture: headless Chromium renders it, its DOM is
read back (``--dump-dom``) and a screenshot is taken, in which the checks
table (the green of an OK cell) and the plots (the blue of a curve) must
show. Without Chromium the rendering tests skip, except in CI (``CI=true``),
where .ci/run installs it and a missing browser is a failure.
"""

from __future__ import annotations

import json
import os
import shutil
import struct
import subprocess
import zlib
from pathlib import Path

import pytest

from asterlite.cli import main
from asterlite.runtime.runner import run_deck
from tests.conftest import SAMPLES

EXPORT = SAMPLES / "friction_oscillator" / "friction_oscillator.export"
CHROME_FLAGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--hide-scrollbars",
]


@pytest.fixture(scope="module")
def ran(tmp_path_factory):
    out = tmp_path_factory.mktemp("report") / "out"
    report = run_deck(EXPORT, out, report_page=True, save_results=True)
    assert report.status == "PASS", report.message
    return out


def test_run_writes_a_self_contained_page(ran):
    page = (ran / "report.html").read_text()
    summary = json.loads((ran / "summary.json").read_text())
    assert "report.html" in summary["output"]["files"]  # a file of the run: moved aside with it
    for section in ('id="checks-table"', 'id="timings-table"', 'id="shocks-table"', "<svg"):
        assert section in page
    assert "data:text/csv;charset=utf-8;base64," in page  # the figures' data
    lowered = page.lower()
    for external in ("<script", "<link", '<img src="http', 'src="http', 'href="http', "url(http"):
        assert external not in lowered
    assert "VALE_REFE" in page and "VALE_CALC" in page
    assert summary["verdicts"] == {
        "VALE_REFE": {"ok": 4, "total": 4},
        "VALE_CALC": {"ok": 4, "total": 4},
    }
    assert summary["supports"][0]["obstacle"] == "PLAN_Y"


def test_report_command_rewrites_the_page_from_the_folder(ran, tmp_path):
    copy = tmp_path / "copy"
    shutil.copytree(ran, copy)
    (copy / "report.html").unlink()
    assert main(["report", str(copy)]) == 0
    page = (copy / "report.html").read_text()
    assert 'id="checks-table"' in page and "orbit at FLOOR" in page
    (copy / "report.html").write_text("someone's notes")  # not asterlite's: never replaced
    assert main(["report", str(copy)]) == 2
    assert (copy / "report.html").read_text() == "someone's notes"
    assert main(["report", str(tmp_path)]) == 2  # no run there


def test_variant_note_is_on_the_page(tmp_path):
    out = tmp_path / "variant"
    report = run_deck(EXPORT, out, overrides={"MU": 0.1}, report_page=True)
    assert report.status == "NOOK"
    page = (out / "report.html").read_text()
    assert 'id="note"' in page and "MU = 0.15" in page and "VALE_CALC" in page


# ------------------------------------------------------------------ rendering


def chromium() -> str:
    for name in ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable"):
        found = shutil.which(name)
        if found:
            return found
    if os.environ.get("CI", "").lower() == "true":
        pytest.fail("CI: chromium is missing (.ci/run installs it)")
    pytest.skip("no chromium: the report's rendering is tested in CI")


def render(browser: str, page: Path, tmp_path: Path, *extra: str) -> subprocess.CompletedProcess:
    profile = tmp_path / f"profile-{len(list(tmp_path.iterdir()))}"
    profile.mkdir()
    command = [browser, *CHROME_FLAGS, f"--user-data-dir={profile}", *extra, page.as_uri()]
    return subprocess.run(command, capture_output=True, text=True, timeout=180)


def read_png(path: Path) -> tuple[int, int, list[bytes]]:
    """(width, height, rows of RGB(A) bytes) of an 8-bit non-interlaced PNG."""
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    position, chunks = 8, {}
    idat = b""
    while position < len(data):
        length, kind = struct.unpack(">I4s", data[position : position + 8])
        body = data[position + 8 : position + 8 + length]
        if kind == b"IDAT":
            idat += body
        else:
            chunks[kind] = body
        position += 12 + length
    width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", chunks[b"IHDR"])
    assert depth == 8 and colour in (2, 6) and interlace == 0
    size = 3 if colour == 2 else 4
    raw = zlib.decompress(idat)
    stride = width * size
    rows, previous = [], bytearray(stride)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1 : (y + 1) * (stride + 1)])
        for x in range(stride):
            left = line[x - size] if x >= size else 0
            up = previous[x]
            corner = previous[x - size] if x >= size else 0
            if kind == 1:
                line[x] = (line[x] + left) & 0xFF
            elif kind == 2:
                line[x] = (line[x] + up) & 0xFF
            elif kind == 3:
                line[x] = (line[x] + (left + up) // 2) & 0xFF
            elif kind == 4:
                p = left + up - corner
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - corner)
                best = left if pa <= pb and pa <= pc else (up if pb <= pc else corner)
                line[x] = (line[x] + best) & 0xFF
        rows.append(bytes(line))
        previous = line
    return width, height, [bytes(r[i : i + 3]) for r in rows for i in range(0, stride, size)]


def count_near(pixels: list[bytes], colour: tuple[int, int, int], tolerance: int = 12) -> int:
    return sum(1 for p in pixels if all(abs(p[i] - colour[i]) <= tolerance for i in range(3)))


def count_drawn(pixels: list[bytes], colour: tuple[int, int, int]) -> int:
    """Pixels of a line of ``colour`` drawn on white, antialiased: each a
    blend white·(1-a) + colour·a with the same a on every channel (a > 0.3)."""
    count = 0
    for p in pixels:
        weights = [(255 - p[i]) / (255 - colour[i]) for i in range(3)]
        if min(weights) > 0.3 and max(weights) - min(weights) < 0.08 and max(weights) <= 1.05:
            count += 1
    return count


def test_page_renders_in_chromium(ran, tmp_path):
    browser = chromium()
    page = ran / "report.html"
    dom = render(browser, page, tmp_path, "--dump-dom")
    assert dom.returncode == 0, dom.stderr[-2000:]
    text = dom.stdout
    assert 'id="checks-table"' in text and text.count("TEST_RESU") >= 4
    assert "<polyline" in text and "orbit at FLOOR" in text
    shot = tmp_path / "report.png"
    made = render(browser, page, tmp_path, "--window-size=1280,2200", f"--screenshot={shot}")
    assert made.returncode == 0 and shot.is_file(), made.stderr[-2000:]
    width, height, pixels = read_png(shot)
    assert (width, height) == (1280, 2200)
    assert count_near(pixels, (0xDA, 0xFB, 0xE1)) > 500  # the OK cells of the checks table
    assert count_drawn(pixels, (0x1F, 0x77, 0xB4)) > 300  # a curve drawn in a plot
    background = pixels[0]
    assert sum(1 for p in pixels if p != background) > 0.05 * len(pixels)


# ------------------------------------------------------------------ curves


def test_curve_sets_of_functions_harmonic_results_and_any_concept():
    import numpy as np

    from asterlite.concepts.base import Concept
    from asterlite.concepts.function import ComplexFunction, Function
    from asterlite.concepts.harmonic import HarmGene
    from asterlite.report.data import ReportData, collect_curves, curves_json
    from asterlite.report.page import curves_section

    frequencies = np.linspace(1.0, 100.0, 400)
    response = 1.0 / (30.0**2 - frequencies**2 + 2j * 0.002 * 30.0 * frequencies)

    class Offered(Concept):  # the generic input: a concept's report_curves()
        aster_types = ("something",)

        def report_curves(self):
            return [{"title": "offered", "x_label": "s", "y_label": "m",
                     "series": [{"label": "a", "x": [0, 1, 2], "y": [1, 4, 9]}]}]  # fmt: skip

    namespace = {
        "F": Function(np.linspace(0, 1, 5), np.arange(5.0), NOM_PARA="INST", NOM_RESU="DX"),
        "H": ComplexFunction(frequencies, response, NOM_PARA="FREQ", NOM_RESU="DY"),
        "Q": HarmGene(None, None, frequencies, np.arange(1, 401),
                      {"DEPL": np.column_stack([response, 0.1 * response])}),
        "O": Offered(),
        "X": 3.0,
    }  # fmt: skip
    sets = collect_curves(namespace)
    titles = [s.get("source", s["title"]) for s in sets]
    assert titles == ["F", "H", "Q", "offered"]
    assert sets[1]["y_label"] == "|DY|" and sets[1]["log_y"]  # a complex function: its modulus
    np.testing.assert_allclose(sets[1]["series"][0]["y"], np.abs(response))
    assert [s["label"] for s in sets[2]["series"]] == ["q1", "q2"]  # largest peak first
    assert sets[2]["x_label"] == "FREQ (Hz)"
    stored = json.loads(curves_json(sets))["curves"]  # what curves.json keeps
    assert stored[2]["series"][0]["x"][0] == 1.0
    html = curves_section(ReportData({}, curves=stored))
    assert html.count("<svg") == 4 and "offered" in html


def test_energy_balance_and_deck_functions_are_drawn(tmp_path):
    from tests.test_extremes_decks import Chain, Shock, write

    chain = Chain(
        depl={1: (0.0, 1.0e-3, 0.0)},
        shocks=[Shock(1, 5.0e-4, 1.0e6, c_n=5.0)],
        pas=1.0e-5,
        inst_fin=0.1,
        pas_arch=10,
        dyna_keywords=", ENERGIE=_F()",
    )
    out = tmp_path / "out"
    report = run_deck(write(chain, tmp_path / "deck"), out, report_page=True, save_results=True)
    assert report.status == "DONE", report.message
    page = (out / "report.html").read_text()
    assert 'id="energy"' in page and "ENER_CIN" in page and "RESIDU" in page
    assert 'id="curves"' in page and "function FN0" in page  # RECU_FONCTION's FN
    assert json.loads((out / "curves.json").read_text())["curves"][0]["source"] == "FN0"
    assert main(["report", str(out)]) == 0  # from the folder: the same sections
    again = (out / "report.html").read_text()
    assert 'id="energy"' in again and "function FN0" in again
