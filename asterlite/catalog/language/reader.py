"""Reading code_aster's catalogue files without executing them.

code_aster describes its command language in Python modules
(``code_aster/Cata/Commands/*.py``, shared pieces in ``Cata/Commons/``,
types in ``Cata/Language/DataStructure.py``). Those modules are code: the
shared pieces are functions with branches and loops (``C_SOLVEUR(command)``
builds its keywords from the command's name), one defines an ``Enum`` and a
class of field names, another reads a pickle when it is called. asterlite
never runs that code: this module parses each file with :mod:`ast` and walks
the tree itself, over a small subset of Python (literals, names,
arithmetic, comparisons, ``if``/``for``/comprehensions, functions and
simple classes, the methods of ``str``/``list``/``tuple``/``dict``/``set``
that catalogues use), where every call of the catalogue vocabulary
(``OPER``, ``SIMP``, ``FACT``, ``BLOC``, rules, validators, types) builds
plain data objects. Nothing reaches Python's own ``exec``, ``eval``,
``open`` or any attribute of a real object: a name or method outside the
subset stops the reading of that module with :class:`ReadError`, and the
work is bounded (:data:`MAX_STEPS` evaluation steps per module, call depth).

``sd_prod`` and ``compat_syntax`` functions are not run here either: they
stay :class:`Function` objects whose syntax tree the generator analyses
(:mod:`asterlite.catalog.language.sdprod`).
"""

from __future__ import annotations

import ast

from asterlite.catalog.language.cata_objects import (
    ClassObj,
    CommandDef,
    EnumMember,
    Function,
    Instance,
    Opaque,
    OrderedSet,
    ReadError,
    RuleDef,
    Scope,
    TypeRef,
    UnitRef,
    ValidatorDef,
    _user_macro,
)
from asterlite.catalog.language.subset_values import (
    METHODS,
    STUB_MODULES,
    BoundBuiltin,
    BoundMethod,
    Builtin,
    Method,
    _as_load,
    _as_mapping,
    _binary,
    _bind,
    _builtin,
    _command_maker,
    _compare,
    _force_list,
    _isinstance,
    _iterate,
    _keyword_maker,
    _make_dict,
    _maker,
    _number,
    _plain,
    _range,
    _repr,
    _sorted,
    _str,
    _truth,
)

MAX_STEPS = 5_000_000  # expression and statement evaluations per module read
MAX_DEPTH = 60  # nested calls of catalogue functions


# ------------------------------------------------------------------- sources


class Source:
    """The text of code_aster's files, by path relative to the ``code_aster``
    package folder (``Cata/Commands/defi_obstacle.py``)."""

    def read(self, path: str) -> str | None:
        raise NotImplementedError

    def listing(self, folder: str) -> list[str]:
        raise NotImplementedError


class _Return(Exception):
    def __init__(self, value):
        self.value = value


class _Break(Exception):
    pass


class _Continue(Exception):
    pass


# ----------------------------------------------------------------- the reader

RULE_CLASSES = (
    "AtLeastOne",
    "ExactlyOne",
    "AtMostOne",
    "IfFirstAllPresent",
    "OnlyFirstPresent",
    "AllTogether",
    "NotEmpty",
)
VALIDATOR_CLASSES = (
    "NoRepeat",
    "LongStr",
    "OrdList",
    "AndVal",
    "OrVal",
    "Compulsory",
    "Absent",
    "Together",
    "NotEqualTo",
    "AtMostOneStartsWith",
)
# the catalogue vocabulary: name in Language/Syntax.py -> what it builds
KEYWORD_CALLS = {"SIMP": "SIMP", "FACT": "FACT", "BLOC": "BLOC"}
COMMAND_CALLS = {"OPER": "OPER", "MACRO": "MACRO", "PROC": "PROC", "FORM": "FORM"}
COMMAND_CALLS["FIN_PROC"] = "PROC"
COMMAND_CALLS["PROC_ETAPE"] = "PROC"


class CatalogueReader:
    """Reads the modules of one catalogue tree (a :class:`Source`)."""

    def __init__(self, source: Source):
        self.source = source
        self.modules: dict[str, Scope] = {}
        self.loading: set[str] = set()
        self.steps = 0
        self.depth = 0
        self.types: dict[str, TypeRef] = {}
        self.type_aliases: dict[str, str] = {}
        self.syntax = self._syntax_names()
        # the Python types a catalogue may name (``type(x) in (tuple, list)``)
        self.type_builtins = {
            "tuple": Builtin(lambda items=(): tuple(_iterate(items)), "tuple", tuple),
            "list": Builtin(lambda items=(): list(_iterate(items)), "list", list),
            "dict": Builtin(_make_dict, "dict", dict),
            "str": Builtin(_str, "str", str),
            "int": Builtin(int, "int", int),
            "float": Builtin(float, "float", float),
            "bool": Builtin(bool, "bool", bool),
        }

    def _type(self, value):
        """``type(value)``: one of the Python type builtins, else opaque."""
        for builtin in self.type_builtins.values():
            if type(value) is builtin.pytype:
                return builtin
        return Opaque(f"type of {type(value).__name__}")

    # --------------------------------------------------------------- modules
    def module(self, path: str) -> Scope:
        """The names a module defines (read once)."""
        if path in self.modules:
            return self.modules[path]
        if path in self.loading:
            raise ReadError(f"circular import of {path}")
        text = self.source.read(path)
        if text is None:
            raise ReadError(f"no module {path}")
        self.loading.add(path)
        try:
            tree = ast.parse(text, filename=path)
            scope = Scope({"__name__": path}, self._builtins())
            self.steps = 0
            self._run_block(tree.body, scope, module=path)
            self.modules[path] = scope
            return scope
        finally:
            self.loading.discard(path)

    def _syntax_names(self) -> dict:
        """Language/DataStructure.py and Language/Syntax.py as names."""
        names: dict = {}
        for path in ("Cata/Language/DataStructure.py", "Cata/DataStructure.py"):
            text = self.source.read(path)
            if text is not None:
                self._read_types(ast.parse(text))
                break
        names.update(self.types)
        for alias, target in self.type_aliases.items():
            names[alias] = self.types.get(target, Opaque(target))
        names["UnitType"] = _builtin(lambda filter=None: UnitRef(filter))
        names["AsType"] = Opaque("AsType")
        for kind in RULE_CLASSES:
            names[kind] = _builtin(_maker(RuleDef, kind))
        for kind in VALIDATOR_CLASSES:
            names[kind] = _builtin(_maker(ValidatorDef, kind))
        for name, kind in KEYWORD_CALLS.items():
            names[name] = _builtin(_keyword_maker(kind))
        for name, kind in COMMAND_CALLS.items():
            names[name] = _builtin(_command_maker(kind))
        # aliases Syntax.py defines (AU_MOINS_UN = AtLeastOne...): read, not assumed
        text = self.source.read("Cata/Language/Syntax.py")
        if text is not None:
            for node in ast.parse(text).body:
                if (
                    isinstance(node, ast.Assign)
                    and len(node.targets) == 1
                    and isinstance(node.targets[0], ast.Name)
                    and isinstance(node.value, ast.Name)
                    and node.value.id in names
                ):
                    names[node.targets[0].id] = names[node.value.id]
        names["tr"] = _builtin(lambda text: text)
        names["OPS"] = _builtin(lambda value: Opaque("OPS"))
        names["EMPTY_OPS"] = Opaque("EMPTY_OPS")
        names["_F"] = _builtin(lambda **kwargs: dict(kwargs))
        names["CataError"] = Opaque("CataError")
        names["deprecate"] = _builtin(lambda *args, **kwargs: None)
        names["force_list"] = _builtin(_force_list)
        names["assd"] = self.types.get("DataStructure", Opaque("assd"))
        return names

    def _read_types(self, tree: ast.Module) -> None:
        """Classes of DataStructure.py (name and bases), and its aliases."""
        for node in tree.body:
            if isinstance(node, ast.ClassDef):
                bases = tuple(b.id for b in node.bases if isinstance(b, ast.Name))
                self.types[node.name] = TypeRef(node.name, bases)
            elif (
                isinstance(node, ast.Assign)
                and len(node.targets) == 1
                and isinstance(node.targets[0], ast.Name)
                and isinstance(node.value, ast.Name)
            ):
                self.type_aliases[node.targets[0].id] = node.value.id

    def _builtins(self) -> Scope:
        names = dict(self.syntax)
        names.update(self.type_builtins)
        names.update(
            {
                "None": None,
                "True": True,
                "False": False,
                "len": _builtin(len),
                "type": _builtin(self._type),
                "set": _builtin(lambda items=(): OrderedSet(_iterate(items))),
                "sorted": _builtin(_sorted),
                "reversed": _builtin(lambda items: list(reversed(list(_iterate(items))))),
                "range": _builtin(_range),
                "zip": _builtin(lambda *seqs: list(zip(*map(_iterate, seqs), strict=False))),
                "enumerate": _builtin(
                    lambda items, start=0: list(enumerate(_iterate(items), start))
                ),
                "any": _builtin(lambda items: any(_iterate(items))),
                "all": _builtin(lambda items: all(_iterate(items))),
                "min": _builtin(lambda *a: min(*a)),
                "max": _builtin(lambda *a: max(*a)),
                "abs": _builtin(abs),
                "isinstance": _builtin(_isinstance),
                "print": _builtin(lambda *a, **k: None),
                "ValueError": Opaque("ValueError"),
                "TypeError": Opaque("TypeError"),
                "KeyError": Opaque("KeyError"),
                "ImportError": Opaque("ImportError"),
                "AssertionError": Opaque("AssertionError"),
                "object": Opaque("object"),
                "classmethod": Opaque("classmethod"),
                "staticmethod": Opaque("staticmethod"),
            }
        )
        return Scope(names)

    # ------------------------------------------------------------- imports
    def _import_from(self, node: ast.ImportFrom, scope: Scope, module: str) -> None:
        target = self._resolve(node.module or "", node.level, module)
        if target is None:  # not a catalogue: names exist but are opaque
            stub = STUB_MODULES.get(node.module or "", {}) if node.level == 0 else {}
            for alias in node.names:
                value = stub.get(alias.name, Opaque(f"{node.module}.{alias.name}"))
                scope.names[alias.asname or alias.name] = value
            return
        if isinstance(target, dict):  # the Language package: vocabulary names
            names = target
        else:
            names = self._package_names(target)
        for alias in node.names:
            if alias.name == "*":
                scope.names.update({k: v for k, v in names.items() if not k.startswith("_")})
            elif alias.name in names:
                scope.names[alias.asname or alias.name] = names[alias.name]
            elif isinstance(target, dict) and target is not self.syntax:
                scope.names[alias.asname or alias.name] = Opaque(alias.name)
            elif isinstance(target, str) and self._is_package(target):
                sub = self.module(f"{target}/{alias.name}.py")
                scope.names[alias.asname or alias.name] = sub
            else:
                raise ReadError(f"cannot import {alias.name} from {node.module}")

    def _package_names(self, target: str) -> dict:
        path = f"{target}/__init__.py" if self._is_package(target) else f"{target}.py"
        return self.module(path).names

    def _is_package(self, target: str) -> bool:
        return self.source.read(f"{target}/__init__.py") is not None

    def _resolve(self, name: str, level: int, module: str):
        """The module (path without .py) an import names when it is one of
        the catalogues (``Cata/...``), the vocabulary dict for the Language
        modules, None for any other module (names there stay opaque)."""
        if level == 0:
            if name == "code_aster" or not name.startswith("code_aster."):
                return None
            name, level, module = name[len("code_aster.") :], 1, "x.py"
        parts = module.split("/")[:-1]  # the package folder of the module
        if level > 1:
            parts = parts[: len(parts) - (level - 1)] if level - 1 <= len(parts) else []
        path = "/".join([*parts, *name.split(".")]) if name else "/".join(parts)
        if path.startswith("Cata/Language") or path in ("Cata/Syntax", "Cata/DataStructure"):
            return self.syntax
        if path in ("Cata/SyntaxUtils", "Cata/SyntaxObjects", "Cata/SyntaxChecker"):
            return self.syntax
        if path == "Supervis" or path.startswith("Supervis/"):
            return {"UserMacro": _builtin(_user_macro)}
        if not path.startswith("Cata"):
            return None
        return path

    # ----------------------------------------------------------- statements
    def _tick(self) -> None:
        self.steps += 1
        if self.steps > MAX_STEPS:
            raise ReadError("too many evaluation steps")

    def _run_block(self, body: list, scope: Scope, module: str) -> None:
        for statement in body:
            self._run(statement, scope, module)

    def _run(self, node: ast.stmt, scope: Scope, module: str) -> None:
        self._tick()
        if isinstance(node, ast.Expr):
            if isinstance(node.value, ast.Constant):  # a docstring
                return
            self.eval(node.value, scope, module)
        elif isinstance(node, ast.Assign):
            value = self.eval(node.value, scope, module)
            for target in node.targets:
                self._assign(target, value, scope, module)
        elif isinstance(node, ast.AnnAssign):
            if node.value is not None:
                self._assign(node.target, self.eval(node.value, scope, module), scope, module)
        elif isinstance(node, ast.AugAssign):
            current = self.eval(_as_load(node.target), scope, module)
            value = _binary(node.op, current, self.eval(node.value, scope, module))
            self._assign(node.target, value, scope, module)
        elif isinstance(node, ast.If):
            if _truth(self.eval(node.test, scope, module)):
                self._run_block(node.body, scope, module)
            else:
                self._run_block(node.orelse, scope, module)
        elif isinstance(node, ast.For):
            self._for(node, scope, module)
        elif isinstance(node, ast.Return):
            value = self.eval(node.value, scope, module) if node.value is not None else None
            raise _Return(value)
        elif isinstance(node, ast.FunctionDef):
            function = Function(node, scope, module)
            for decorator in reversed(node.decorator_list):
                function = self._decorate(decorator, function)
            scope.names[node.name] = function
        elif isinstance(node, ast.ClassDef):
            scope.names[node.name] = self._class(node, scope, module)
        elif isinstance(node, ast.ImportFrom):
            self._import_from(node, scope, module)
        elif isinstance(node, ast.Import):
            for alias in node.names:
                name = alias.asname or alias.name.split(".")[0]
                scope.names[name] = Opaque(alias.name)
        elif isinstance(node, ast.Try):
            self._try(node, scope, module)
        elif isinstance(node, (ast.Pass, ast.Assert, ast.Global, ast.Nonlocal)):
            return  # assertions check the catalogue's own arguments
        elif isinstance(node, ast.Delete):
            for target in node.targets:
                self._delete(target, scope, module)
        elif isinstance(node, ast.Raise):
            raise ReadError(f"the catalogue raises an error (line {node.lineno})")
        elif isinstance(node, ast.Break):
            raise _Break()
        elif isinstance(node, ast.Continue):
            raise _Continue()
        elif isinstance(node, ast.While):
            raise ReadError(f"while loop (line {node.lineno})")
        else:
            raise ReadError(f"statement {type(node).__name__} (line {node.lineno})")

    def _decorate(self, decorator: ast.expr, function: Function):
        if isinstance(decorator, ast.Name) and decorator.id in ("classmethod", "staticmethod"):
            return Method(function, decorator.id)
        return function  # other decorators (wraps...) change nothing the reader uses

    def _try(self, node: ast.Try, scope: Scope, module: str) -> None:
        """``try: from .x import y`` / ``except ImportError``: the handler runs
        when the body cannot be read (c_mfront_official exists only once
        code_aster is installed)."""
        try:
            self._run_block(node.body, scope, module)
        except ReadError:
            if not node.handlers:
                raise
            self._run_block(node.handlers[0].body, scope, module)
        else:
            self._run_block(node.orelse, scope, module)
        self._run_block(node.finalbody, scope, module)

    def _for(self, node: ast.For, scope: Scope, module: str) -> None:
        items = list(_iterate(self.eval(node.iter, scope, module)))
        broke = False
        for item in items:
            self._assign(node.target, item, scope, module)
            try:
                self._run_block(node.body, scope, module)
            except _Break:
                broke = True
                break
            except _Continue:
                continue
        if not broke:
            self._run_block(node.orelse, scope, module)

    def _assign(self, target: ast.expr, value, scope: Scope, module: str) -> None:
        if isinstance(target, ast.Name):
            scope.names[target.id] = value
        elif isinstance(target, (ast.Tuple, ast.List)):
            values = list(_iterate(value))
            if len(values) != len(target.elts):
                raise ReadError("unpacking: wrong number of values")
            for element, item in zip(target.elts, values, strict=True):
                self._assign(element, item, scope, module)
        elif isinstance(target, ast.Subscript):
            container = self.eval(target.value, scope, module)
            key = self.eval(target.slice, scope, module)
            if isinstance(container, (dict, list)):
                container[key] = value
            else:
                raise ReadError("item assignment to a value that is not a dict or list")
        elif isinstance(target, ast.Attribute):
            owner = self.eval(target.value, scope, module)
            if isinstance(owner, Instance) and not target.attr.startswith("__"):
                owner.attrs[target.attr] = value
            else:
                raise ReadError(f"attribute assignment .{target.attr}")
        else:
            raise ReadError(f"assignment to {type(target).__name__}")

    def _delete(self, target: ast.expr, scope: Scope, module: str) -> None:
        if isinstance(target, ast.Name):
            scope.names.pop(target.id, None)
        elif isinstance(target, ast.Subscript):
            container = self.eval(target.value, scope, module)
            key = self.eval(target.slice, scope, module)
            if not isinstance(container, (dict, list)):
                raise ReadError("del of an item of a value that is not a dict or list")
            del container[key]
        else:
            raise ReadError("del of something else than a name or an item")

    def _class(self, node: ast.ClassDef, scope: Scope, module: str) -> ClassObj:
        bases = tuple(self.eval(base, scope, module) for base in node.bases)
        enum = any(isinstance(b, Opaque) and b.name in ("Enum", "enum.Enum") for b in bases)
        enum = enum or any(isinstance(b, ClassObj) and b.enum for b in bases)
        body = Scope({}, scope)
        self._run_block(node.body, body, module)
        cls = ClassObj(node.name, body.names, bases, enum)
        if enum:
            for name, value in list(body.names.items()):
                if name.startswith("_") or isinstance(value, (Function, Method)):
                    continue
                member = EnumMember(cls, name, value)
                cls.members.append(member)
                cls.attrs[name] = member
        return cls

    # ----------------------------------------------------------- expressions
    def eval(self, node: ast.expr, scope: Scope, module: str):
        self._tick()
        method = getattr(self, f"_e_{type(node).__name__}", None)
        if method is None:
            raise ReadError(f"expression {type(node).__name__} (line {node.lineno})")
        return method(node, scope, module)

    def _e_Constant(self, node, scope, module):
        return node.value

    def _e_Name(self, node, scope, module):
        if node.id.startswith("__") and node.id != "__name__":
            raise ReadError(f"name {node.id}")
        return scope.lookup(node.id)

    def _e_Tuple(self, node, scope, module):
        return tuple(self._elements(node.elts, scope, module))

    def _e_List(self, node, scope, module):
        return list(self._elements(node.elts, scope, module))

    def _e_Set(self, node, scope, module):
        return OrderedSet(self._elements(node.elts, scope, module))

    def _elements(self, elts, scope, module):
        items = []
        for element in elts:
            if isinstance(element, ast.Starred):
                items.extend(_iterate(self.eval(element.value, scope, module)))
            else:
                items.append(self.eval(element, scope, module))
        return items

    def _e_Dict(self, node, scope, module):
        result = {}
        for key, value in zip(node.keys, node.values, strict=True):
            if key is None:  # {**other}
                result.update(_as_mapping(self.eval(value, scope, module)))
            else:
                result[self.eval(key, scope, module)] = self.eval(value, scope, module)
        return result

    def _e_JoinedStr(self, node, scope, module):
        parts = []
        for value in node.values:
            if isinstance(value, ast.Constant):
                parts.append(str(value.value))
            else:
                parts.append(self._e_FormattedValue(value, scope, module))
        return "".join(parts)

    def _e_FormattedValue(self, node, scope, module):
        value = self.eval(node.value, scope, module)
        spec = self.eval(node.format_spec, scope, module) if node.format_spec else ""
        if node.conversion == ord("r"):
            value = _repr(value)
        return format(_plain(value), spec)

    def _e_BinOp(self, node, scope, module):
        left = self.eval(node.left, scope, module)
        right = self.eval(node.right, scope, module)
        return _binary(node.op, left, right)

    def _e_UnaryOp(self, node, scope, module):
        operand = self.eval(node.operand, scope, module)
        if isinstance(node.op, ast.Not):
            return not _truth(operand)
        if isinstance(node.op, ast.USub):
            return -_number(operand)
        if isinstance(node.op, ast.UAdd):
            return +_number(operand)
        raise ReadError("unary operator")

    def _e_BoolOp(self, node, scope, module):
        is_and = isinstance(node.op, ast.And)
        value = None
        for element in node.values:
            value = self.eval(element, scope, module)
            if _truth(value) != is_and:
                return value
        return value

    def _e_Compare(self, node, scope, module):
        left = self.eval(node.left, scope, module)
        for op, right_node in zip(node.ops, node.comparators, strict=True):
            right = self.eval(right_node, scope, module)
            if not _compare(op, left, right):
                return False
            left = right
        return True

    def _e_IfExp(self, node, scope, module):
        if _truth(self.eval(node.test, scope, module)):
            return self.eval(node.body, scope, module)
        return self.eval(node.orelse, scope, module)

    def _e_Subscript(self, node, scope, module):
        container = self.eval(node.value, scope, module)
        key = self.eval(node.slice, scope, module)
        if isinstance(container, (Opaque, ClassObj)):  # typing: Dict[str, ...]
            return Opaque("typing")
        if not isinstance(container, (dict, list, tuple, str)):
            raise ReadError(f"indexing a {type(container).__name__}")
        return container[key]

    def _e_Slice(self, node, scope, module):
        parts = (node.lower, node.upper, node.step)
        return slice(*(self.eval(p, scope, module) if p is not None else None for p in parts))

    def _e_Attribute(self, node, scope, module):
        owner = self.eval(node.value, scope, module)
        return self._attribute(owner, node.attr)

    def _attribute(self, owner, name: str):
        if name.startswith("_") and not (isinstance(owner, (ClassObj, Instance))):
            raise ReadError(f"attribute {name}")
        if isinstance(owner, CommandDef):
            return owner.attribute(name)
        if isinstance(owner, ClassObj):
            if name in owner.attrs:
                return _bind(owner.attrs[name], owner)
            for base in owner.bases:
                if isinstance(base, ClassObj):
                    try:
                        return self._attribute(base, name)
                    except ReadError:
                        pass
            raise ReadError(f"class {owner.name} has no attribute {name}")
        if isinstance(owner, Instance):
            if name in owner.attrs:
                return owner.attrs[name]
            value = self._attribute(owner.cls, name)
            if isinstance(value, BoundMethod) and value.kind == "class":
                return value
            if isinstance(value, Function):
                return BoundMethod(value, owner, "instance")
            return value
        if isinstance(owner, EnumMember):
            if name == "name":
                return owner.name
            if name == "value":
                return owner.value
            raise ReadError(f"attribute {name} of an enum member")
        allowed = METHODS.get(type(owner))
        if allowed is not None and name in allowed:
            return BoundBuiltin(owner, name)
        raise ReadError(f"attribute {name} of {type(owner).__name__}")

    def _e_Call(self, node, scope, module):
        function = self.eval(node.func, scope, module)
        args = []
        for arg in node.args:
            if isinstance(arg, ast.Starred):
                args.extend(_iterate(self.eval(arg.value, scope, module)))
            else:
                args.append(self.eval(arg, scope, module))
        kwargs = {}
        for keyword in node.keywords:
            value = self.eval(keyword.value, scope, module)
            items = _as_mapping(value).items() if keyword.arg is None else [(keyword.arg, value)]
            for key, item in items:
                if key in kwargs:  # Python's TypeError: multiple values for a keyword
                    raise ReadError(f"keyword {key} given twice (line {node.lineno})")
                kwargs[key] = item
        return self.call(function, args, kwargs)

    def call(self, function, args: list, kwargs: dict):
        if isinstance(function, Builtin):
            try:
                return function.fn(*args, **kwargs)
            except ReadError:
                raise
            except Exception as error:  # a wrong call of the vocabulary
                raise ReadError(f"{type(error).__name__}: {error}") from None
        if isinstance(function, BoundBuiltin):
            return function.call(args, kwargs)
        if isinstance(function, Function):
            return self._call_function(function, args, kwargs)
        if isinstance(function, BoundMethod):
            return self._call_function(function.function, [function.owner, *args], kwargs)
        if isinstance(function, Method) and function.kind == "static":
            return self._call_function(function.function, args, kwargs)
        if isinstance(function, Instance):
            method = self._attribute(function.cls, "__call__")
            if isinstance(method, Function):
                return self._call_function(method, [function, *args], kwargs)
        if isinstance(function, ClassObj) and not function.enum:
            instance = Instance(function)
            init = function.attrs.get("__init__")
            if isinstance(init, Function):
                self._call_function(init, [instance, *args], kwargs)
            return instance
        name = getattr(function, "name", type(function).__name__)
        raise ReadError(f"call of {name}")

    def _call_function(self, function: Function, args: list, kwargs: dict):
        self.depth += 1
        if self.depth > MAX_DEPTH:
            self.depth -= 1
            raise ReadError("calls nested too deeply")
        try:
            local = Scope(self._bind_arguments(function, args, kwargs), function.scope)
            try:
                self._run_block(function.node.body, local, function.module)
            except _Return as result:
                return result.value
            return None
        finally:
            self.depth -= 1

    def _bind_arguments(self, function: Function, args: list, kwargs: dict) -> dict:
        spec = function.node.args
        positional = [a.arg for a in spec.posonlyargs + spec.args]
        names: dict = {}
        defaults = spec.defaults
        scope, module = function.scope, function.module
        first_default = len(positional) - len(defaults)
        for index, name in enumerate(positional):
            if index < len(args):
                names[name] = args[index]
            elif name in kwargs:
                names[name] = kwargs.pop(name)
            elif index >= first_default:
                names[name] = self.eval(defaults[index - first_default], scope, module)
            else:
                raise ReadError(f"{function.name}() misses argument {name}")
        extra = args[len(positional) :]
        if spec.vararg is not None:
            names[spec.vararg.arg] = tuple(extra)
        elif extra:
            raise ReadError(f"{function.name}() takes {len(positional)} arguments")
        for arg, default in zip(spec.kwonlyargs, spec.kw_defaults, strict=True):
            if arg.arg in kwargs:
                names[arg.arg] = kwargs.pop(arg.arg)
            elif default is not None:
                names[arg.arg] = self.eval(default, scope, module)
            else:
                raise ReadError(f"{function.name}() misses argument {arg.arg}")
        if spec.kwarg is not None:
            names[spec.kwarg.arg] = dict(kwargs)
        elif kwargs:
            raise ReadError(f"{function.name}() got unexpected {', '.join(kwargs)}")
        return names

    def _comprehension(self, generators, scope, module, produce):
        def walk(index: int, inner: Scope):
            if index == len(generators):
                produce(inner)
                return
            generator = generators[index]
            for item in list(_iterate(self.eval(generator.iter, inner, module))):
                level = Scope({}, inner)
                self._assign(generator.target, item, level, module)
                if all(_truth(self.eval(c, level, module)) for c in generator.ifs):
                    walk(index + 1, level)

        walk(0, scope)

    def _e_ListComp(self, node, scope, module):
        result = []
        self._comprehension(
            node.generators, scope, module, lambda s: result.append(self.eval(node.elt, s, module))
        )
        return result

    def _e_GeneratorExp(self, node, scope, module):
        return self._e_ListComp(node, scope, module)

    def _e_SetComp(self, node, scope, module):
        return OrderedSet(self._e_ListComp(node, scope, module))

    def _e_DictComp(self, node, scope, module):
        result = {}

        def produce(inner):
            result[self.eval(node.key, inner, module)] = self.eval(node.value, inner, module)

        self._comprehension(node.generators, scope, module, produce)
        return result

    def _e_Lambda(self, node, scope, module):
        raise ReadError(f"lambda (line {node.lineno})")
