"""The code_aster command language, one JSON file per version (``v17.json``...).

Generated from code_aster's own catalogues by
``python3 -m asterlite.catalog.language.generate`` (see that module); read by
:mod:`asterlite.catalog.language.model`. Do not edit by hand: regenerate.
"""
