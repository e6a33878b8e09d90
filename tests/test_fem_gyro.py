"""Rotor matrices: MECA_GYRO / RIGI_GYRO of beams and disks (analytic
Campbell diagram of an overhung disk) and RIGI_MECA_HYST (K (1 + i eta))."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as sla

from asterlite.concepts.assembly import ComplexAssembledMatrix, ComplexElementaryMatrices
from asterlite.concepts.mesh import Mesh
from asterlite.fem import gyro
from tests.test_fem_support import CO, FakeSession, chain_mesh, run

E, NU, RHO = 2.0e11, 0.3, 7800.0


def test_beam_gyro_matches_closed_form():
    """S - S^T from the Timoshenko rotation shapes equals the closed-form
    gyroscopic matrix of the literature (Nelson 1980) with code_aster's phi."""
    L, A, iy, iz, ay = 0.37, 0.01, 2e-5, 2e-5, 7.0 / 6.0
    g = gyro.beam_gyro_damping_local(L, RHO, A, iy, iz, NU, ay, ay)[0]
    phi = 12.0 * (iy + iz) * (1 + NU) / ay / (A * L * L)
    c = RHO * (iy + iz) / (30 * L * (1 + phi) ** 2)
    a, b, d = 3 - 15 * phi, 4 + 5 * phi + 10 * phi**2, 1 + 5 * phi - 5 * phi**2
    upper = {
        (2, 3): 36, (2, 5): -a * L, (3, 6): -a * L, (5, 6): b * L * L, (3, 8): 36,
        (5, 8): -a * L, (2, 9): -36, (6, 9): -a * L, (8, 9): 36, (2, 11): -a * L,
        (6, 11): d * L * L, (8, 11): a * L, (3, 12): -a * L, (5, 12): -d * L * L,
        (9, 12): a * L, (11, 12): b * L * L,
    }  # fmt: skip
    ref = np.zeros((12, 12))
    for (i, j), v in upper.items():
        ref[i - 1, j - 1], ref[j - 1, i - 1] = v * c, -v * c
    np.testing.assert_allclose(g, ref, atol=1e-12 * abs(ref).max())


def test_beam_gyro_rigid_tilt_and_euler_limit():
    """A rigid tilt of a beam carries the gyroscopic moment rho Ip L Ω;
    POU_D_E (no shear coefficients) uses phi = 0."""
    L, A, iy = 0.5, 3e-3, 1e-6
    g = gyro.beam_gyro_damping_local(L, RHO, A, iy, iy, NU)[0]
    tilt_z = np.zeros(12)
    tilt_z[[1, 5, 7, 11]] = [0.0, 1.0, L, 1.0]  # v = x θz
    tilt_y = np.zeros(12)
    tilt_y[[2, 4, 8, 10]] = [0.0, 1.0, -L, 1.0]  # w = -x θy
    assert tilt_y @ g @ tilt_z == pytest.approx(RHO * 2 * iy * L, rel=1e-12)
    assert gyro.gyro_shear_parameter(L, A, iy, iy, NU) == 0.0
    kg = gyro.beam_gyro_stiffness_local(L, RHO, A, iy, iy, NU)[0]
    s = gyro.beam_gyro_coupling_local(L, RHO, A, iy, iy, NU)[0]
    np.testing.assert_allclose(kg, s.T)
    np.testing.assert_allclose(g, s - s.T)


def _overhung_rotor(
    session, n_el=4, length=0.6, radius=0.02, disk=(12.0, 0.15, 0.08), axis=(1, 0, 0)
):
    """Massless shaft clamped at N1 along ``axis``, a disk (m, Ip, Id) on the
    free end: the Stodola-Green rotor."""
    d = np.asarray(axis, float)
    coords = np.linspace(0.0, length, n_el + 1)[:, None] * d
    mesh = Mesh(
        coords=coords,
        node_names=[f"N{i + 1}" for i in range(n_el + 1)],
        cell_names=[f"M{i + 1}" for i in range(n_el)] + ["DISQ"],
        cell_types=["SEG2"] * n_el + ["POI1"],
        cell_nodes=[(i, i + 1) for i in range(n_el)] + [(n_el,)],
        node_groups={"A": np.array([0]), "B": np.array([n_el])},
        cell_groups={"ROTOR": np.arange(n_el), "DISQUE": np.array([n_el])},
    )
    model = run(
        session,
        "AFFE_MODELE",
        MAILLAGE=mesh,
        AFFE=[
            {"GROUP_MA": ("ROTOR",), "PHENOMENE": "MECANIQUE", "MODELISATION": "POU_D_E"},
            {"GROUP_MA": ("DISQUE",), "PHENOMENE": "MECANIQUE", "MODELISATION": "DIS_TR"},
        ],
    )
    steel = run(session, "DEFI_MATERIAU", ELAS={"E": E, "NU": NU, "RHO": 1e-9})
    field = run(session, "AFFE_MATERIAU", MAILLAGE=mesh, AFFE={"TOUT": "OUI", "MATER": steel})
    m, ip, idiam = disk
    discret = {
        "GROUP_MA": ("DISQUE",),
        "CARA": "M_TR_D_N",
        "VALE": (m, ip, idiam, idiam, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0),
    }
    cara_kw = {
        "MODELE": model,
        "POUTRE": {"GROUP_MA": ("ROTOR",), "SECTION": "CERCLE", "CARA": ("R",), "VALE": (radius,)},
        "DISCRET": discret,
    }
    if tuple(axis) != (1, 0, 0):
        discret["REPERE"] = "LOCAL"
        cara_kw["ORIENTATION"] = {
            "GROUP_MA": ("DISQUE",),
            "CARA": "VECT_X_Y",
            "VALE": (*d, *np.cross(d, [1.0, 0.0, 0.0] if abs(d[0]) < 0.9 else [0.0, 1.0, 0.0])),
        }
    cara = run(session, "AFFE_CARA_ELEM", **cara_kw)
    fixed = run(
        session,
        "AFFE_CHAR_MECA",
        MODELE=model,
        DDL_IMPO={
            "GROUP_NO": ("A",),
            "DX": 0.0,
            "DY": 0.0,
            "DZ": 0.0,
            "DRX": 0.0,
            "DRY": 0.0,
            "DRZ": 0.0,
        },
    )
    run(
        session,
        "ASSEMBLAGE",
        MODELE=model,
        CHAM_MATER=field,
        CARA_ELEM=cara,
        CHARGE=fixed,
        NUME_DDL=CO("NU"),
        MATR_ASSE=[
            {"MATRICE": CO("K"), "OPTION": "RIGI_MECA"},
            {"MATRICE": CO("M"), "OPTION": "MASS_MECA"},
            {"MATRICE": CO("G"), "OPTION": "MECA_GYRO"},
            {"MATRICE": CO("KG"), "OPTION": "RIGI_GYRO"},
        ],
    )
    return session.bound


def _free_dofs(numbering):
    fixed = {
        i
        for rel in numbering.relations
        for (n, c, _) in rel.terms
        for i in [numbering.index[(n, c)]]
    }
    return np.array([i for i in range(numbering.n_dofs) if i not in fixed])


def _whirl_frequencies(k, m, g, spin):
    """Positive frequencies (Hz) of M q'' + spin G q' + K q = 0 with their
    complex mode shapes (first-order form)."""
    n = len(k)
    minv = np.linalg.inv(m)
    a = np.block([[np.zeros((n, n)), np.eye(n)], [-minv @ k, -spin * minv @ g]])
    values, vectors = np.linalg.eig(a)
    keep = values.imag > 1e-6
    order = np.argsort(values.imag[keep])
    return values.imag[keep][order] / (2 * np.pi), vectors[:n, keep][:, order]


def _campbell_analytic(length, radius, disk, spin):
    """Roots of the Stodola-Green frequency equation
    (k11 - m w^2)(k22 - Id w^2 ± Ip Ω w) - k12^2 = 0 (forward: +)."""
    inertia = np.pi * radius**4 / 4
    flex = np.array([[length**3 / 3, length**2 / 2], [length**2 / 2, length]]) / (E * inertia)
    (k11, k12), (_, k22) = np.linalg.inv(flex)
    m, ip, idiam = disk
    out = {}
    for name, sign in (("forward", 1.0), ("backward", -1.0)):
        # polynomial in w: m Id w^4 - sign m Ip Ω w^3 - (k11 Id + k22 m) w^2 + sign k11 Ip Ω w + det
        coeffs = [
            m * idiam,
            -sign * m * ip * spin,
            -(k11 * idiam + k22 * m),
            sign * k11 * ip * spin,
            k11 * k22 - k12**2,
        ]
        roots = np.roots(coeffs)
        roots = np.sort(roots.real[(abs(roots.imag) < 1e-9) & (roots.real > 0)])
        out[name] = roots / (2 * np.pi)
    return out


@pytest.mark.parametrize("spin", [0.0, 300.0, 1500.0])
def test_overhung_disk_campbell(spin):
    """Forward/backward whirl frequencies of a spinning overhung disk split as
    the analytic Campbell relation says, forward whirl stiffening."""
    length, radius, disk = 0.6, 0.02, (12.0, 0.15, 0.08)
    bound = _overhung_rotor(FakeSession(), length=length, radius=radius, disk=disk)
    numbering = bound["NU"]
    free = _free_dofs(numbering)
    # condense the massless shaft onto the disk node DOFs (static condensation is exact)
    k, m, g = (bound[name].matrix.toarray()[np.ix_(free, free)] for name in ("K", "M", "G"))
    tip = [i for i, f in enumerate(free) if numbering.dofs[f][0] == numbering.mesh.n_nodes - 1]
    inner = [i for i in range(len(free)) if i not in tip]
    kc = k[np.ix_(tip, tip)] - k[np.ix_(tip, inner)] @ np.linalg.solve(
        k[np.ix_(inner, inner)], k[np.ix_(inner, tip)]
    )
    mc, gc = m[np.ix_(tip, tip)], g[np.ix_(tip, tip)]
    keep = [
        i for i, t in enumerate(tip) if numbering.dofs[free[t]][1] in ("DY", "DZ", "DRY", "DRZ")
    ]
    freqs, shapes = _whirl_frequencies(
        kc[np.ix_(keep, keep)], mc[np.ix_(keep, keep)], gc[np.ix_(keep, keep)], spin
    )
    ref = _campbell_analytic(length, radius, disk, spin)
    expected = np.sort(np.concatenate([ref["forward"], ref["backward"]]))
    np.testing.assert_allclose(freqs, expected, rtol=1e-8)
    comps = [numbering.dofs[free[tip[i]]][1] for i in keep]
    v, w = shapes[comps.index("DY")], shapes[comps.index("DZ")]
    for f, vv, ww in zip(freqs, v, w, strict=True):
        # forward whirl (orbit turning from +Y to +Z, the spin's sense): w = -i v
        is_forward = np.isclose(f, ref["forward"], rtol=1e-8).any()
        if spin > 0:
            assert (np.imag(ww / vv) < 0) == is_forward
    if spin > 0:
        assert ref["forward"][0] > ref["backward"][0]


def test_disk_axis_follows_orientation_and_rigi_gyro():
    """A disk spinning about +Z (ORIENTATION) has G[DRX, DRY] = Ip; its
    RIGI_GYRO is the single local term Kg[rz, ry] = Ip (code_aster's), here
    with local y = +Y, z = -X: Kg[DRX, DRY] = -Ip."""
    bound = _overhung_rotor(FakeSession(), axis=(0.0, 0.0, 1.0), disk=(12.0, 0.15, 0.08))
    numbering, g, kg = bound["NU"], bound["G"].matrix, bound["KG"].matrix
    node = numbering.mesh.n_nodes - 1
    i = {c: numbering.index[(node, c)] for c in ("DRX", "DRY", "DRZ")}
    shaft = gyro.beam_gyro_damping_local(
        0.15, 1e-9, np.pi * 0.02**2, np.pi * 0.02**4 / 4, np.pi * 0.02**4 / 4, NU
    )
    assert g[i["DRX"], i["DRY"]] == pytest.approx(0.15, abs=10 * abs(shaft).max())
    assert g[i["DRY"], i["DRX"]] == pytest.approx(-0.15, abs=10 * abs(shaft).max())
    assert abs(g - (-g.T)).max() == 0.0
    assert kg[i["DRX"], i["DRY"]] == pytest.approx(-0.15, abs=10 * abs(shaft).max())
    assert abs(kg[i["DRY"], i["DRX"]]) < 10 * abs(shaft).max()


def test_calc_matr_elem_gyro_and_asse_matrice():
    session = FakeSession()
    bound = _overhung_rotor(session)
    numbering = bound["NU"]
    model = numbering.model
    elem = run(
        session,
        "CALC_MATR_ELEM",
        OPTION="MECA_GYRO",
        MODELE=model,
        CHAM_MATER=numbering.materials,
        CARA_ELEM=numbering.characteristics,
    )
    g = run(session, "ASSE_MATRICE", MATR_ELEM=elem, NUME_DDL=numbering)
    assert g.kind == "GYRO"
    np.testing.assert_allclose(g.matrix.toarray(), bound["G"].matrix.toarray())


def _hysteretic_chain(session, eta_k=0.02, eta_material=0.05):
    """Two springs (AMOR_HYST eta_k) and a beam whose material has AMOR_HYST."""
    mesh = chain_mesh(3)
    model = run(
        session,
        "AFFE_MODELE",
        MAILLAGE=mesh,
        AFFE={
            "GROUP_MA": ("RESSORTS", "MASSES"),
            "PHENOMENE": "MECANIQUE",
            "MODELISATION": "DIS_T",
        },
    )
    cara = run(
        session,
        "AFFE_CARA_ELEM",
        MODELE=model,
        DISCRET=[
            {
                "GROUP_MA": ("RESSORTS",),
                "CARA": "K_T_D_L",
                "VALE": (100.0, 200.0, 300.0),
                "AMOR_HYST": eta_k,
            },
            {"GROUP_MA": ("MASSES",), "CARA": "M_T_D_N", "VALE": 1.0},
        ],
    )
    return mesh, model, cara


def test_rigi_meca_hyst_discrete():
    session = FakeSession()
    _, model, cara = _hysteretic_chain(session, eta_k=0.02)
    rigi = run(session, "CALC_MATR_ELEM", OPTION="RIGI_MECA", MODELE=model, CARA_ELEM=cara)
    hyst = run(session, "CALC_MATR_ELEM", OPTION="RIGI_MECA_HYST", MODELE=model, RIGI_MECA=rigi)
    assert isinstance(hyst, ComplexElementaryMatrices) and hyst.aster_type == "matr_elem_depl_c"
    numbering = run(session, "NUME_DDL", MATR_RIGI=rigi)
    k = run(session, "ASSE_MATRICE", MATR_ELEM=rigi, NUME_DDL=numbering)
    kh = run(session, "ASSE_MATRICE", MATR_ELEM=hyst, NUME_DDL=numbering)
    assert isinstance(kh, ComplexAssembledMatrix) and kh.satisfies("matr_asse_depl_c")
    np.testing.assert_allclose(kh.matrix.toarray(), k.matrix.toarray() * (1 + 0.02j))
    # COMB_R takes a part of a complex matrix, COMB_C keeps it complex
    imag = run(session, "COMB_MATR_ASSE", COMB_R={"MATR_ASSE": kh, "COEF_R": 1.0, "PARTIE": "IMAG"})
    np.testing.assert_allclose(imag.matrix.toarray(), 0.02 * k.matrix.toarray())
    both = run(
        session,
        "COMB_MATR_ASSE",
        COMB_C=[{"MATR_ASSE": kh, "COEF_C": 2.0}, {"MATR_ASSE": k, "COEF_R": -2.0}],
    )
    assert isinstance(both, ComplexAssembledMatrix)
    np.testing.assert_allclose(both.matrix.toarray(), 0.04j * k.matrix.toarray())


def test_rigi_meca_hyst_beam_material():
    """Beams take AMOR_HYST from DEFI_MATERIAU/ELAS."""
    session = FakeSession()
    mesh = Mesh(
        coords=np.array([[0.0, 0, 0], [0.5, 0, 0], [1.0, 0, 0]]),
        node_names=["N1", "N2", "N3"],
        cell_names=["M1", "M2"],
        cell_types=["SEG2", "SEG2"],
        cell_nodes=[(0, 1), (1, 2)],
        cell_groups={"POUTRE": np.array([0]), "AUTRE": np.array([1])},
    )
    model = run(
        session,
        "AFFE_MODELE",
        MAILLAGE=mesh,
        AFFE={"TOUT": "OUI", "PHENOMENE": "MECANIQUE", "MODELISATION": "POU_D_E"},
    )
    lossy = run(session, "DEFI_MATERIAU", ELAS={"E": E, "NU": NU, "RHO": RHO, "AMOR_HYST": 0.1})
    plain = run(session, "DEFI_MATERIAU", ELAS={"E": E, "NU": NU, "RHO": RHO})
    field = run(
        session,
        "AFFE_MATERIAU",
        MAILLAGE=mesh,
        AFFE=[{"GROUP_MA": ("POUTRE",), "MATER": lossy}, {"GROUP_MA": ("AUTRE",), "MATER": plain}],
    )
    cara = run(
        session,
        "AFFE_CARA_ELEM",
        MODELE=model,
        POUTRE={"TOUT": "OUI", "SECTION": "CERCLE", "CARA": ("R",), "VALE": (0.01,)},
    )
    run(
        session,
        "ASSEMBLAGE",
        MODELE=model,
        CHAM_MATER=field,
        CARA_ELEM=cara,
        NUME_DDL=CO("NU"),
        MATR_ASSE=[
            {"MATRICE": CO("K"), "OPTION": "RIGI_MECA"},
            {"MATRICE": CO("KH"), "OPTION": "RIGI_MECA_HYST"},
        ],
    )
    k, kh = session.bound["K"].matrix.toarray(), session.bound["KH"].matrix.toarray()
    np.testing.assert_allclose(kh.real, k, rtol=1e-12, atol=1e-6)
    numbering = session.bound["NU"]
    first = [numbering.index[(0, c)] for c in ("DY", "DRZ")]  # only in the lossy element
    last = [numbering.index[(2, c)] for c in ("DY", "DRZ")]  # only in the plain one
    np.testing.assert_allclose(kh[np.ix_(first, first)].imag, 0.1 * k[np.ix_(first, first)])
    assert not np.any(kh[np.ix_(last, last)].imag)
    assert sla.norm(kh.imag) > 0


def _front_end_of(corpus_dir, tmp_path, deck: str, mesh: str, stop: str) -> dict:
    """Run a corpus deck up to (not including) the line starting with ``stop``."""
    from asterlite.io.export import describe_run
    from asterlite.runtime.session import Session

    text = (corpus_dir / deck / f"{deck}.comm").read_text()
    (tmp_path / "front.comm").write_text(text[: text.index(stop)] + "\nFIN()\n")
    (tmp_path / mesh).write_bytes((corpus_dir / deck / mesh).read_bytes())
    (tmp_path / "front.export").write_text(f"F comm front.comm D 1\nF mail {mesh} D 20\n")
    (tmp_path / "out").mkdir()
    session = Session(
        describe_run(tmp_path / "front.export"),
        output_dir=tmp_path / "out",
        check_only=False,
        echo=False,
        overrides={},
    )
    session.run_all()
    return session.namespace


def test_sdll126b_unbalance_response(corpus_dir, tmp_path):
    """The steady unbalance response of sdll126b's rotor (three disks, two
    damped bearings, 15000 rpm) with K - Ω²M + iΩ(C + ΩG): the amplitudes of
    the deck's reference (VALE_REFE, 5e-3); the opposite spin sense is far off."""
    ns = _front_end_of(corpus_dir, tmp_path, "sdll126b", "sdll126a.mail", "TRANSMO = DYNA_VIBRA")
    k, m, c, g = (ns[n].matrix.toarray() for n in ("RIGIDITE", "MASSE", "AMOR", "GYRO"))
    numbering = ns["NUMEDDL"]
    basis = sla.null_space(numbering.constraint_matrix()[0].toarray())
    spin = ns["OM"]
    force = ns["bal_Yass"].values - 1j * ns["bal_Zass"].values  # FY cos + FZ sin
    iy, iz = numbering.dof_index("N6", "DY"), numbering.dof_index("N6", "DZ")
    amplitudes = {}
    for sense in (1.0, -1.0):
        a = basis.T @ (k - spin**2 * m + 1j * spin * (c + sense * spin * g)) @ basis
        u = basis @ np.linalg.solve(a, basis.T @ force)
        amplitudes[sense] = abs(u[iy]), abs(u[iz])
    assert amplitudes[1.0][0] == pytest.approx(5.721e-4, rel=5e-3)
    assert amplitudes[1.0][1] == pytest.approx(7.023e-4, rel=5e-3)
    assert amplitudes[-1.0][0] < 0.8 * amplitudes[1.0][0]
    # the projected gyroscopic damping stays antisymmetric
    gene = ns["AGGE"].matrix - ns["AMGE"].matrix
    np.testing.assert_allclose(gene, -gene.T, atol=1e-9 * abs(gene).max())
