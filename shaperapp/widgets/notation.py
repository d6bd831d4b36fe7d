"""The course notation of the program's own labels: J_F, v_A3A4, a^k_A4A3, O4, (1/2π).

Why one module: the report typesets it (sub- and superscripts in HTML, which
QTextDocument prints), and a widget that shows plain text (a table's header) writes it
in characters a font has, from the same reading of the notation.
"""
from __future__ import annotations

import re

# The formulas' notation in the (translated) source text, typeset by ``typeset``:
# a^k_A4A3 → a with k above and A4A3 below, a^k → a with k above, v_A4 and ω_max → v, ω with
# A4, max below, O4/L1/S4/ω4 → O, L, S, ω with
# the digit below, (1/2π) → a slanted fraction.
_NOTATION = re.compile(r"(?<![A-Za-z0-9])(?P<base>[A-Za-zΔ]{1,2})\^(?P<sup>[a-z])_(?P<sub>[A-Za-z0-9]+)"
                       r"|(?<![A-Za-z0-9])(?P<base1>[A-Za-z])\^(?P<sup1>[a-z])(?![A-Za-z0-9_])"
                       r"|(?<![A-Za-z0-9])(?P<base2>[A-Za-zΔωαψ]{1,2})_(?P<sub2>[A-Za-z0-9]+)"
                       r"|(?<![A-Za-z_])(?P<name>[OLSωαψr])(?P<digit>\d)"
                       r"|\((?P<num>\d)/(?P<den>\d?π)\)")


def typeset(text: str) -> str:
    """Rich text of a formula paragraph: sub- and superscripts and fractions in HTML
    (QTextDocument prints them in the PDF), from the plain notation of the source."""
    def one(m: re.Match) -> str:
        if m["base"]:
            return f"{m['base']}<sup>{m['sup']}</sup><sub>{m['sub']}</sub>"
        if m["base1"]:
            return f"{m['base1']}<sup>{m['sup1']}</sup>"
        if m["base2"]:
            return f"{m['base2']}<sub>{m['sub2']}</sub>"
        if m["name"]:
            return f"{m['name']}<sub>{m['digit']}</sub>"
        return f"(<sup>{m['num']}</sup>⁄<sub>{m['den']}</sub>)"
    return _NOTATION.sub(one, text)


# superscript letters that fonts carry (Unicode's modifier letters): the notation's a^k,
# a^n, a^t and a^r
_SUPERSCRIPT = dict(zip("abcdefghijklmnoprstuvwxyz", "ᵃᵇᶜᵈᵉᶠᵍʰⁱʲᵏˡᵐⁿᵒᵖʳˢᵗᵘᵛʷˣʸᶻ"))


def on_screen(text: str) -> str:
    """Plain text of a label for a widget that shows no rich text (a table's header): a
    superscript letter as its modifier letter (a^k → aᵏ), an index run on after its base
    (v_A3A4 → vA3A4), as the window writes O2O4 and ω4; the rest as it is."""
    def one(m: re.Match) -> str:
        if m["base"]:
            return m["base"] + _SUPERSCRIPT.get(m["sup"], m["sup"]) + m["sub"]
        if m["base1"]:
            return m["base1"] + _SUPERSCRIPT.get(m["sup1"], m["sup1"])
        if m["base2"]:
            return m["base2"] + m["sub2"]
        return m[0]
    return _NOTATION.sub(one, text)
