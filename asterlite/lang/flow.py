"""``try``, ``raise``, ``with``, f-strings and Python 2's print statement and
backquotes: the evaluator's half that runs them (mixed into
:class:`asterlite.lang.evaluator.Evaluator`).

Which errors a deck may catch is decided in :mod:`asterlite.lang.exceptions`.
Errors that end the run (limits, interruptions, refusals, asterlite's own
errors) pass every ``except``, and neither ``finally`` blocks nor ``with``
exits run for them: the run is over.

``with`` takes only the context managers asterlite provides (an object
whose type has ``deck_enter``/``deck_exit``: ``CA.disable_fpe()``,
``TestCase.assertRaises(...)``); Python's ``__enter__``/``__exit__`` of any
other object are never called.

Compiled deck functions never contain these statements (the compiler
refuses them), so the interpreter runs them.
"""

from __future__ import annotations

from asterlite.errors import AsterliteError, DeckRuntimeError
from asterlite.lang import fstrings
from asterlite.lang import limits as guards
from asterlite.lang.exceptions import (
    CaughtError,
    DeckRaised,
    ExceptionClass,
    RaisedException,
    classify,
    ends_run,
    matches,
    python_error,
)
from asterlite.lang.values import Unknown


class FlowStatements:
    """Mixed into the Evaluator (which provides ``ev``, ``_exec_suite``,
    ``_store``, ``_assign_target``, ``location``, ``namespace``, ``limits``
    and ``_FLOW``, its break/continue/return signals)."""

    caught_hook = None  # caught_hook(error, location): told of each error a deck catches
    catching = 0  # try bodies with handlers and with bodies under way (an error may be caught)

    @property
    def _handling(self) -> list:
        """Errors being handled, innermost last (a bare ``raise`` re-raises it)."""
        stack = self.__dict__.get("_handling_stack")
        if stack is None:
            stack = self.__dict__["_handling_stack"] = []
        return stack

    # ------------------------------------------------------------------ try

    def _try_stmt(self, node, frame):
        body, *clauses = node.children
        handlers = [c for c in clauses if c is not None and c.data != "else_clause"]
        handlers = [c for c in handlers if c.data != "finally_clause"]
        else_clause = next((c for c in clauses if c is not None and c.data == "else_clause"), None)
        final = next((c for c in clauses if c is not None and c.data == "finally_clause"), None)

        def attempt():
            self.catching += bool(handlers)
            try:
                self._exec_suite(body, frame)
            except AsterliteError as error:
                failure = error
            else:
                failure = None
            finally:
                self.catching -= bool(handlers)
            if failure is not None:
                kind = classify(failure)
                if kind is None or not self._handle(failure, kind, handlers, frame):
                    raise failure
                return
            if else_clause is not None:
                self._exec_suite(else_clause.children[0], frame)

        self._with_finally(attempt, final, frame)

    def _try_finally(self, node, frame):
        body, final = node.children
        self._with_finally(lambda: self._exec_suite(body, frame), final, frame)

    def _with_finally(self, action, final, frame) -> None:
        if final is None:
            action()
            return
        suite = final.children[0]
        try:
            action()
        except self._FLOW:
            self._exec_suite(suite, frame)
            raise
        except BaseException as error:
            if ends_run(error):
                raise
            self._exec_suite(suite, frame)
            raise
        self._exec_suite(suite, frame)

    def _handle(self, error, kind: ExceptionClass, handlers, frame) -> bool:
        """Run the first handler matching ``error``; False when none does."""
        for clause in handlers:
            _, test, name, suite = clause.children
            if test is not None:
                wanted = self.ev(test, frame)
                try:
                    caught = matches(kind, wanted)
                except DeckRuntimeError as refused:
                    refused.location = refused.location or self.location(test, frame.module)
                    raise
                if not caught:
                    continue
            if self.caught_hook is not None:
                self.caught_hook(error, self.location(clause, frame.module))
            if name is not None:
                self._store(name.value, CaughtError(error, kind), frame)
            stack = self._handling
            stack.append(error)
            try:
                self._exec_suite(suite, frame)
            finally:
                stack.pop()
                if name is not None and not frame.module.python2:  # Python 3 unbinds it
                    scope = frame.locals if frame.locals is not None else self.namespace
                    scope.pop(name.value, None)
            return True
        return False

    # ---------------------------------------------------------------- raise

    def _raise_stmt(self, node, frame):
        value_node, cause_node = node.children
        if value_node is None:
            if not self._handling:
                raise python_error(RuntimeError, "no active exception to re-raise")
            raise self._handling[-1]
        value = self.ev(value_node, frame)
        if cause_node is not None:
            self.ev(cause_node, frame)
        if value is Unknown:  # asterlite check: what would be raised is not known
            return
        raise self._raised(value)

    def _raise_py2(self, node, frame):
        """Python 2's ``raise E, message``."""
        cls = self.ev(node.children[0], frame)
        message = self.ev(node.children[1], frame)
        if not isinstance(cls, ExceptionClass):
            raise python_error(TypeError, "instance exception may not have a separate value")
        raise self._raised(RaisedException(cls, (message,)))

    def _raised(self, value) -> AsterliteError:
        if isinstance(value, ExceptionClass):
            value = RaisedException(value, ())
        if isinstance(value, RaisedException):
            return DeckRaised(value)
        if isinstance(value, CaughtError):
            return value.error
        return python_error(TypeError, "exceptions must derive from BaseException")

    # ----------------------------------------------------------------- with

    def _with_stmt(self, node, frame):
        *items, suite = node.children
        self._with_items(items, suite, frame)

    def _with_items(self, items, suite, frame) -> None:
        if not items:
            self._exec_suite(suite, frame)
            return
        expression, target = items[0].children
        manager = self.ev(expression, frame)
        if manager is Unknown:  # asterlite check: the body is checked as it stands
            if target is not None:
                self._assign_target(target, Unknown, frame)
            self._with_items(items[1:], suite, frame)
            return
        if not hasattr(type(manager), "deck_enter"):
            raise DeckRuntimeError(
                f"'{type(manager).__name__}' objects cannot be used in a 'with' block in decks "
                "(decks may use CA.disable_fpe() and TestCase.assertRaises())"
            )
        value = manager.deck_enter()
        if target is not None:
            self._assign_target(target, value, frame)
        self.catching += 1
        try:
            self._with_items(items[1:], suite, frame)
        except self._FLOW:
            manager.deck_exit(None, None)
            raise
        except AsterliteError as error:
            kind = classify(error)
            if kind is None:
                raise
            if manager.deck_exit(error, kind):
                if self.caught_hook is not None:
                    self.caught_hook(error, self.location(items[0], frame.module))
                return
            raise
        finally:
            self.catching -= 1
        manager.deck_exit(None, None)

    # ------------------------------------------------------------ f-strings

    def _fstring(self, node, frame):
        limits = self.limits
        pieces, total = [], 0
        for part in node.children[1:]:
            if part.data == "fstring_text":
                text = part.children[0]
            else:
                expression, conversion, spec_node, debug = part.children
                value = self.ev(expression, frame)
                spec = "" if spec_node is None else self._fstring(spec_node, frame)
                if value is Unknown or spec is Unknown:
                    return Unknown
                room = limits.max_string_length - total
                text = fstrings.format_field(value, conversion, spec, limits, room)
                if debug:
                    text = debug + text
            total += len(text)
            if total > limits.max_string_length:
                raise guards.exceeded("string length", limits.max_string_length)
            pieces.append(text)
        return "".join(pieces)

    # ------------------------------------------------------------- Python 2

    def _print_stmt(self, node, frame):
        """Python 2's print statement: items separated by spaces, a newline
        unless it ends with a comma (the line then goes on at the next print,
        after a space)."""
        items = node.children[1]
        values, trailing = [], False
        if items is not None:
            *tests, comma = items.children
            values = [self.ev(test, frame) for test in tests]
            trailing = comma is not None
        guards.check_nested_size(values, self.limits)
        text = " ".join(str(value) for value in guards.deck_text_value(values))
        pending = self.__dict__.get("_print_pending")
        if pending is not None and values:
            text = f"{pending} {text}"
        elif pending is not None:
            text = pending
        guards.check_string_length(len(text), self.limits)
        if trailing:
            self.__dict__["_print_pending"] = text
            return
        self.__dict__["_print_pending"] = None
        self.namespace["print"](text)

    def flush_print(self) -> None:
        """What print statements ending with a comma left on their line."""
        pending = self.__dict__.pop("_print_pending", None)
        if pending is not None:
            self.namespace["print"](pending)

    def _backquote(self, node, frame):
        value = self.ev(node.children[0], frame)
        if value is Unknown:
            return Unknown
        guards.check_nested_size((value,), self.limits)
        return repr(guards.deck_text_value(value))
