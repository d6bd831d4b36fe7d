"""The task book's link numbering (issue 41), as a check on any text a user reads.

Links: 1 frame, 2 crank, 3 block, 4 lever, 5 rod (the block at B in the block
variant), 6 ram; the table is in docs/methods.md (#link-numbers-and-symbols).
The numbering before issue 41 was one lower (1 crank, 2 block, 3 lever, 4 rod,
5 ram), so a symbol of it either cannot occur in the new one (ω3, J3, G3, v_A3A2,
R_3B, a2′ …) or means another link there (G5, F_I5, m5: the ram before, the rod
now; ω4: the rod before, the lever now). The first kind is refused anywhere; the
second wherever its text names only the link it meant before ("ram … G5",
"rod ω4"). Texts are checked in units (a line, a label, a column title) small
enough for that test to mean something.
"""
from __future__ import annotations

import re

_SUB = "₀₁₂₃₄₅₆₇₈₉"
_DIGIT = {str(d): f"[{d}{_SUB[d]}]" for d in range(10)}


def _index(symbol: str, digit: str) -> str:
    """A symbol with its index as plain text writes it, or as a subscript, with or
    without the underscore, and as pdftotext joins the runs of a sheet ("FI6")."""
    return rf"(?<![A-Za-z0-9_]){symbol}_?{_DIGIT[digit]}(?![0-9{_SUB}])"


# Symbols that do not exist in the task book's numbering as this tool writes it.
NEVER = [
    *(_index(s, d) for s in ("ω", "α") for d in "13"),   # the crank is ω2; the lever ω4, α4
    *(_index(s, d) for s in ("m", "G", "F_?I") for d in "1"),
    _index("J", "3"), _index("J", "4"), _index("J", "5"),  # inertias are J_S4, J_S5 (task book)
    _index("G", "3"), _index("F_?I", "3"),                 # the block carries no drawn force
    r"A3A2|A2A3|R_?3B",                                    # block 2 on lever 3: now A4A3, R_4B
    r"(?<![A-Za-z0-9_α])[an]2[′']|(?<![A-Za-z0-9_])n3[′']",    # polygon points a2′, n3′: now a3′, n4′
    r"lever \(link 3\)|导杆（构件 ?3）|\b1 crank,|1 曲柄|(?<!Figure )\b5 ram\b|(?<!图 )5 滑枕",
]
_NEVER = re.compile("|".join(f"(?:{p})" for p in NEVER))
_RAM = re.compile(r"\bram\b|滑枕|刨头", re.I)
_ROD = re.compile(r"\brod\b(?! variant)|连杆(?!方案)", re.I)   # a variant is no link
_LEVER = re.compile(r"\blever\b|导杆", re.I)
_BLOCK = re.compile(r"\bblock\b|滑块", re.I)
_THREE = re.compile(_index("m", "3"))
_FOUR = re.compile("|".join(_index(s, "4") for s in ("m", "ω", "α")))
_FIVE = re.compile("|".join(_index(s, "5") for s in ("m", "G", "F_?I", "ω", "α")))
NEAR = 24            # characters either side in which a word names the symbol's link


def _near(unit: str, match: re.Match) -> str:
    return unit[max(match.start() - NEAR, 0):match.end() + NEAR]


def old_symbols(unit: str) -> list[str]:
    """The symbols of the old numbering in one unit of text (empty: none): those that
    cannot occur in the new one, and those whose nearest words name the link the
    old numbering meant (the ram's 5, the rod's 4, the lever's m3)."""
    found = [m.group(0) for m in _NEVER.finditer(unit)]
    for rule, meant, means in ((_FIVE, _RAM, _ROD), (_FOUR, _ROD, _LEVER), (_THREE, _LEVER, _BLOCK)):
        for m in rule.finditer(unit):
            near = _near(unit, m)
            if meant.search(near) and not means.search(near):
                found.append(f"{m.group(0)} ({meant.pattern.split('|')[1]})")
    return found


def offending(units, where: str) -> list[str]:
    """``where: unit → symbols`` for every unit of ``units`` with an old symbol."""
    return [f"{where}: {u.strip()[:160]!r} → {old_symbols(u)}" for u in units if old_symbols(u)]
