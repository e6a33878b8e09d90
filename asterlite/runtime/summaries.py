"""The run's summary of each transient a command made: integration figures
per tran_gene result and peak forces and wear power per shock, taken when
the command returns the result, so that the run holds no result for its
summary (a deck that rebinds a name frees what it held)."""

from __future__ import annotations

from dataclasses import dataclass, field

from asterlite.runtime.verdicts import plain_value


@dataclass
class RunSummaries:
    """The summaries of the run so far; ``error`` the first one that failed."""

    transients: list[dict] = field(default_factory=list)
    shocks: list[dict] = field(default_factory=list)
    supports: list[dict] = field(default_factory=list)  # per shock: its support's data
    calls: dict[str, int] = field(default_factory=dict)  # results made per command
    error: str | None = None
    # (name, result) of each transient, kept only for a report page that draws them
    keep_results: bool = False
    results_kept: list[tuple[str | None, object]] = field(default_factory=list)

    def add(self, command: str, name: str | None, concept) -> None:
        """A command made ``concept`` (bound to ``name``)."""
        from asterlite.concepts.transient import TranGene

        call = self.calls[command] = self.calls.get(command, 0) + 1  # the n-th call
        if not isinstance(concept, TranGene) or self.error is not None:
            return
        if self.keep_results:
            self.results_kept.append((name, concept))
        try:
            self.transients.append(transient_summary(command, name, concept, call))
            self.shocks += [shock_summary(name, concept.times, shock) for shock in concept.shocks]
            self.supports += [support_row(name, shock) for shock in concept.shocks]
        except (MemoryError, RecursionError, ValueError, TypeError) as error:
            self.error = f"cannot summarise the results: {type(error).__name__}: {error}"

    def results(self) -> tuple[list[dict], list[dict]]:
        """(transients, shocks); ValueError if a summary failed."""
        if self.error is not None:
            raise ValueError(self.error)
        return self.transients, self.shocks


def transient_summary(command: str, name: str | None, concept, call: int) -> dict:
    """Integration figures of one tran_gene result, the ``call``-th result of
    ``command``."""
    import numpy as np

    info = concept.info
    summary = {
        "result": name,
        "command": command,
        "call": call,
        "scheme": concept.scheme,
        "step": float(concept.step),
        "t_start": float(concept.times[0]) if len(concept.times) else None,
        "t_end": float(concept.times[-1]) if len(concept.times) else None,
        "steps": int(info.get("steps", 0)),
        "rejected_steps": int(info.get("rejected_steps", 0)),
        "min_step": plain_value(info.get("min_step")),
        "max_step": plain_value(info.get("max_step")),
        # the steps that led to the archived instants (PTEM): their median
        # (numpy's: the (a + b) / 2 of the former statistics.median, no list)
        "median_step": float(np.median(concept.step_sizes[1:]))
        if concept.step_sizes is not None and len(concept.step_sizes) > 1
        else None,
        "integration_seconds": float(info.get("integration_seconds", 0.0)),
        "loop": info.get("loop"),  # the compiled loop that ran (integrate.run_kernel)
        # SCHEMA_TEMPS's PAS_MINI / PAS_MAXI as the deck gave them (None: default)
        "pas_mini": plain_value(info.get("pas_mini")),
        "pas_maxi": plain_value(info.get("pas_maxi")),
    }
    if "energy_residual" in info:  # ENERGIE=_F(): the final balance residual
        summary["energy_residual"] = plain_value(info["energy_residual"])
        summary["energy_residual_ratio"] = plain_value(info["energy_residual_ratio"])
        summary["energy_residual_flow_ratio"] = plain_value(info.get("energy_residual_flow_ratio"))
    return summary


def shock_summary(result: str | None, times, shock) -> dict:
    """Peak and mean normal force, contact fraction and wear power
    (code_aster's PUIS_USURE, :func:`asterlite.post.wear.wear_power`: time
    mean of FN·|VT| over the sliding intervals) of one shock history."""
    import numpy as np

    from asterlite.post.wear import history_wear_power

    fields = shock.fields
    fn = np.asarray(fields["FN"] if "FN" in fields else np.zeros(len(times)), dtype=float)
    if not fn.size:
        figures = {"impacts": 0, "max_FN": 0.0, "mean_FN": 0.0, "contact_fraction": 0.0}
    else:
        in_contact = fn != 0.0
        magnitude = np.abs(fn)
        # an impact starts where the archived normal force leaves zero
        starts = int(in_contact[0]) + int(np.count_nonzero(in_contact[1:] > in_contact[:-1]))
        figures = {
            "impacts": starts,
            "max_FN": float(magnitude.max()),
            "mean_FN": float(magnitude.mean()),
            "contact_fraction": float(np.mean(in_contact)),
        }
    return {
        "result": result,
        "shock": shock.name,
        **figures,
        "wear_power": history_wear_power(times, fields),
    }


def support_row(result: str | None, shock) -> dict:
    """Relation, nodes, obstacle, gap and normal stiffness of one shock."""
    parameters = shock.parameters or {}
    return {
        "result": result,
        "shock": shock.name,
        "relation": shock.relation,
        "node_1": shock.node_1,
        "node_2": shock.node_2,
        "obstacle": _plain(parameters.get("OBSTACLE")),
        "gap": _plain(parameters.get("JEU")),
        "stiffness": _plain(parameters.get("RIGI_NOR")),
    }


def _plain(value):
    if value is None:
        return None
    if hasattr(value, "item"):
        try:
            return value.item()
        except (ValueError, AttributeError):
            return str(value)
    return value if isinstance(value, (int, float, str, bool)) else str(value)
