"""Dynamic substructuring numerics: interface DOFs and reduction bases
(:mod:`.interfaces`), placement and interface compatibility of the coupled
generalized model (:mod:`.coupling`), and restitution on the substructures
and the skeleton mesh (:mod:`.restitution`). The concepts are in
:mod:`asterlite.concepts.substructure`."""
