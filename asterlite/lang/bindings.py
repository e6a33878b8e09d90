"""The names a deck statement binds, read from its tree without running it:
what becomes unknown when ``asterlite check`` cannot run a statement (it
failed, or an ``if`` hangs on a value check does not compute)."""

from __future__ import annotations


def statement_outputs(statement) -> list[str]:
    """Names a deck statement binds: assignment and loop targets, imported
    names, functions, ``with ... as`` names and CO("NAME") outputs."""
    names = []
    for node in statement.iter_subtrees_topdown():
        data = node.data
        if data == "assign":
            for target in node.children[:-1]:
                names += _target_names(target)
        elif data in ("augassign", "for_stmt", "comp_for"):
            names += _target_names(node.children[0])
        elif data == "with_item" and len(node.children) > 1 and node.children[1] is not None:
            names += _target_names(node.children[1])
        elif data == "funcdef":
            names.append(str(node.children[0]))
        elif data == "import_as_name":
            bound = node.children[1] if len(node.children) > 1 else None
            names.append(str(bound if bound is not None else node.children[0]))
        elif data == "dotted_as_name":
            bound = node.children[1] if len(node.children) > 1 else None
            if bound is not None:
                names.append(str(bound))
            else:
                dotted = node.children[0]
                first = dotted.children[0] if hasattr(dotted, "children") else dotted
                names.append(str(first))
        elif data == "funccall" and _is_co_call(node):
            names.append(node.children[1].children[0].children[0])
    return names


def _target_names(target) -> list[str]:
    data = getattr(target, "data", None)
    if data == "var":
        return [target.children[0].value]
    if data in ("tuple", "list", "exprlist", "testlist"):
        return [n for child in target.children for n in _target_names(child)]
    if data == "getitem":  # A[i] = ...: what A holds is unknown as a whole
        return _target_names(target.children[0])
    return []


def _is_co_call(node) -> bool:
    callee, arguments = node.children
    if callee.data != "var" or callee.children[0].value != "CO" or arguments is None:
        return False
    first = arguments.children[0] if arguments.children else None
    return (
        getattr(first, "data", None) == "const"
        and isinstance(first.children[0], str)
        and first.children[0].isidentifier()
    )


def method_receivers(statement) -> list[str]:
    """Names whose object a method call may change (``L.append(x)``,
    ``a.b.c(y)``: ``L``, ``a``)."""
    names = []
    for node in statement.iter_subtrees_topdown():
        if node.data != "funccall" or getattr(node.children[0], "data", None) != "getattr":
            continue
        base = node.children[0]
        while getattr(base, "data", None) in ("getattr", "getitem"):
            base = base.children[0]
        if getattr(base, "data", None) == "var":
            names.append(base.children[0].value)
    return names
