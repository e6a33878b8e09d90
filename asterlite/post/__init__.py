"""Post-processing: restitution of physical fields (``restitution``), shock
statistics and wear (``shocks``), TEST_* verdicts (``checks``, their records
``check_record``) and the safe FORMULE expression compiler (``expression``)."""
