"""What the user types, as values: the defaults a new design starts from, one state
of the inputs (an entry of the undo history), and the rules that turn an edit of the
spec into the next state.

Kept apart from the model's QObject (signals, recomputing, undo stack) because these
are plain values and pure rules: the form reads the limits here, the document the
defaults, and the model applies the rules without any of them knowing about Qt.
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass, replace
from typing import Any, Hashable, Mapping

from core.forces.masses import MassProperties
from core.base.errors import DesignError
from core.linkage.geometry import Design
from core.linkage.spec import NUMBER_FIELDS, Spec

DEFAULT_RPMS = (40.0, 60.0)
DEFAULT_STEP = 1.0
MAX_SPEEDS = 16          # as core.linkage.kinematics.check_rpms allows
# The classic course-design loads of a shaper (lever 200 N, J = 1.1 kg·m², ram 700 N,
# cutting force 7000 N at 80 mm below the guide), so the Forces view shows a case at once.
DEFAULT_MASSES = MassProperties(lever_mass_kg=20.0, lever_inertia_kg_m2=1.1, ram_mass_kg=70.0,
                                cut_force_N=7000.0, cut_height_mm=80.0, delta=1.0 / 30.0)


@dataclass(frozen=True)
class Inputs:
    """Everything the user typed, valid or not: one state of the undo history.

    ``rpms`` and ``step`` hold floats, or the text the user typed when it is not a
    number; ``loads`` are the load fields as typed (``MassProperties`` names)."""

    spec: Spec
    rpms: tuple[Any, ...]
    step: Any
    loads: tuple[tuple[str, Any], ...]

    @classmethod
    def of(cls, spec: Spec, rpms: tuple[Any, ...], step: Any, masses: MassProperties) -> Inputs:
        """The inputs that show a valid state: its spec, speeds, step and loads."""
        return cls(spec, rpms, step, tuple(sorted(asdict(masses).items())))

    @property
    def load_dict(self) -> dict[str, Any]:
        return dict(self.loads)


def typed_spec(old: Spec, mode: str, changes: Mapping[str, Any], design: Design,
               valid: Spec) -> tuple[Spec, Spec]:
    """The spec an edit asks for, and the spec it gives: (requested, settled).

    ``changes`` are fields typed into ``old``; a switch to another ``mode`` carries the
    ``design`` on screen over, except the fields given with the switch. Settled, a
    field that the new mode, variant or rule leaves unused and that holds an invalid
    value takes its last ``valid`` value back, so Save never writes invalid text."""
    spec = replace(old, **changes)
    if mode != old.mode:
        spec = replace(spec.switch_mode(mode, design), **changes)
    fixes = {}
    for name in set(NUMBER_FIELDS) - spec.active_fields():
        try:
            spec.check_field(name)
        except DesignError:
            fixes[name] = getattr(valid, name)
    return spec, (replace(spec, **fixes) if fixes else spec)


def spec_edit_key(old: Spec, mode: str, changes: Mapping[str, Any]) -> tuple[Hashable | None, list[str]]:
    """How an edit of ``old`` (``changes``, and ``mode``) is kept in the undo history: the
    key its keystrokes merge by (None for a choice, a mode, variant or rule, which never
    merges) and the names of the fields it changes, for the step's text."""
    touched = tuple(sorted(name for name in changes if changes[name] != getattr(old, name)))
    choice = mode != old.mode or any(name not in NUMBER_FIELDS for name in touched)
    names = ["mode"] if mode != old.mode else list(touched)
    return (None if choice else ("spec", touched)), names


def same_typed(a: Any, b: Any) -> bool:
    """Two typed values alike: equal, or both NaN (typing "nan" again is no edit)."""
    return a == b or (isinstance(a, float) and isinstance(b, float) and math.isnan(a) and math.isnan(b))
