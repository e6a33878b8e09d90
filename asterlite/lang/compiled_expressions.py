"""Expressions of deck functions as guarded Python ``ast`` (the expression
half of :class:`asterlite.lang.compiler.FunctionCompiler`).

Each operation runs natively only when its operand types make every guard
of the interpreter moot (see :meth:`ExpressionCompiler._binary_guard`),
else it calls the interpreter's own code through the compiled runtime."""

from __future__ import annotations

import ast

from asterlite.lang.compiled_ast import (
    BINARY,
    COMPARE,
    NUMBERS,
    UNARY,
    Either,
    Operand,
    Refused,
    _all,
    _call,
    _chain,
    _is,
    _name,
    _stamp,
    _type_in,
    _type_is,
)
from asterlite.lang.compiled_runtime import PLAIN_CALLABLES, PLAIN_SCALARS
from asterlite.lang.library import DIRECT, DeckModule


class ExpressionCompiler:
    """Mixed into FunctionCompiler, which provides ``line``, ``temp``,
    ``definite``, ``local_names``, ``float_locals``, ``global_reads``,
    ``sites`` and ``frame``."""

    def expr(self, node, assigned_name=None) -> ast.expr:
        kind = node.data
        method = getattr(self, f"_e_{kind}", None)
        if method is None:
            raise Refused(kind)
        line = self.line(node)
        if kind == "funccall":
            return _stamp(self._e_funccall(node, line, assigned_name), line)
        return _stamp(method(node, line), line)

    def operand(self, node) -> Operand:
        if node.data == "const":
            return Operand(ast.Constant(node.children[0]), type(node.children[0]), simple=True)
        if node.data in ("const_none", "const_true", "const_false"):
            value = {"const_none": None, "const_true": True, "const_false": False}[node.data]
            return Operand(ast.Constant(value), type(value), simple=True)
        if node.data == "unary" and node.children[0].value in "+-":  # -0.2: a constant
            inner = node.children[1]
            if inner.data == "const" and type(inner.children[0]) in NUMBERS:
                value = inner.children[0]
                value = -value if node.children[0].value == "-" else +value
                return Operand(ast.Constant(value), type(value), simple=True)
        if node.data == "var" and node.children[0].value in self.definite:
            name = node.children[0].value
            static = float if name in self.float_locals else None
            return Operand(self.expr(node), static, simple=True)
        return self.operand_ast(self.expr(node))

    def operand_ast(self, expression: ast.expr) -> Operand:
        if isinstance(expression, ast.Name) and expression.id in self.definite:
            return Operand(expression, simple=True)
        return Operand(expression, temp=self.temp())

    def guarded(self, operands, tests, fast, slow) -> ast.expr:
        """``fast(refs)`` when ``tests(refs)`` hold, else ``slow(refs)``; each
        operand evaluated once, in order. ``tests`` None: always slow; []:
        always fast (operands inline)."""
        if tests is None:
            return slow([o.expression for o in operands])
        if tests == []:
            return fast([o.expression for o in operands])
        if isinstance(tests, Either):
            return self._either(operands, tests, fast, slow)
        bindings = [o.binding() for o in operands if not o.simple]
        checks = tests([o.ref() for o in operands])
        if bindings:
            checks.insert(0, _chain(bindings))
        return ast.IfExp(
            _all(checks), fast([o.ref() for o in operands]), slow([o.ref() for o in operands])
        )

    def _either(self, operands, either: Either, fast, slow) -> ast.expr:
        """``fast`` when the checked operand (or either one) has a safe type:
        operands bound in order, the second check skipped once one holds."""
        left, right = operands

        def check(expression):
            if either.kinds == "__FL":
                return _type_is(expression, "__FL")
            return _type_in(expression, either.kinds)

        def bound(operand):
            return operand.ref() if operand.simple else operand.binding()

        def evaluated(operand):
            return ast.Compare(operand.binding(), [ast.IsNot()], [_name("__S")])

        if either.side == "left":
            if right.simple:
                test = check(bound(left))
            elif left.simple:
                test = _all([evaluated(right), check(left.ref())])
            else:
                test = _all([_chain([left.binding(), right.binding()]), check(left.ref())])
        elif either.side == "right":
            test = (
                check(bound(right)) if left.simple else _all([evaluated(left), check(bound(right))])
            )
        elif left.simple:
            test = ast.BoolOp(ast.Or(), [check(bound(right)), check(left.ref())])
        elif right.simple:
            test = ast.BoolOp(ast.Or(), [check(left.binding()), check(right.ref())])
        else:
            either_one = ast.BoolOp(ast.Or(), [check(right.binding()), check(left.ref())])
            test = _all([evaluated(left), either_one])
        refs = [o.ref() for o in operands]
        return ast.IfExp(test, fast(refs), slow([o.ref() for o in operands]))

    def _e_const(self, node, line):
        return ast.Constant(node.children[0])

    def _e_const_none(self, node, line):
        return ast.Constant(None)

    def _e_const_true(self, node, line):
        return ast.Constant(True)

    def _e_const_false(self, node, line):
        return ast.Constant(False)

    def _e_var(self, node, line):
        return self.read(node, line)

    def read(self, node, line=None) -> ast.expr:
        name = node.children[0].value
        if name in self.definite:
            return _name(name)
        if line is None:
            line = self.line(node)
        self.global_reads[line] = name
        from_namespace = _stamp(ast.Subscript(_name("__G"), ast.Constant(name), ast.Load()), line)
        if name not in self.local_names:
            return from_namespace
        unbound = ast.Compare(_name(name), [ast.IsNot()], [_name("__UNB")])
        return _stamp(ast.IfExp(unbound, _name(name), from_namespace), line)

    def _e_tuple(self, node, line):
        return ast.Tuple([self.expr(child) for child in node.children], ast.Load())

    def _e_list(self, node, line):
        return ast.List([self.expr(child) for child in node.children], ast.Load())

    def _e_set(self, node, line):
        return ast.Set([_call("__rt_key", self.expr(child)) for child in node.children])

    def _e_dict(self, node, line):
        keys, values = [], []
        for pair in node.children:
            keys.append(_call("__rt_key", self.expr(pair.children[0])))
            values.append(self.expr(pair.children[1]))
        return ast.Dict(keys, values)

    def _e_or_test(self, node, line):
        return ast.BoolOp(ast.Or(), [self.expr(child) for child in node.children])

    def _e_and_test(self, node, line):
        return ast.BoolOp(ast.And(), [self.expr(child) for child in node.children])

    def _e_not_(self, node, line):
        value = self.operand(node.children[0])
        test = _is(value.binding() if not value.simple else value.ref(), _name("__U"))
        return ast.IfExp(test, _name("__U"), ast.UnaryOp(ast.Not(), value.ref()))

    def _e_ternary(self, node, line):
        if_true, condition, if_false = node.children
        test = self.operand(condition)
        unknown = _is(test.binding() if not test.simple else test.ref(), _name("__U"))
        chosen = ast.IfExp(test.ref(), self.expr(if_true), self.expr(if_false))
        return ast.IfExp(unknown, _name("__U"), chosen)

    def _e_comparison(self, node, line):
        children = node.children
        left = self.operand(children[0])
        pairs = []
        for position in range(1, len(children), 2):
            op = "".join(token.value for token in children[position].children)
            pairs.append((op, children[position + 1]))
        return self._compare_chain(left, pairs)

    def _compare_chain(self, left: Operand, pairs) -> ast.expr:
        op, right_node = pairs[0]
        right = self.operand(right_node)
        if len(pairs) == 1:
            return self._compare(op, left, right)
        # a < b < c: the middle operand is kept for the next link; the chain
        # stops at the first falsy link (Unknown included), as the interpreter does
        if right.simple:
            middle, following = right, Operand(right.ref(), right.static, simple=True)
        else:
            held = self.temp()
            bound = ast.NamedExpr(_name(held, store=True), right.expression)
            middle = Operand(bound, temp=self.temp())
            following = Operand(_name(held), simple=True)
        first = self._compare(op, left, middle)
        rest = self._compare_chain(following, pairs[1:])
        result = self.temp()
        test = ast.UnaryOp(ast.Not(), ast.NamedExpr(_name(result, store=True), first))
        return ast.IfExp(test, _name(result), rest)

    def _compare(self, op: str, left: Operand, right: Operand) -> ast.expr:
        def slow(refs):
            return _call("__rt_compare", ast.Constant(op), *refs)

        def fast(refs):
            return ast.Compare(refs[0], [COMPARE[op]()], [refs[1]])

        if op not in COMPARE:
            tests = None
        elif left.static is not None or right.static is not None:
            tests = []  # a scalar constant: nothing to broadcast, nothing to size
        else:
            tests = Either("__CM")
        return self.guarded([left, right], tests, fast, slow)

    def _binary_guard(self, op: str, left: Operand, right: Operand):
        """When ``left op right`` may run natively: None never (the
        interpreter's code), [] always, or an :class:`Either` test."""
        if op not in BINARY:
            return None
        statics = [t for t in (left.static, right.static) if t is not None]
        if any(t not in NUMBERS for t in statics):
            return None  # str, bool, None, complex constants: the guarded path
        if op == "%":  # only a string on the left formats
            return [] if left.static is not None else Either("__IF", "left")
        if op in ("*", "**"):  # repetition, integer growth: a float operand is needed
            if float in statics:
                return []
            if left.static is int:
                return Either("__FL", "right")
            if right.static is int:
                return Either("__FL", "left")
            return Either("__FL")
        return [] if statics else Either("__IF")  # + - / //: two sequences or arrays only

    def binary(self, op: str, left: Operand, right: Operand) -> ast.expr:
        return self.guarded(
            [left, right],
            self._binary_guard(op, left, right),
            lambda refs: ast.BinOp(refs[0], BINARY[op](), refs[1]),
            lambda refs: _call("__rt_binary", ast.Constant(op), *refs),
        )

    def _e_arith_expr(self, node, line):
        children = node.children
        value = self.operand(children[0])
        for position in range(1, len(children), 2):
            right = self.operand(children[position + 1])
            result = self.binary(children[position].value, value, right)
            if position + 2 < len(children):
                result = _stamp(result, line)
            value = self.operand_ast(result)
        return value.expression

    _e_term = _e_arith_expr

    def _bitwise(self, node, op: str):
        value = self.expr(node.children[0])
        for child in node.children[1:]:
            value = _call("__rt_binary", ast.Constant(op), value, self.expr(child))
        return value

    def _e_or_expr(self, node, line):
        return self._bitwise(node, "|")

    def _e_xor_expr(self, node, line):
        return self._bitwise(node, "^")

    def _e_and_expr(self, node, line):
        return self._bitwise(node, "&")

    def _e_power(self, node, line):
        return self.binary("**", self.operand(node.children[0]), self.operand(node.children[1]))

    def _e_unary(self, node, line):
        op, operand_node = node.children
        # Unknown's own operators give Unknown: the interpreter's result
        return ast.UnaryOp(UNARY[op.value](), self.expr(operand_node))

    def _e_getattr(self, node, line):
        value = self.operand(node.children[0])
        name = ast.Constant(node.children[1].value)
        # a member of a loaded deck module (NU.pi), as the runtime's
        # attribute() reads it; anything else through the whitelists
        members = self.temp()
        module = self.constant(DeckModule)
        test = [
            _type_is(value.ref() if value.simple else value.binding(), module),
            ast.Compare(
                ast.NamedExpr(
                    _name(members, store=True), ast.Attribute(value.ref(), "_members", ast.Load())
                ),
                [ast.IsNot()],
                [ast.Constant(None)],
            ),
            ast.Compare(name, [ast.In()], [_name(members)]),
        ]
        member = ast.Subscript(_name(members), ast.Constant(name.value), ast.Load())
        slow = _call("__rt_attribute", value.ref(), ast.Constant(name.value))
        return ast.IfExp(_all(test), member, slow)

    def index(self, node, keyed: bool = True) -> ast.expr:
        """The index of a subscript: a slice, a tuple of parts, or a value
        (checked by ``_key`` when ``keyed``)."""
        if node.data == "slice":  # located with the subscript, as the interpreter does
            bounds = [ast.Constant(None) if p is None else self.expr(p) for p in node.children]
            return _call("__rt_slice", *bounds)
        if node.data == "subscript_tuple":
            return _call("__rt_index_tuple", *[self.index(child) for child in node.children])
        value = self.expr(node)
        return _call("__rt_key", value) if keyed else value

    def _e_getitem(self, node, line):
        container_node, index_node = node.children
        if index_node.data in ("slice", "subscript_tuple"):
            container = self.expr(container_node)
            return _call("__rt_item", container, self.index(index_node, keyed=False))
        container = self.operand(container_node)
        index = self.operand(index_node)
        if index.static is int:
            tests = []
        elif index.static is not None:
            tests = None
        else:

            def tests(refs):
                return [_type_is(refs[1], "__IN")]

        return self.guarded(
            [container, index],
            tests,
            lambda refs: ast.Subscript(refs[0], refs[1], ast.Load()),
            lambda refs: _call("__rt_keyed_item", *refs),
        )

    # ---------------------------------------------------------------- calls

    def _e_funccall(self, node, line, assigned_name=None):
        callee_node, arguments = node.children
        self.sites.append((node, self.frame))
        site = ast.Subscript(_name("__sites"), ast.Constant(len(self.sites) - 1), ast.Load())
        items = [] if arguments is None else arguments.children
        if arguments is not None and arguments.data != "arguments":
            raise Refused(arguments.data)
        kinds = [getattr(item, "data", None) for item in items]
        if any(k in ("kwarg", "star_arg", "double_star_arg") for k in kinds):
            return self._call_with_keywords(callee_node, items, site, assigned_name)
        callee = self.operand(callee_node)
        args = [self.operand(item) for item in items]
        operands = [callee, *args]
        bindings = [o.binding() for o in operands if not o.simple]
        refs = [o.ref() for o in operands]
        count = len(args)

        def refs_again():
            return [o.ref() for o in operands]

        direct = ast.Call(ast.Attribute(refs[0], "direct", ast.Load()), refs_again()[1:], [])
        is_deck_function = [
            _type_is(refs_again()[0], "__DF"),
            ast.Compare(
                ast.Attribute(refs_again()[0], "arity", ast.Load()),
                [ast.Eq()],
                [ast.Constant(count)],
            ),
        ]
        plain_tests = [_type_in(refs_again()[0], "__PC")]
        for arg, ref in zip(args, refs_again()[1:], strict=True):
            if arg.static is None:
                plain_tests.append(_type_in(ref, "__SC"))
            elif arg.static not in PLAIN_SCALARS:
                plain_tests = None
                break
        slow = _call(
            "__rt_call",
            site,
            refs_again()[0],
            ast.Tuple(refs_again()[1:], ast.Load()),
            ast.Constant(assigned_name),
        )
        fallback = slow
        if plain_tests is not None:
            plain = ast.Call(refs_again()[0], refs_again()[1:], [])
            fallback = ast.IfExp(_all(plain_tests), plain, slow)
        tests = is_deck_function
        known = self._known_structural_callee(callee_node)
        if known is not None:  # zip, len, enumerate...: a call as _call_python makes it
            fast = [ast.Compare(refs_again()[0], [ast.Is()], [_name(known)])]
            fast += [
                ast.Compare(ref, [ast.IsNot()], [_name("__U")])
                for arg, ref in zip(args, refs_again()[1:], strict=True)
                if arg.static is None
            ]
            if bindings:
                fast.insert(0, _chain(bindings))
            plain = ast.Call(refs_again()[0], refs_again()[1:], [])
            return ast.IfExp(_all(fast), plain, ast.IfExp(_all(tests), direct, fallback))
        if bindings:
            tests = [_chain(bindings), *tests]
        return ast.IfExp(_all(tests), direct, fallback)

    def _known_structural_callee(self, callee_node):
        """The closure name of the deck name's value when compiling, if it is a
        plain Python callable the interpreter calls directly once no argument
        is Unknown (``zip``, ``len``, ``map``: structural builtins); the
        call site tests that the name still holds that very object."""
        if callee_node.data != "var":
            return None
        name = callee_node.children[0].value
        if name in self.local_names or name not in self.evaluator.namespace:
            return None
        value = self.evaluator.namespace[name]
        if type(value) not in PLAIN_CALLABLES:
            return None
        if hasattr(type(getattr(value, "__self__", None)), "deck_methods"):
            return None  # a concept's method: its arguments' nesting is checked
        if self.evaluator._unknown_policy(value) != DIRECT:
            return None
        return self.constant(value)

    def _call_with_keywords(self, callee_node, items, site, assigned_name):
        for position, item in enumerate(items):
            kind = getattr(item, "data", None)
            if kind in ("star_arg", "double_star_arg") and position != len(items) - 1:
                raise Refused("spread argument before other arguments")
        callee = self.expr(callee_node)
        pieces = []
        for item in items:
            kind = getattr(item, "data", None)
            if kind == "kwarg":
                key, value = item.children
                piece = ("kwarg", key.children[0].value, self.expr(value))
            elif kind in ("star_arg", "double_star_arg"):
                piece = (kind, None, self.expr(item.children[0]))
            else:
                piece = ("arg", None, self.expr(item))
            pieces.append(
                ast.Tuple([ast.Constant(piece[0]), ast.Constant(piece[1]), piece[2]], ast.Load())
            )
        return _call(
            "__rt_call_kw",
            site,
            callee,
            ast.Tuple(pieces, ast.Load()),
            ast.Constant(assigned_name),
        )
