"""DYNA_VIBRA's transient on the physical basis: linear transient
analysis on assembled (sparse) physical matrices.

The kinematic relations of the numbering are eliminated once,
u = T q + u0 (``asterlite.fem.constraints``), and the schemes integrate the
reduced system Tᵀ M T q'' + Tᵀ C T q' + Tᵀ K T q = Tᵀ (F(t) - K u0).

Cost and choice: the problem is linear, so the implicit schemes (NEWMARK,
WILSON) factorise their effective stiffness once per distinct step with
``scipy.sparse.linalg.splu`` and the explicit ones (DIFF_CENTRE,
ADAPT_ORDRE2) need only the inverse of the diagonal mass. A step is then
one prefactored solve (or none) and a few sparse products, driven from a
Python loop: each step is vectorised over the DOFs, the loop overhead is a
few microseconds per step, negligible beside the sparse solve for the
structures these decks model. Memory grows with the archived instants only.
"""
