"""asterlite: run Code_Aster command files for modal transient dynamics with shocks.

The package is split into single-purpose rooms:

- ``lang``      deck grammar, parser and safe evaluator (no numerical imports)
- ``catalog``   keyword model (SIMP/FACT/BLOC/rules) and validation
- ``runtime``   a deck session: namespace, logical units, dispatcher, test records
- ``concepts``  the data types commands hand to each other (Mesh, ModeResult, ...)
- ``fem``       mesh, elements, assembly, constraints
- ``modal``     eigen solver, static modes, projection
- ``dynamics``  integration schemes, nonlinear forces, compiled kernels
- ``post``      restitution, shock statistics, wear, functions, tables
- ``io``        mesh readers, MED/HDF5 writers, table and function writers

Keyword catalogues live in ``asterlite.catalogues`` (one file per command) and
command implementations in ``asterlite.commands`` (one file per command).
"""

__version__ = "0.1.0"
