"""Block Lanczos in shift-invert mode for K φ = λ M φ (large models).

The operator ``OP = (K - σM)⁻¹ M`` is self-adjoint in the M inner product and
its eigenvalues θ = 1 / (λ - σ) are largest in modulus for the λ nearest σ.
A block of ``p`` vectors is multiplied at each step, so the factor of K - σM
solves ``p`` right-hand sides at once (BLAS 3 in MUMPS: a block of 8 costs
about 2.5 single solves on a 3D mesh) and repeated eigenvalues (a square
section's two bending modes) come together. Every new block is
M-orthogonalised first against the last two blocks of the basis (the
three-term recurrence: its large components, with the coefficients
(M V)ᵀ w from the M-images of those two blocks, kept), then, with M w
recomputed, once against the whole basis (full reorthogonalisation,
classical Gram-Schmidt in matrix products: the components left are round-off
and the loss of orthogonality, small, so one pass brings them to round-off),
then M-orthonormalised by a
symmetric (eigenvalue) factorisation that also finds rank loss; the Rayleigh
quotient H = Vᵀ M OP V is built from the coefficients, its eigenpairs give
the Ritz pairs, and a pair has converged when the M-norm of its residual
``OP y - θ y`` (known from the last block without forming it) is at most
``tol · |θ|``. There is no restart: the basis grows until the ``count`` pairs
nearest σ have converged (about 5 times ``count`` vectors for 50 modes of a
3D solid) or until ``max_dim`` vectors, when :class:`LanczosNotConverged`
lets the caller fall back on ARPACK, whose memory stays bounded.

The starting block is random with a fixed seed, multiplied once by OP (its
vectors then lie in OP's range: no component along massless DOFs), so a
model gives the same modes run after run.
"""

from __future__ import annotations

import numpy as np

#: relative residual ||OP y - θ y||_M / |θ| at which a Ritz pair is accepted:
#: eigenvalues are then exact to round-off and vectors to about tol / gap
DEFAULT_TOL = 1e-12
#: a direction whose norm after reorthogonalisation is below this fraction of
#: its norm before is noise: the Krylov space is exhausted along it
RANK_TOL = 1e-10


class LanczosNotConverged(RuntimeError):
    """The basis reached ``max_dim`` vectors before ``count`` pairs converged."""


def block_size(count: int) -> int:
    """Vectors per block: 8 for tens of modes (measured best on the 98 172-DOF
    bar: fewer solves than 16, cheaper orthogonalisation than 32), fewer for
    a handful, at least 2 so that double eigenvalues come together."""
    return int(min(8, max(2, -(-count // 6))))


def _t_dot(tall, block):
    """tallᵀ block (d × p) for an n × d ``tall`` and an n × p ``block``, as
    (blockᵀ tall)ᵀ: OpenBLAS streams the tall matrix 1.2-1.3 times faster in
    that shape (one thread, n = 97 200, d = 64-256)."""
    return (block.T @ tall).T


def _dot(tall, coefficients):
    """tall · coefficients (n × p), as (coefficientsᵀ tallᵀ)ᵀ: 1.2-1.9 times
    faster than ``tall @ coefficients`` (OpenBLAS, one thread, n = 97 200,
    d = 16-256), and Fortran-ordered like the blocks, without a copy."""
    return (coefficients.T @ tall.T).T


def _symmetric_orthonormalize(w, mw, reference_norms, rng, basis, m):
    """(Q, MQ, R) with W = Q R, Qᵀ M Q = I, by the eigen decomposition of the
    Gram matrix, twice. Directions lost to round-off (rank loss) become
    random vectors M-orthogonal to ``basis`` and to the kept ones, with zero
    rows in R: the Krylov space has an invariant subspace there. Q and MQ
    are Fortran-ordered."""
    p = w.shape[1]
    total = np.eye(p)
    for sweep in range(2):
        gram = w.T @ mw
        gram = 0.5 * (gram + gram.T)
        d, u = np.linalg.eigh(gram)
        floor = (RANK_TOL * reference_norms.max()) ** 2 if sweep == 0 else 1e-28 * d.max()
        keep = d > floor
        if keep.all():
            root = np.sqrt(d)
            transform = u / root
            w = _dot(w, transform)
            mw = _dot(mw, transform)
            total = (root[:, None] * u.T) @ total
            continue
        # rank loss: keep the good directions, fill the rest with random ones
        kept_u, kept_d = u[:, keep], d[keep]
        transform = kept_u / np.sqrt(kept_d)
        q = _dot(w, transform)
        mq = _dot(mw, transform)
        fill = rng.standard_normal((w.shape[0], p - q.shape[1]))
        mfill = m @ fill
        for _ in range(2):
            for vectors in (basis, q):
                if vectors.shape[1]:
                    fill -= _dot(vectors, _t_dot(vectors, mfill))
            mfill = m @ fill
        g = fill.T @ mfill
        dg, ug = np.linalg.eigh(0.5 * (g + g.T))
        transform = ug / np.sqrt(np.maximum(dg, 1e-300))
        w = np.hstack([q, _dot(fill, transform)])
        mw = np.hstack([mq, _dot(mfill, transform)])
        r = np.zeros((p, p))
        r[: q.shape[1]] = np.sqrt(kept_d)[:, None] * kept_u.T
        total = r @ total
    return np.asfortranarray(w), np.asfortranarray(mw), total


def shift_invert_lanczos(
    m,
    solve,
    sigma: float,
    count: int,
    *,
    block: int | None = None,
    tol: float = DEFAULT_TOL,
    max_dim: int | None = None,
    seed: int = 0,
):
    """The ``count`` eigenpairs of K φ = λ M φ nearest σ.

    ``solve(B)`` applies (K - σM)⁻¹ to a block of columns. Returns
    (λ, φ, statistics): λ sorted by distance to σ, φ M-orthonormal columns,
    statistics a dict (solves, basis dimension, steps)."""
    n = m.shape[0]
    p = block or block_size(count)
    p = max(1, min(p, n))
    if max_dim is None:
        max_dim = 8 * count + 20 * p
    max_dim = min(max_dim, n)
    rng = np.random.default_rng(seed)

    capacity = min(max_dim, max(4 * count + 8 * p, 2 * p))
    basis = np.empty((n, capacity), order="F")
    # H = Vᵀ M OP V, filled block column by block column
    h = np.zeros((capacity, capacity))

    start = solve(np.asfortranarray(m @ rng.standard_normal((n, p))))
    mstart = m @ start
    q, mq, _ = _symmetric_orthonormalize(
        np.asfortranarray(start),
        np.asfortranarray(mstart),
        np.sqrt(np.maximum(np.einsum("ij,ij->j", start, mstart), 0.0)),
        rng,
        basis[:, :0],
        m,
    )
    basis[:, :p] = q
    solves, dim, steps = p, p, 0
    # M times the last two blocks of the basis (the previous one absent at first)
    m_previous, m_current = None, mq
    while True:
        steps += 1
        current = slice(dim - p, dim)
        w = np.asfortranarray(solve(m_current))
        solves += p
        # first pass, against the last two blocks: M is symmetric, so their
        # coefficients Vᵀ M w are (M V)ᵀ w, from the images kept
        local = slice(max(0, dim - 2 * p), dim)
        first = _t_dot(m_current, w)
        if m_previous is not None:
            first = np.vstack([_t_dot(m_previous, w), first])
        w -= _dot(basis[:, local], first)
        # M w recomputed, not updated by subtraction: the pass cancels most
        # of w once the Krylov space nears an invariant one
        mw = m @ w
        # |w|_M before the passes (its parts are M-orthogonal), the reference for rank loss
        before = np.sqrt(
            np.sum(first * first, axis=0) + np.maximum(np.einsum("ij,ij->j", w, mw), 0.0)
        )
        # second pass, classical Gram-Schmidt against the whole basis
        v = basis[:, :dim]
        coef = _t_dot(v, mw)
        w -= _dot(v, coef)
        coef[local] += first
        mw = m @ w
        h[:dim, current] = coef
        w, mw, r = _symmetric_orthonormalize(w, mw, before, rng, v, m)

        hs = h[:dim, :dim]
        theta, s = np.linalg.eigh(0.5 * (hs + hs.T))
        order = np.argsort(-np.abs(theta), kind="stable")
        theta, s = theta[order], s[:, order]
        wanted = min(count, dim)
        residual = np.linalg.norm(r @ s[dim - p : dim, :wanted], axis=0)
        converged = residual <= tol * np.abs(theta[:wanted])
        exhausted = dim + p > max_dim
        if (wanted == count and converged.all()) or dim >= n:
            break
        if exhausted:
            raise LanczosNotConverged(
                f"{int(converged.sum())} of {count} eigenpairs converged "
                f"with a basis of {dim} vectors"
            )
        if dim + p > capacity:
            capacity = min(max_dim, max(2 * capacity, dim + p))
            grown = np.empty((n, capacity), order="F")
            grown[:, :dim] = basis[:, :dim]
            basis = grown
            grown_h = np.zeros((capacity, capacity))
            grown_h[:dim, :dim] = h[:dim, :dim]
            h = grown_h
        nxt = slice(dim, dim + p)
        basis[:, nxt] = w
        h[nxt, current] = r
        dim += p
        m_previous, m_current = m_current, mw

    theta, s = theta[:wanted], s[:, :wanted]
    vectors = basis[:, :dim] @ s
    values = sigma + 1.0 / theta
    stats = {"solves": solves, "dimension": dim, "steps": steps, "block": p}
    return values, vectors, stats
