"""Float loops of deck functions without per-operation guards.

A ``for`` loop whose body only does float arithmetic (``+ - * / // %``,
``**`` by an integral constant, comparisons in ``if`` tests), calls pure
float functions of the math module and small deck functions made of
``if ...: return ...`` branches (``Rampe(t)``) gets a second, typed version
next to the guarded one :mod:`asterlite.lang.compiler` builds:

- before the loop, one test proves what the body reads: float locals
  (those it carries from one iteration to the next included: a typed
  iteration leaves them floats), float deck names (read once), the callees
  (the very objects seen when compiling) and room for the callees' call
  depth;
- at each iteration, the loop variables are tested to be floats and the
  budget must have room for the iteration's steps (one, plus one per
  inlined call) before its next check: they are taken at once. A loop over
  float constants the function holds itself (``for u, f in zip(uu, ff)``
  with ``uu = [0.2, 0.15]``...) runs over items known when compiling: room
  for all its steps is tested once, nothing per item;
- the body then runs without guards: forward inference proves every
  operand a float, the small deck functions are inlined (and computed once
  before the loop when their arguments do not change in it and they cannot
  raise);
- when anything in that typed body raises, the budget and the carried
  locals are put back as they were at the start of the iteration and the
  iteration runs again in the guarded code, which raises the interpreter's
  error at the interpreter's step; from then on, and as soon as a test
  fails, the remaining iterations run guarded.

Values, errors and step counts are those of the guarded code: the typed
body has no effect but on locals and the step count, both restored before
a replay. Anything outside this subset leaves the loop guarded only.
"""

from __future__ import annotations

import ast
import builtins
import copy
import math
import types

from asterlite.lang.compiled_ast import (
    BINARY,
    COMPARE,
    Refused,
    _all,
    _name,
    _stamp,
    _type_is,
    if_branches,
)

# math functions giving a float for float arguments (they may raise; a
# raise replays the iteration guarded)
PURE_FLOAT_FUNCTIONS = frozenset(
    [
        *(
            getattr(math, name)
            for name in (
                "sin cos tan asin acos atan atan2 sinh cosh tanh asinh acosh atanh exp expm1 "
                "log log10 log1p log2 sqrt hypot fabs pow degrees radians"
            ).split()
        ),
        builtins.abs,
    ]
)
FLOAT, INT, BOOL = "float", "int", "bool"
EXACT_INT = 2**53  # larger int constants are left to the guarded code
NON_RAISING = frozenset({"+", "-", "*"})  # between floats: inf or nan, never an exception


class Typed:
    """A typed expression: its ``ast``, its type, whether it may raise, and
    how many deck function calls it inlines."""

    def __init__(self, expression, kind, raises=False, calls=0, invariant=False):
        self.expression = expression
        self.kind = kind
        self.raises = raises
        self.calls = calls
        self.invariant = invariant  # the same value at every iteration


class FastLoop:
    """Builds the typed version of one ``for`` loop of a FunctionCompiler."""

    def __init__(self, compiler, node, line: int):
        self.compiler = compiler
        self.node = node
        self.line = line
        self.evaluator = compiler.evaluator
        self.namespace = compiler.evaluator.namespace
        self.assigned: set[str] = set()  # locals the body assigns
        self.targets: list[str] = []
        self.invariant_locals: list[str] = []  # tested once, before the loop
        self.carried: list[str] = []  # read before the body assigns them: tested before the loop
        self.globals: dict[str, str] = {}  # deck name -> temporary holding it
        self.callees: dict[str, str] = {}  # deck name -> closure name of the object
        self.hoisted: dict[tuple, str] = {}  # value computed before the loop -> temporary
        self.hoisted_code: list = []
        self.inlines = False
        self.calls = 0
        self.in_branch = False
        self.in_inline = False  # building an inlined body (its values depend on its test)

    # -------------------------------------------------------------- build

    def build(self, iterable: ast.expr, variable: str, generic_body: list, orelse: list) -> list:
        """``if <entry test>: <typed loop> else: <guarded loop>``, or Refused.
        ``iterable`` is the guarded code of the loop's iterable, ``variable``
        the guarded loop's variable, ``generic_body`` its body (step, binding
        of the targets, statements)."""
        target, _, suite, _ = self.node.children
        self._targets(target)
        self._collect_assigned(suite)
        env = dict.fromkeys(self.targets, FLOAT)
        body = self.suite(suite, env)
        c = self.compiler
        steps = 1 + self.calls
        items = self._static_items()
        if items is not None:
            return self._counted_loop(iterable, variable, generic_body, orelse, body, items)
        iterable_temp = c.temp()
        item, ok, started, saved = c.temp(), c.temp(), c.temp(), c.temp()
        budget = _name("__b")
        if target.data == "var":
            item_test = []
            bind = ast.Assign([_name(self.targets[0], store=True)], _name(item))
        else:  # a tuple of another size raises in the try below: replayed guarded
            item_test = [_type_is(_name(item), "__TU")]
            store = ast.Tuple([_name(n, store=True) for n in self.targets], ast.Store())
            bind = ast.Assign([store], _name(item))
        # room for the iteration's steps before the next check: next_check
        # never decreases, so its value when the loop starts is a safe bound;
        # -1 once an iteration ran guarded (all the following do)
        room = ast.Compare(ast.Attribute(budget, "steps", ast.Load()), [ast.Lt()], [_name(ok)])
        carried = sorted(self.assigned - set(self.targets))
        # carried locals: floats when the loop starts, floats after each typed iteration
        iteration_types = [_type_is(_name(n), "__FL") for n in self.targets]
        restore = [ast.Assign([ast.Attribute(budget, "steps", ast.Store())], _name(started))]
        snapshot = []
        if carried:
            if len(carried) == 1:
                held, current = _name(carried[0], store=True), _name(carried[0])
            else:
                held = ast.Tuple([_name(n, store=True) for n in carried], ast.Store())
                current = ast.Tuple([_name(n) for n in carried], ast.Load())
            restore.append(ast.Assign([held], _name(saved)))
            snapshot.append(ast.Assign([_name(saved, store=True)], current))
        typed_iteration = [
            ast.Assign([_name(started, store=True)], ast.Attribute(budget, "steps", ast.Load())),
            *snapshot,
            ast.Try(
                body=[
                    bind,
                    ast.If(
                        _all(iteration_types),
                        [
                            ast.Assign(
                                [ast.Attribute(budget, "steps", ast.Store())],
                                ast.BinOp(_name(started), ast.Add(), ast.Constant(steps)),
                            ),
                            *body,
                            ast.Continue(),
                        ],
                        [],
                    ),
                ],
                handlers=[ast.ExceptHandler(_name(c.constant(Exception)), None, restore)],
                orelse=[],
                finalbody=[],
            ),
        ]
        per_item = ast.If(_all([room, *item_test]), typed_iteration, [])
        guarded_iteration = [
            ast.Assign([_name(ok, store=True)], ast.Constant(-1)),
            ast.Assign([_name(variable, store=True)], _name(item)),
            *copy.deepcopy(generic_body),
        ]
        typed_loop = ast.For(
            _name(item, store=True),
            _name(iterable_temp),
            [per_item, *guarded_iteration],
            copy.deepcopy(orelse),
        )
        limit = ast.BinOp(
            ast.Attribute(budget, "next_check", ast.Load()), ast.Sub(), ast.Constant(steps)
        )
        prelude = [*self.hoisted_code, ast.Assign([_name(ok, store=True)], limit)]
        guarded_loop = ast.For(
            _name(variable, store=True), _name(iterable_temp), generic_body, orelse
        )
        entry = self._entry_tests()
        test = _all(entry) if entry else ast.Constant(True)
        typed = self._stamp(ast.If(test, [*prelude, typed_loop], [guarded_loop]))
        return [self._stamp(ast.Assign([_name(iterable_temp, store=True)], iterable)), typed]

    def _static_items(self):
        """The items of a loop over float constants the function itself holds
        (``for u, f in zip(uu, ff)`` with ``uu = [0.2, 0.15]`` and ``ff`` as
        such, see FunctionCompiler.float_lists), or None. Such a loop runs
        over these very values, known when compiling: the iterable itself
        (the builtin ``zip`` of those lists, no effect) is then left
        unevaluated by the typed loop."""
        c = self.compiler
        _, iterable, _, _ = self.node.children
        body = c.function.body.children
        position = next((i for i, s in enumerate(body) if s is self.node), None)
        if position is None:
            return None

        def values(argument):
            if argument.data != "var":
                return None
            held = c.float_lists.get(argument.children[0].value)
            return held[1] if held is not None and held[0] < position else None

        single = self.node.children[0].data == "var"
        if iterable.data == "var":
            return values(iterable) if single else None
        if iterable.data != "funccall" or iterable.children[0].data != "var":
            return None
        callee, arguments = iterable.children
        if callee.children[0].value != "zip" or "zip" in c.local_names:
            return None
        if self.namespace.get("zip") is not zip or arguments is None:
            return None
        if arguments.data != "arguments" or single:
            return None
        columns = [values(argument) for argument in arguments.children]
        if not columns or None in columns or len(columns) != len(self.targets):
            return None
        self._callee("zip", zip)  # the name still holds the builtin when the loop starts
        return tuple(zip(*columns, strict=False))  # as the deck's zip: the shortest

    def _counted_loop(self, iterable, variable, generic_body, orelse, body, items):
        """The typed loop over a known count of float items: room for every
        iteration's steps is tested once, before the loop; the steps are
        given to the budget when the loop ends or an iteration runs guarded
        (nothing reads them in between: typed bodies call nothing that
        counts)."""
        c = self.compiler
        steps = 1 + self.calls
        item, done, base, saved = c.temp(), c.temp(), c.temp(), c.temp()
        budget = _name("__b")
        if len(self.targets) == 1 and self.node.children[0].data == "var":
            bind = ast.Assign([_name(self.targets[0], store=True)], _name(item))
        else:
            store = ast.Tuple([_name(n, store=True) for n in self.targets], ast.Store())
            bind = ast.Assign([store], _name(item))
        carried = sorted(self.assigned - set(self.targets))
        snapshot, restore = [], []
        if carried:
            held = ast.Tuple([_name(n, store=True) for n in carried], ast.Store())
            current = ast.Tuple([_name(n) for n in carried], ast.Load())
            if len(carried) == 1:
                held, current = _name(carried[0], store=True), _name(carried[0])
            snapshot.append(ast.Assign([_name(saved, store=True)], current))
            restore.append(ast.Assign([held], _name(saved)))
        typed_done = ast.Compare(_name(done), [ast.GtE()], [ast.Constant(0)])
        settle = ast.If(
            typed_done,
            [
                ast.Assign(
                    [ast.Attribute(budget, "steps", ast.Store())],
                    ast.BinOp(
                        _name(base),
                        ast.Add(),
                        ast.BinOp(_name(done), ast.Mult(), ast.Constant(steps)),
                    ),
                ),
                ast.Assign([_name(done, store=True)], ast.Constant(-1)),
            ],
            [],
        )
        typed_iteration = [
            *snapshot,
            ast.Try(
                body=[
                    bind,
                    *body,
                    ast.AugAssign(_name(done, store=True), ast.Add(), ast.Constant(1)),
                    ast.Continue(),
                ],
                handlers=[ast.ExceptHandler(_name(c.constant(Exception)), None, restore)],
                orelse=[],
                finalbody=[],
            ),
        ]
        count = len(items)
        loop = ast.For(
            _name(item, store=True),
            _name(c.constant(items)),
            [
                ast.If(typed_done, typed_iteration, []),
                copy.deepcopy(settle),  # this iteration and the following run guarded
                ast.Assign([_name(variable, store=True)], _name(item)),
                *copy.deepcopy(generic_body),
            ],
            [copy.deepcopy(settle), *copy.deepcopy(orelse)] if orelse else [],
        )
        room = ast.Compare(
            ast.BinOp(
                ast.Attribute(budget, "steps", ast.Load()),
                ast.Add(),
                ast.Constant(steps * count),
            ),
            [ast.Lt()],
            [ast.Attribute(budget, "next_check", ast.Load())],
        )
        prelude = [
            *self.hoisted_code,
            ast.Assign([_name(base, store=True)], ast.Attribute(budget, "steps", ast.Load())),
            ast.Assign([_name(done, store=True)], ast.Constant(0)),
        ]
        guarded_loop = ast.For(_name(variable, store=True), iterable, generic_body, orelse)
        test = _all([*self._entry_tests(), room])
        return [self._stamp(ast.If(test, [*prelude, loop, settle], [guarded_loop]))]

    def _entry_tests(self) -> list:
        tests = [_type_is(_name(n), "__FL") for n in [*self.invariant_locals, *self.carried]]
        for name, temp in self.globals.items():
            value = ast.NamedExpr(_name(temp, store=True), self._read_global(name))
            tests.append(_type_is(value, "__FL"))
        for name, closure_name in self.callees.items():
            current = self._read_global(name)
            tests.append(ast.Compare(current, [ast.Is()], [_name(closure_name)]))
        if self.inlines:
            depth = ast.Attribute(_name("__b"), "depth", ast.Load())
            limit = ast.Constant(self.evaluator.budget.max_depth)
            tests.append(ast.Compare(depth, [ast.Lt()], [limit]))
        return tests

    def _read_global(self, name: str) -> ast.expr:
        """The deck name's current value, or None (never an error here: the
        guarded loop reports a missing name where it is read)."""
        get = self.compiler.constant(self.compiler.namespace_get)
        return ast.Call(_name(get), [ast.Constant(name)], [])

    # ------------------------------------------------------------ analysis

    def _targets(self, target) -> None:
        if target.data == "var":
            self.targets = [target.children[0].value]
        elif target.data in ("tuple", "list") and all(t.data == "var" for t in target.children):
            self.targets = [t.children[0].value for t in target.children]
        else:
            raise Refused("loop target")

    def _collect_assigned(self, suite) -> None:
        pending = [suite]
        while pending:
            node = pending.pop()
            if not hasattr(node, "data"):
                continue
            if node.data in ("assign", "augassign"):
                targets = node.children[:-1] if node.data == "assign" else node.children[:1]
                for target in targets:
                    if target.data != "var":
                        raise Refused("typed loop: store into a container")
                    self.assigned.add(target.children[0].value)
            pending.extend(child for child in node.children if hasattr(child, "data"))

    # ---------------------------------------------------------- statements

    def suite(self, suite, env: dict) -> list:
        statements = []
        for child in suite.children:
            statements.extend(self.statement(child, env))
        return statements

    def statement(self, node, env: dict) -> list:
        if not hasattr(node, "data"):
            return []
        kind = node.data
        if kind == "simple_stmt":
            return [s for child in node.children for s in self.statement(child, env)]
        if kind == "pass_stmt":
            return [ast.Pass()]
        if kind == "assign":
            if len(node.children) != 2:
                raise Refused("typed loop: chained assignment")
            target, value_node = node.children
            value = self.shared(self.float_value(value_node, env))
            env[target.children[0].value] = FLOAT
            return [self._stamp(ast.Assign([_name(target.children[0].value, store=True)], value))]
        if kind == "augassign":
            target, op_token, value_node = node.children
            name, symbol = target.children[0].value, op_token.value[:-1]
            if symbol not in BINARY or symbol == "**":
                raise Refused("typed loop: operator")
            current = self.name(name, env)
            value = self.expr(value_node, env)
            if current.kind != FLOAT or value.kind not in (FLOAT, INT):
                raise Refused("typed loop: operand types")
            env[name] = FLOAT
            update = ast.AugAssign(
                _name(name, store=True), BINARY[symbol](), self.shared(value.expression)
            )
            return [self._stamp(update)]
        if kind == "if_stmt":
            return self._if(node, env)
        raise Refused(f"typed loop: {kind}")

    def _if(self, node, env: dict) -> list:
        branches, otherwise = if_branches(node)
        outer, self.in_branch = self.in_branch, True
        outcomes, built = [], []
        for test_node, body_node in branches:
            test = self.expr(test_node, env)
            if test.kind != BOOL:
                raise Refused("typed loop: test")
            branch_env = dict(env)
            built.append((test.expression, self.suite(body_node, branch_env) or [ast.Pass()]))
            outcomes.append(branch_env)
        else_env = dict(env)
        orelse = self.suite(otherwise, else_env) if otherwise is not None else []
        outcomes.append(else_env)
        self.in_branch = outer
        for name in list(set().union(*outcomes)):
            if all(name in o for o in outcomes):
                env[name] = FLOAT
        for test, body in reversed(built):
            orelse = [self._stamp(ast.If(test, body, orelse))]
        return orelse

    def shared(self, expression: ast.expr) -> ast.expr:
        """``expression`` computing each repeated operation once: the first
        one evaluated keeps its value in a temporary (a walrus), the others
        read it. Typed operations have no effect and read no name an
        expression assigns, so the values are the same; branches (inlined
        bodies) are left whole."""
        kinds = (ast.BinOp, ast.Call, ast.UnaryOp)
        counts: dict[str, int] = {}
        pending = [expression]
        while pending:  # in evaluation order; a repeat's own operands are not counted
            node = pending.pop()
            if isinstance(node, ast.IfExp):
                continue
            if isinstance(node, kinds):
                key = ast.dump(node)
                counts[key] = counts.get(key, 0) + 1
                if counts[key] > 1:
                    continue
            pending.extend(reversed(list(ast.iter_child_nodes(node))))
        repeated = {key for key, count in counts.items() if count > 1}
        if not repeated:
            return expression
        held: dict[str, str] = {}

        def visit(node):
            if isinstance(node, ast.IfExp) or not isinstance(node, kinds):
                return node
            key = ast.dump(node)
            if key in held:
                return _name(held[key])
            if isinstance(node, ast.BinOp):  # operands first, left to right
                node = ast.BinOp(visit(node.left), node.op, visit(node.right))
            elif isinstance(node, ast.UnaryOp):
                node = ast.UnaryOp(node.op, visit(node.operand))
            else:
                node = ast.Call(node.func, [visit(a) for a in node.args], [])
            if key in repeated:
                held[key] = self.compiler.temp()
                return ast.NamedExpr(_name(held[key], store=True), node)
            return node

        return visit(expression)

    # --------------------------------------------------------- expressions

    def float_value(self, node, env: dict) -> ast.expr:
        value = self.expr(node, env)
        if value.kind != FLOAT:
            raise Refused("typed loop: not a float")
        return value.expression

    def name(self, name: str, env: dict) -> Typed:
        c = self.compiler
        if name in env:
            return Typed(_name(name), env[name], invariant=name in self.invariant_locals)
        if name in self.assigned:  # carried from the previous iteration
            if name not in self.carried:
                self.carried.append(name)
            env[name] = FLOAT
            return Typed(_name(name), FLOAT)
        if name in c.local_names:
            if name not in self.invariant_locals:
                self.invariant_locals.append(name)
            return Typed(_name(name), FLOAT, invariant=True)
        if name not in self.globals:
            self.globals[name] = c.temp()
        return Typed(_name(self.globals[name]), FLOAT, invariant=True)

    def expr(self, node, env: dict) -> Typed:
        kind = node.data
        if kind == "const":
            value = node.children[0]
            if type(value) is float:
                return Typed(ast.Constant(value), FLOAT, invariant=True)
            if type(value) is int and abs(value) <= EXACT_INT:  # converts without raising
                return Typed(ast.Constant(value), INT, invariant=True)
            raise Refused("typed loop: constant")
        if kind == "var":
            if isinstance(env, _Parameters):
                return env.lookup(node.children[0].value)
            return self.name(node.children[0].value, env)
        if kind == "unary":
            op, operand = node.children
            inner = self.expr(operand, env)
            if op.value not in "+-" or inner.kind not in (FLOAT, INT):
                raise Refused("typed loop: unary")
            if inner.kind == INT and not isinstance(inner.expression, ast.Constant):
                raise Refused("typed loop: int")
            operator = ast.USub() if op.value == "-" else ast.UAdd()
            return Typed(
                ast.UnaryOp(operator, inner.expression), inner.kind, inner.raises, inner.calls
            )
        if kind in ("arith_expr", "term"):
            children = node.children
            value = self.expr(children[0], env)
            for position in range(1, len(children), 2):
                right = self.expr(children[position + 1], env)
                value = self._binary(children[position].value, value, right)
            return value
        if kind == "power":
            base, exponent = (self.expr(child, env) for child in node.children)
            integral = (
                isinstance(exponent.expression, ast.Constant)
                and float(exponent.expression.value).is_integer()
            )
            if base.kind != FLOAT or exponent.kind not in (FLOAT, INT) or not integral:
                raise Refused("typed loop: power")
            expression = ast.BinOp(base.expression, ast.Pow(), exponent.expression)
            return Typed(expression, FLOAT, True, base.calls + exponent.calls)
        if kind == "comparison" and len(node.children) == 3:
            left, op_node, right_node = node.children
            op = "".join(token.value for token in op_node.children)
            left, right = self.expr(left, env), self.expr(right_node, env)
            if op not in COMPARE or FLOAT not in (left.kind, right.kind):
                raise Refused("typed loop: comparison")
            if {left.kind, right.kind} - {FLOAT, INT}:
                raise Refused("typed loop: comparison")
            expression = ast.Compare(left.expression, [COMPARE[op]()], [right.expression])
            raises = left.raises or right.raises
            return Typed(expression, BOOL, raises, left.calls + right.calls)
        if kind == "funccall":
            return self._call(node, env)
        raise Refused(f"typed loop: {kind}")

    def _binary(self, op: str, left: Typed, right: Typed) -> Typed:
        if op not in BINARY or op == "**" or FLOAT not in (left.kind, right.kind):
            raise Refused("typed loop: operator")
        if {left.kind, right.kind} - {FLOAT, INT}:
            raise Refused("typed loop: operand types")
        raises = left.raises or right.raises
        if op not in NON_RAISING:  # by zero
            divisor = right.expression
            raises = raises or not (isinstance(divisor, ast.Constant) and divisor.value != 0)
        expression = ast.BinOp(left.expression, BINARY[op](), right.expression)
        calls = left.calls + right.calls
        if left.invariant and right.invariant and not raises and not self.in_inline:
            key = ("value", ast.dump(expression))
            if key not in self.hoisted:  # computed once, before the loop
                self.hoisted[key] = temp = self.compiler.temp()
                assign = ast.Assign([_name(temp, store=True)], expression)
                self.hoisted_code.append(self._stamp(assign))
            return Typed(_name(self.hoisted[key]), FLOAT, False, calls, invariant=True)
        return Typed(expression, FLOAT, raises, calls)

    def _call(self, node, env: dict) -> Typed:
        callee_node, arguments = node.children
        if isinstance(env, _Parameters):
            raise Refused("inline: calls")
        if callee_node.data != "var" or (arguments is not None and arguments.data != "arguments"):
            raise Refused("typed loop: call")
        items = [] if arguments is None else arguments.children
        if any(
            getattr(item, "data", None) in ("kwarg", "star_arg", "double_star_arg")
            for item in items
        ):
            raise Refused("typed loop: keywords")
        name = callee_node.children[0].value
        if name in self.compiler.local_names or name not in self.namespace:
            raise Refused("typed loop: callee")
        callee = self.namespace[name]
        if _hashable(callee) and callee in PURE_FLOAT_FUNCTIONS:
            args = [self.expr(item, env) for item in items]
            if any(a.kind not in (FLOAT, INT) for a in args):
                raise Refused("typed loop: argument")
            function = ast.Call(_name(self._callee(name, callee)), [a.expression for a in args], [])
            return Typed(function, FLOAT, True, sum(a.calls for a in args))
        if type(callee) is self.compiler.runtime.deck_function_type:
            return self._inline(name, callee, items, env)
        raise Refused("typed loop: callee")

    def _callee(self, name: str, callee) -> str:
        if name not in self.callees:
            self.callees[name] = self.compiler.constant(callee)
        return self.callees[name]

    def _inline(self, name: str, function, items, env: dict) -> Typed:
        """A small deck function's body as one conditional expression."""
        if (
            self.in_branch
            or function.evaluator is not self.evaluator
            or function.closure.locals is not None
            or len(items) != len(function.parameters)
        ):
            raise Refused("typed loop: deck call")
        args = []
        for item in items:
            if item.data not in ("var", "const"):
                raise Refused("typed loop: argument")
            args.append(self.expr(item, env))
        if any(a.kind != FLOAT for a in args):
            raise Refused("typed loop: argument")
        parameters = {p: a for p, a in zip(function.parameters, args, strict=True)}
        outer, self.in_inline = self.in_inline, True
        try:
            if function.is_lambda:
                inlined = _Inliner(self, parameters).expr(function.body)
            else:
                inlined = _Inliner(self, parameters).body(function.body.children)
        finally:
            self.in_inline = outer
        if inlined.kind != FLOAT:
            raise Refused("typed loop: deck call result")
        self._callee(name, function)
        self.inlines = True
        self.calls += 1
        if all(a.invariant for a in args) and not inlined.raises:  # computed once, before the loop
            key = (name, *(ast.dump(a.expression) for a in args))
            if key not in self.hoisted:
                temp = self.compiler.temp()
                self.hoisted[key] = temp
                self.hoisted_code.append(
                    self._stamp(ast.Assign([_name(temp, store=True)], inlined.expression))
                )
            return Typed(_name(self.hoisted[key]), FLOAT, False, 1, invariant=True)
        return Typed(inlined.expression, FLOAT, inlined.raises, 1)

    def _stamp(self, statement):
        return _stamp(statement, self.line)


class _Inliner:
    """The typed expression of a deck function body made of ``if test:
    return value`` branches and returns, its parameters bound to typed
    arguments; it reads nothing but its parameters and constants."""

    def __init__(self, loop: FastLoop, parameters: dict):
        self.loop = loop
        self.parameters = parameters

    def expr(self, node) -> Typed:
        return self.loop.expr(node, _Parameters(self.parameters))

    def body(self, statements) -> Typed:
        statements = [s for s in statements if hasattr(s, "data")]
        if not statements:
            raise Refused("inline: falls off")
        first, rest = statements[0], statements[1:]
        if first.data == "simple_stmt" and len(first.children) == 1:
            first = first.children[0]
        if first.data == "return_stmt":
            value = first.children[-1]
            if value is None:
                raise Refused("inline: returns None")
            return self.expr(value)
        if first.data != "if_stmt":
            raise Refused(f"inline: {first.data}")
        branches, otherwise = if_branches(first)
        if otherwise is not None:
            if rest:
                raise Refused("inline: code after if/else")
            result = self.body(otherwise.children)
        else:
            result = self.body(rest)
        for test_node, suite_node in reversed(branches):
            test = self.expr(test_node)
            value = self.body(suite_node.children)
            if test.kind != BOOL or value.kind != FLOAT or result.kind != FLOAT:
                raise Refused("inline: types")
            raises = test.raises or value.raises or result.raises
            expression = ast.IfExp(test.expression, value.expression, result.expression)
            result = Typed(expression, FLOAT, raises)
        return result


class _Parameters(dict):
    """The environment of an inlined body: its parameters only."""

    def __init__(self, parameters: dict):
        super().__init__()
        self.bound = parameters

    def lookup(self, name: str) -> Typed:
        if name not in self.bound:
            raise Refused("inline: reads a deck name")
        argument = self.bound[name]
        return Typed(copy.deepcopy(argument.expression), argument.kind)


def _hashable(value) -> bool:
    """Whether ``value`` may be looked up in a set (deck values may not be
    hashable, or hash through deck-visible code)."""
    return isinstance(value, (types.BuiltinFunctionType, types.FunctionType))
