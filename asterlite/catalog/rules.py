"""Rules on which keywords of one level may or must appear together.

Each rule is built from keyword names and checks the set of names present
at its level (given by the deck or filled by a default); ``check`` returns
an error message stating what was expected, or None when the rule holds.
"""

from __future__ import annotations

from collections.abc import Collection


def _names(names: tuple[str, ...]) -> str:
    return ", ".join(names)


class Rule:
    """A constraint over the presence of keywords at one level."""

    code = "RULE"

    def __init__(self, *names: str):
        if not names or not all(isinstance(n, str) for n in names):
            raise TypeError(f"{self.code} takes keyword names")
        self.names = names

    def check(self, present: Collection[str]) -> str | None:
        """None when the rule holds for the present names, else a message."""
        given = [n for n in self.names if n in present]
        if self.holds(given):
            return None
        return f"{self.expectation(given)} ({self.code})"

    def holds(self, given: list[str]) -> bool:
        raise NotImplementedError

    def expectation(self, given: list[str]) -> str:
        raise NotImplementedError

    def __repr__(self) -> str:
        return f"{self.code}({', '.join(map(repr, self.names))})"


class UN_PARMI(Rule):  # noqa: N801 - code_aster's name
    """Exactly one of the keywords."""

    code = "UN_PARMI"

    def holds(self, given: list[str]) -> bool:
        return len(given) == 1

    def expectation(self, given: list[str]) -> str:
        if not given:
            return f"exactly one of {_names(self.names)} must be given"
        return f"exactly one of {_names(self.names)} must be given, got {_names(tuple(given))}"


class EXCLUS(Rule):  # noqa: N801
    """At most one of the keywords."""

    code = "EXCLUS"

    def holds(self, given: list[str]) -> bool:
        return len(given) <= 1

    def expectation(self, given: list[str]) -> str:
        return f"at most one of {_names(self.names)} may be given, got {_names(tuple(given))}"


class AU_MOINS_UN(Rule):  # noqa: N801
    """At least one of the keywords."""

    code = "AU_MOINS_UN"

    def holds(self, given: list[str]) -> bool:
        return len(given) >= 1

    def expectation(self, given: list[str]) -> str:
        return f"at least one of {_names(self.names)} must be given"


class PRESENT_PRESENT(Rule):  # noqa: N801
    """If the first keyword is given, all the others must be too."""

    code = "PRESENT_PRESENT"

    def holds(self, given: list[str]) -> bool:
        return self.names[0] not in given or len(given) == len(self.names)

    def expectation(self, given: list[str]) -> str:
        missing = tuple(n for n in self.names[1:] if n not in given)
        return f"{self.names[0]} requires {_names(self.names[1:])}, missing {_names(missing)}"


class PRESENT_ABSENT(Rule):  # noqa: N801
    """If the first keyword is given, none of the others may be."""

    code = "PRESENT_ABSENT"

    def holds(self, given: list[str]) -> bool:
        return self.names[0] not in given or given == [self.names[0]]

    def expectation(self, given: list[str]) -> str:
        extra = tuple(n for n in given if n != self.names[0])
        return f"{self.names[0]} excludes {_names(self.names[1:])}, got {_names(extra)}"


class ENSEMBLE(Rule):  # noqa: N801
    """All of the keywords or none of them."""

    code = "ENSEMBLE"

    def holds(self, given: list[str]) -> bool:
        return len(given) in (0, len(self.names))

    def expectation(self, given: list[str]) -> str:
        missing = tuple(n for n in self.names if n not in given)
        return (
            f"{_names(self.names)} go together: all or none, "
            f"got {_names(tuple(given))} without {_names(missing)}"
        )


class TOUT_OU_RIEN(ENSEMBLE):  # noqa: N801
    """All of the keywords or none of them (code_aster's other spelling)."""

    code = "TOUT_OU_RIEN"
