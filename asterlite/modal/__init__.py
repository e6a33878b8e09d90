"""Modal analysis: constrained eigen solver, normalisation, static modes, projection."""
