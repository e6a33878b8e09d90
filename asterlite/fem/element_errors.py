"""The error of element computations, in a module of its own so that every
element family (beams, plane and 3D solids, plates, absorbing boundaries)
can raise it without importing the table of families in
:mod:`asterlite.fem.elements`, which imports them."""


class ElementError(ValueError):
    """A model/characteristics combination that cannot give element matrices."""
