"""One library entry and its design document (the text of a design file).

Apart from :mod:`core.library` so that the entry, the text it stores and the check
of that text are one small module: what is written and what is read back are the
same rules (:func:`core.files.io.parse_design`).
"""
from __future__ import annotations

import json
from dataclasses import dataclass
from typing import Any, Sequence

from core.space.figures import FIGURES_VERSION, Figures, SpeedFigures

# The design file's reader and writer (numpy and the linkage) are imported where a document
# is read or written: ``shaper library --help`` prints texts only (issue 43 item 5).


@dataclass(frozen=True)
class Entry:
    """One library entry: what it is called, when, the document text and its figures."""

    name: str
    notes: str
    tags: tuple[str, ...]
    created: str          # UTC ISO 8601
    modified: str         # UTC ISO 8601
    text: str             # the design document as JSON, the text of a design file
    figures: Figures
    figures_version: int = FIGURES_VERSION   # the computation the figures come from

    @property
    def figures_current(self) -> bool:
        """False when an older program computed the figures (see ``refresh_figures``)."""
        return self.figures_version >= FIGURES_VERSION

    def document(self, any_step: bool = False) -> dict[str, Any]:
        """The validated design (keys of ``core.files.io.load_design``); FileFormatError if bad.
        With ``any_step``, an entry too fine for a design file (stored before its sample
        limit) is read at the coarsest step a file holds: for a comparison, which takes the
        linkage, the speeds and the loads and its own --step, never the stored one (`library
        compare` refused such an entry, telling to use a step its --step could not give)."""
        from core.files.io import parse_design
        label = f"library entry {self.name!r}"
        try:
            return parse_design(self.text.encode("utf-8"), label, self.name)
        except Exception as exc:            # noqa: BLE001 — only a too fine step is set right here
            fine = too_fine(exc)
            if not any_step or fine is None:
                raise
        return parse_design(with_step(self.name, self.text, fine.coarsest).encode("utf-8"), label, self.name)


def document_text(loaded: dict[str, Any]) -> str:
    """A loaded design (``load_design``'s dict) as the JSON text of a design file."""
    from core.files.design_file import OWN_KEYS     # numpy: not for a --help that imports this module
    from core.files.io import design_document, masses_to_dict
    masses = loaded.get("masses")
    extra: dict[str, Any] = {}
    for key, value in loaded.items():              # keep the file's key order
        if key == "forces" and masses is not None:
            extra["forces"] = masses_to_dict(masses)
        elif key not in OWN_KEYS:
            extra[key] = value
    if masses is not None and "forces" not in extra:
        extra["forces"] = masses_to_dict(masses)
    doc = design_document(loaded["spec"], loaded["rpm"], loaded["step_deg"], extra)
    text = json.dumps(doc, indent=2, ensure_ascii=False)
    try:
        text.encode("utf-8")
    except UnicodeEncodeError:      # a lone surrogate ("\ud800" in the file): kept as a JSON escape
        text = json.dumps(doc, indent=2, ensure_ascii=True)
    return text


def check_document(name: str, text: str) -> None:
    """Refuse (FileFormatError) a stored document a design file could not be."""
    from core.files.io import parse_design
    parse_design(text.encode("utf-8"), f"library entry {name!r}", name)


def too_fine(exc: BaseException):
    """The ``TooManySamples`` behind ``exc`` (a document refused only because its step gives
    more samples than a design file holds: an entry stored before that limit), or None."""
    from core.linkage.limits import TooManySamples
    cause = getattr(exc, "cause", None)
    return cause if isinstance(cause, TooManySamples) else None


def with_step(name: str, text: str, step_deg: float) -> str:
    """The stored document ``text`` at the crank-angle step ``step_deg`` (°), every other key
    as it is; FileFormatError if the result is no design file (the step too fine still, or
    the document refused for another reason). Why: ``shaper library export --step`` gets
    an entry stored before the sample limit out at a step a design file may hold; the
    library itself is not changed."""
    try:
        check_document(name, text)
    except Exception as exc:            # noqa: BLE001 — only a too fine step is set right here
        if too_fine(exc) is None:
            raise
    doc = json.loads(text)
    doc["step_deg"] = step_deg
    new = json.dumps(doc, indent=2, ensure_ascii=False)
    try:
        new.encode("utf-8")
    except UnicodeEncodeError:          # a lone surrogate, kept as a JSON escape (document_text)
        new = json.dumps(doc, indent=2, ensure_ascii=True)
    check_document(name, new)
    return new


def distinct_speeds(speeds: Sequence[SpeedFigures]) -> list[SpeedFigures]:
    """The speeds without repeats (a document may list one speed twice), first one kept."""
    out: list[SpeedFigures] = []
    for s in speeds:
        if not any(abs(s.rpm - t.rpm) <= 1e-9 for t in out):
            out.append(s)
    return out
