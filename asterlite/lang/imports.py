"""``import`` statements of decks: the evaluator's half that binds modules.

Decks may import ``math``, ``cmath``, ``numpy`` (and ``numpy.linalg``),
``os`` and ``os.path`` (:mod:`asterlite.lang.stdlib`: string functions of
paths, file tests inside the run's output folder only), and what the
evaluator's ``module_loader`` provides (code_aster's command modules, the
deck's own helper files, ``os`` bound to the run's output folder); every
module is a :class:`DeckModule`, cached per evaluator.
"""

from __future__ import annotations

from asterlite.errors import DeckRuntimeError
from asterlite.lang.exceptions import python_error
from asterlite.lang.library import DeckModule


class ImportStatements:
    """Mixed into :class:`asterlite.lang.evaluator.Evaluator` (which provides
    ``modules``, ``module_loader``, ``_builtin_modules`` and ``_store``)."""

    def _import_name(self, node, frame):
        for dotted_as_name in node.children:
            dotted, alias = dotted_as_name.children
            parts = [token.value for token in dotted.children]
            full_name = ".".join(parts)
            module = self._import(full_name)
            if alias is not None:
                self._store(alias.value, module, frame)
                continue
            # "import a.b" binds a, with a.b reachable as an attribute
            top = self._import(parts[0])
            for depth in range(1, len(parts)):
                parent = self._import(".".join(parts[:depth]))
                parent.members.setdefault(parts[depth], self._import(".".join(parts[: depth + 1])))
            self._store(parts[0], top, frame)

    def _import_from(self, node, frame):
        dotted, names = node.children
        if not dotted.children:  # from __future__ import ...: checked by the parser
            return
        full_name = ".".join(token.value for token in dotted.children)
        module = self._import(full_name)
        if names.data == "import_star":
            for name, value in module.public_names().items():
                self._store(name, value, frame)
            return
        for import_as_name in names.children:
            name, alias = import_as_name.children
            self._store((alias or name).value, self._import_member(module, name.value), frame)

    def _import_member(self, module: DeckModule, name: str):
        if name in module.members:
            return module.members[name]
        try:
            return self._import(f"{module.name}.{name}")
        except DeckRuntimeError:
            raise DeckRuntimeError(f"cannot import name '{name}' from '{module.name}'") from None

    def _import(self, name: str) -> DeckModule:
        if name in self.modules:
            return self.modules[name]
        if name in self._builtin_modules:
            module = self._builtin_modules[name]()
        else:
            members = self.module_loader(name) if self.module_loader is not None else None
            if members is None and name in ("os", "os.path"):  # no run: no output folder
                from asterlite.lang import stdlib

                module = stdlib.os_module(lambda: None, self.limits)
                members = module if name == "os" else module.attribute("path")
            if members is None:  # as Python says of a module it lacks: a deck may catch it
                raise python_error(
                    ImportError,
                    f"no module named '{name}' (decks may import math, cmath, numpy, os.path, "
                    "code_aster and their own helper files)",
                )
            module = members if isinstance(members, DeckModule) else DeckModule(name, members)
        self.modules[name] = module
        return module
