"""The gear pair's words in the UI's language: its field names, core's refusals and the
checks' advice, so the Chinese Gear tab shows no English sentence.

Core (``core.gear``) speaks English with numbers in fixed phrases. A refusal is matched
against the patterns here (then the shared ones of ``shaperapp.widgets.messages``); a check's
advice is rebuilt from the check's own fields, with the same English words as core's.
"""
from __future__ import annotations

import re

from PySide6.QtCore import QCoreApplication

from core.base.errors import DesignError
from core.gear import Check
from core.gear.advice import Move
from core.gear.shift import bound_text
from shaperapp.widgets.messages import allowed_text, field_name

translate = QCoreApplication.translate


def field_names() -> dict[str, str]:
    """The gear's fields (the GearPairInputs errors' names) in the UI's language."""
    return {"z1": translate("GearMessages", "Teeth z1"), "z2": translate("GearMessages", "Teeth z2"),
            "module": translate("GearMessages", "Module m"),
            "x1": translate("GearMessages", "Shift factor x1"),
            "x2": translate("GearMessages", "Shift factor x2"),
            "centre": translate("GearMessages", "Centre distance a′"),
            "pressure_angle": translate("GearMessages", "Pressure angle α"),
            "addendum": translate("GearMessages", "Addendum factor h*a"),
            "clearance": translate("GearMessages", "Clearance factor c*"),
            "tip_limit": translate("GearMessages", "Least tip thickness"),
            "contact_limit": translate("GearMessages", "Least contact ratio"),
            "mode": translate("GearMessages", "Shifts given as")}


# (pattern on core.gear's English text, template with %1, %2 …)
_PATTERNS: tuple[tuple[str, str], ...] = (
    (r"must be a whole number of teeth$", "must be a whole number of teeth"),
    (r"must be ≤ (\S+) at α = (\S+)° and h\*a = (\S+): the rack's tip rounding would not fit its tooth$",
     "must be at most %1 at α = %2° and h*a = %3: the rack's tip rounding would not fit its tooth"),
    (r"must be ≥ (\S+) and ≤ (\S+) teeth$", "must be at least %1 and at most %2 teeth"),
    (r"x1 \+ x2 is too negative: the gears would not mesh \(α′ ≤ 0\); raise x1 \+ x2 above (\S+)$",
     "x1 + x2 is too negative: the gears would not mesh (α′ ≤ 0); raise x1 + x2 above %1"),
    (r"must be > a cos α = (\S+) mm \(the working pressure angle would be 0\)$",
     "must be more than a cos α = %1 mm (the working pressure angle would be 0)"),
    (r"needs x1 \+ x2 = (\S+), below the (\S+) that keeps both gears uncut; give ≥ (\S+) mm$",
     "needs x1 + x2 = %1, below the %2 that keeps both gears uncut; give at least %3 mm"),
    (r"x1 \+ x2 is too large: the addendum reduction leaves gear (\d) no flank above its base circle; give "
     r"(x\d) ≤ (\S+), for a tip of gear \d at least (\S+) mm thick$",
     "x1 + x2 is too large: the addendum reduction leaves gear %1 no flank above its base circle; give %2 ≤ %3, "
     "for a tip of gear %1 at least %4 mm thick"),
    (r"x1 \+ x2 is too large: the addendum reduction leaves gear (\d) no flank above its base circle$",
     "x1 + x2 is too large: the addendum reduction leaves gear %1 no flank above its base circle"),
    (r"x1 \+ x2 is too large: the addendum reduction Δy = (\S+) cuts both tips so far that the teeth never touch; "
     r"give (x\d) ≤ (\S+)$",
     "x1 + x2 is too large: the addendum reduction Δy = %1 cuts both tips so far that the teeth never touch; give %2 ≤ %3"),
    (r"x1 \+ x2 is too large: the addendum reduction Δy = (\S+) cuts both tips so far that the teeth never touch; "
     r"give a′ ≤ (\S+) mm$",
     "x1 + x2 is too large: the addendum reduction Δy = %1 cuts both tips so far that the teeth never touch; give a′ ≤ %2 mm"),
    (r"x1 \+ x2 is too large: the addendum reduction Δy = (\S+) cuts both tips so far that the teeth never touch$",
     "x1 + x2 is too large: the addendum reduction Δy = %1 cuts both tips so far that the teeth never touch"),
    (r"makes the tip of gear (\d) pointed \(x\d = (\S+)\): give (x\d) ≤ (\S+), for a tip at least (\S+) mm thick$",
     "makes the tip of gear %1 pointed (x = %2): give %3 ≤ %4, for a tip at least %5 mm thick"),
    (r"makes the tip of gear (\d) pointed \(x\d = (\S+)\): give a′ ≤ (\S+) mm, for a tip at least (\S+) mm "
     r"thick$",
     "makes the tip of gear %1 pointed (x = %2): give a′ ≤ %3 mm, for a tip at least %4 mm thick"),
    (r"too few teeth for the rule's shifts, which make the tip of gear (\d) pointed \(x\d = (\S+)\): give "
     r"(z\d) ≥ (\d+), for a tip at least (\S+) mm thick$",
     "too few teeth for the rule's shifts, which make the tip of gear %1 pointed (x = %2): give %3 ≥ %4, for a "
     "tip at least %5 mm thick"),
    (r"makes the tip of gear (\d) pointed \(x\d = (\S+)\): no smaller (x\d) found that gives a tip at least (\S+) mm thick; "
     r"give gear \d more teeth$",
     "makes the tip of gear %1 pointed (x = %2): no smaller %3 found that gives a tip at least %4 mm thick; give gear %1 "
     "more teeth"),
    (r"makes the tip of gear (\d) pointed \(x\d = (\S+)\): no smaller centre distance found that gives a tip at least (\S+) "
     r"mm thick; give gear \d more teeth$",
     "makes the tip of gear %1 pointed (x = %2): no smaller centre distance found that gives a tip at least %3 mm thick; "
     "give gear %1 more teeth"),
    (r"too few teeth for the rule's shifts, which make the tip of gear (\d) pointed \(x\d = (\S+)\).*$",
     "too few teeth for the rule's shifts, which make the tip of gear %1 pointed (x = %2): give more "
     "teeth, or the shifts or the centre distance"),
)


def _templates() -> dict[str, str]:
    # Listed literally so pyside6-lupdate finds every template.
    return {
        "must be a whole number of teeth": translate("GearMessages", "must be a whole number of teeth"),
        "must be at most %1 at α = %2° and h*a = %3: the rack's tip rounding would not fit its tooth":
            translate("GearMessages", "must be at most %1 at α = %2° and h*a = %3: the rack's tip rounding "
                      "would not fit its tooth"),
        "must be at least %1 and at most %2 teeth":
            translate("GearMessages", "must be at least %1 and at most %2 teeth"),
        "x1 + x2 is too negative: the gears would not mesh (α′ ≤ 0); raise x1 + x2 above %1":
            translate("GearMessages", "x1 + x2 is too negative: the gears would not mesh (α′ ≤ 0); raise x1 + x2 above %1"),
        "must be more than a cos α = %1 mm (the working pressure angle would be 0)":
            translate("GearMessages", "must be more than a cos α = %1 mm (the working pressure angle would be 0)"),
        "needs x1 + x2 = %1, below the %2 that keeps both gears uncut; give at least %3 mm":
            translate("GearMessages", "needs x1 + x2 = %1, below the %2 that keeps both gears uncut; give at least %3 mm"),
        "x1 + x2 is too large: the addendum reduction leaves gear %1 no flank above its base circle; give %2 ≤ %3, "
        "for a tip of gear %1 at least %4 mm thick":
            translate("GearMessages", "x1 + x2 is too large: the addendum reduction leaves gear %1 no flank above its "
                      "base circle; give %2 ≤ %3, for a tip of gear %1 at least %4 mm thick"),
        "x1 + x2 is too large: the addendum reduction Δy = %1 cuts both tips so far that the teeth never touch; give %2 ≤ %3":
            translate("GearMessages", "x1 + x2 is too large: the addendum reduction Δy = %1 cuts both tips so far that the "
                      "teeth never touch; give %2 ≤ %3"),
        "x1 + x2 is too large: the addendum reduction Δy = %1 cuts both tips so far that the teeth never touch; give a′ ≤ %2 mm":
            translate("GearMessages", "x1 + x2 is too large: the addendum reduction Δy = %1 cuts both tips so far that the "
                      "teeth never touch; give a′ ≤ %2 mm"),
        "x1 + x2 is too large: the addendum reduction Δy = %1 cuts both tips so far that the teeth never touch":
            translate("GearMessages", "x1 + x2 is too large: the addendum reduction Δy = %1 cuts both tips so far that the "
                      "teeth never touch"),
        "makes the tip of gear %1 pointed (x = %2): give %3 ≤ %4, for a tip at least %5 mm thick":
            translate("GearMessages", "makes the tip of gear %1 pointed (x = %2): give %3 ≤ %4, for a tip at least "
                      "%5 mm thick"),
        "makes the tip of gear %1 pointed (x = %2): give a′ ≤ %3 mm, for a tip at least %4 mm thick":
            translate("GearMessages", "makes the tip of gear %1 pointed (x = %2): give a′ ≤ %3 mm, for a tip at "
                      "least %4 mm thick"),
        "too few teeth for the rule's shifts, which make the tip of gear %1 pointed (x = %2): give %3 ≥ %4, for a "
        "tip at least %5 mm thick":
            translate("GearMessages", "too few teeth for the rule's shifts, which make the tip of gear %1 pointed "
                      "(x = %2): give %3 ≥ %4, for a tip at least %5 mm thick"),
        "x1 + x2 is too large: the addendum reduction leaves gear %1 no flank above its base circle":
            translate("GearMessages", "x1 + x2 is too large: the addendum reduction leaves gear %1 no flank "
                      "above its base circle"),
        "makes the tip of gear %1 pointed (x = %2): no smaller %3 found that gives a tip at least %4 mm thick; give gear %1 "
        "more teeth":
            translate("GearMessages", "makes the tip of gear %1 pointed (x = %2): no smaller %3 found that gives a tip at least "
                      "%4 mm thick; give gear %1 more teeth"),
        "makes the tip of gear %1 pointed (x = %2): no smaller centre distance found that gives a tip at least %3 mm thick; "
        "give gear %1 more teeth":
            translate("GearMessages", "makes the tip of gear %1 pointed (x = %2): no smaller centre distance found that "
                      "gives a tip at least %3 mm thick; give gear %1 more teeth"),
        "too few teeth for the rule's shifts, which make the tip of gear %1 pointed (x = %2): give more "
        "teeth, or the shifts or the centre distance":
            translate("GearMessages", "too few teeth for the rule's shifts, which make the tip of gear %1 "
                      "pointed (x = %2): give more teeth, or the shifts or the centre distance"),
    }


def describe_gear_error(error: DesignError) -> str:
    """'Field: what is allowed' for a refusal of the gear pair, in the UI's language."""
    name = field_names().get(error.parameter) or field_name(error.parameter)
    body = allowed_text(error.allowed, _PATTERNS, _templates())
    return translate("messages", "%1: %2").replace("%1", name).replace("%2", body)


def gear_refusal(error: DesignError) -> str | None:
    """:func:`describe_gear_error` when ``error`` is one of core.gear's own refusals (its
    text one of this module's patterns), else None: a design file's gear pair refused on
    Open was shown in English in the Chinese window."""
    return None if gear_text(error.allowed) is None else describe_gear_error(error)


def gear_text(allowed: str) -> str | None:
    """One of core.gear's refusals (``DesignError.allowed``) in the UI's language, or None
    when ``allowed`` is none of them: the Class dialog's row errors said a gear pair's
    refusal in English."""
    if not any(re.match(pattern, allowed) for pattern, _ in _PATTERNS):
        return None
    return allowed_text(allowed, _PATTERNS, _templates())


def module_note(module_mm: float) -> str:
    """core's note on a module outside GB/T 1357's first series, in the UI's language."""
    return translate("GearMessages", "m = %1 mm is not a GB/T 1357 first-series module").replace(
        "%1", f"{module_mm:g}")


def check_name(check: Check) -> str:
    """What a check tests, in the UI's language."""
    k = check.name[-1]
    if check.name.startswith("undercut"):
        return translate("GearMessages", "Gear %1 not undercut: x%1 ≥ x%1min").replace("%1", k)
    if check.name.startswith("tip"):
        return translate("GearMessages", "Gear %1 tip thick enough: sa%1 ≥ %2 mm").replace(
            "%1", k).replace("%2", bound_text(check.limit, True))
    if check.name == "contact":
        return translate("GearMessages", "Contact ratio: ε ≥ %1").replace("%1", f"{check.limit:g}")
    return translate("GearMessages", "No interference at the root of gear %1").replace("%1", k)


def move_words(move: Move) -> str:
    """One change of ``core.gear.advice`` (``advice.move_text``) in the UI's language: with the
    value to type and the checks it breaks, or (no value) the direction alone."""
    if move.to:
        return _amount_words(move)
    if move.name in ("x1", "x2"):
        text = (translate("GearMessages", "raise %1") if move.sign > 0
                else translate("GearMessages", "lower %1"))
        return text.replace("%1", move.name)
    if move.name == "centre":
        return (translate("GearMessages", "a larger a′") if move.sign > 0
                else translate("GearMessages", "a smaller a′"))
    return (translate("GearMessages", "x1 + δ and x2 − δ at the same a′") if move.sign > 0
            else translate("GearMessages", "x1 − δ and x2 + δ at the same a′"))


def _amount_words(move: Move) -> str:
    if move.name in ("x1", "x2"):
        text = (translate("GearMessages", "raise %1 to ≥ %2") if move.sign > 0
                else translate("GearMessages", "lower %1 to ≤ %2")).replace("%1", move.name)
    elif move.name == "centre":
        text = (translate("GearMessages", "raise a′ to ≥ %2 mm") if move.sign > 0
                else translate("GearMessages", "lower a′ to ≤ %2 mm"))
    else:
        text = translate("GearMessages", "x1 = %2 and x2 = %3 (a′ about the same)").replace("%3", move.to[1])
    text = text.replace("%2", move.to[0])
    if not move.breaks:
        return text
    broken = problem_words(move.breaks[0])
    for name in move.breaks[1:]:
        broken = translate("GearMessages", "%1, %2").replace("%1", broken).replace("%2", problem_words(name))
    return translate("GearMessages", "%1 (but then %2)").replace("%1", text).replace("%2", broken)


def problem_words(name: str) -> str:
    """What is wrong when check ``name`` fails (``advice.BREAK_TEXT``), in the UI's language."""
    k = name[-1]
    other = "2" if k == "1" else "1"
    if name.startswith("undercut"):
        return translate("GearMessages", "gear %1 is undercut").replace("%1", k)
    if name.startswith("tip"):
        return translate("GearMessages", "the tip of gear %1 is too thin").replace("%1", k)
    if name == "contact":
        return translate("GearMessages", "ε is too small")
    return translate("GearMessages", "the tip of gear %2 digs into the root of gear %1").replace(
        "%1", k).replace("%2", other)


def check_advice(check: Check) -> str:
    """What to change when ``check`` fails ('' when it passes): core's advice, the same
    words in English (``Check.advice``), rebuilt from the changes it names (``check.moves``)
    in the UI's language."""
    if check.ok:
        return ""
    k = check.name[-1]
    if check.name.startswith("undercut"):
        return translate("GearMessages", "raise x%1 to ≥ %2 (or give gear %1 more teeth)").replace(
            "%1", k).replace("%2", bound_text(check.limit, True))
    problem = problem_words(check.name)
    if check.moves:
        changes = move_words(check.moves[0])
        for move in check.moves[1:]:
            changes = translate("GearMessages", "%1 or %2").replace("%1", changes).replace(
                "%2", move_words(move))
    else:
        changes = translate("GearMessages", "no change of one shift or of a′ makes it pass: try other teeth")
    return translate("messages", "%1: %2").replace("%1", problem).replace("%2", changes)


def mode_text(mode: str) -> str:
    """How the shifts were found (core.gear.shift.MODES), in the UI's language."""
    return {"given": translate("GearMessages", "x1 and x2 given"),
            "centre": translate("GearMessages", "from the centre distance: the pinion's least uncut "
                                "shift, the rest to the gear"),
            "balanced": translate("GearMessages", "rule: z1 + z2 ≥ 2 zmin, the pinion's least uncut "
                                  "shift and x2 = −x1"),
            "positive": translate("GearMessages", "rule: z1 + z2 < 2 zmin, the least positive pair at "
                                  "a′ rounded up to a step of about m/10")}[mode]
