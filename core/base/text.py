"""What one line of user text (a name, a title, a tag, a cover field) may hold: one set of
rules for every text option and the library's names (issue 33), and what a multi-line
text (a library entry's notes) and a terminal may be given (issue 42)."""
from __future__ import annotations

import re

# Unicode's 66 noncharacters: U+FDD0..U+FDEF and the last two code points of every plane
# (U+FFFE, U+FFFF, U+1FFFE …). XML 1.0 forbids U+FFFE/U+FFFF outright (an SVG holding one is
# "not well-formed"), and Unicode reserves all of them for a program's internal use: text
# exchanged in a file must not hold them (issue 42).
NONCHARACTERS = "\ufdd0-\ufdef" + "".join(
    chr(plane * 0x10000 + 0xFFFE) + chr(plane * 0x10000 + 0xFFFF) for plane in range(17))
# Unicode's explicit bidirectional embeddings, overrides and isolates (U+202A..U+202E,
# U+2066..U+2069): invisible, they reorder the rest of the line they stand in, so a student
# "a\u202efdp.exe" got the folder 1-a<RLO>fdp.exe, shown as "1-aexe.pdf", and the same
# reversed text on the task sheet and in the terminal (the "Trojan Source" characters,
# CVE-2021-42574). A name never needs them: the bidirectional algorithm orders Arabic and
# Hebrew by itself (the implicit marks U+200E/U+200F stay allowed).
BIDI_CONTROLS = "\u202a-\u202e\u2066-\u2069"
# The C0 and C1 control characters (U+0085, a line break, among them), DEL, and U+2028/U+2029:
# every line break str.splitlines() knows; the bidi controls; and the noncharacters: what no
# text option accepts.
CONTROL = re.compile(f"[\x00-\x1f\x7f-\x9f\u2028\u2029{BIDI_CONTROLS}{NONCHARACTERS}]")
# CONTROL, and a byte the system could not decode (Python keeps it as a lone surrogate, which
# no UTF-8 writer accepts: DXF and HTML failed on it, PDF and SVG wrote a replacement).
UNPRINTABLE = re.compile(f"[\x00-\x1f\x7f-\x9f\u2028\u2029{BIDI_CONTROLS}\ud800-\udfff{NONCHARACTERS}]")
UNDECODABLE = re.compile("[\ud800-\udfff]")
# What a multi-line text (notes) may not hold: CONTROL but its line breaks (LF, CR LF) and tab.
NOTE_FORBIDDEN = re.compile(f"[\x00-\x08\x0b\x0c\x0e-\x1f\x7f-\x9f\u2028\u2029{BIDI_CONTROLS}\ud800-\udfff{NONCHARACTERS}]"
                            "|\r(?!\n)")


def terminal_text(text: str, multi_line: bool = False) -> str:
    """``text`` as a terminal can print it without obeying it: every control character (ESC
    would start an escape sequence that retitles the window or clears the screen, CR and LF
    break a table's row), noncharacter and undecodable byte as its Python escape (``\\x1b``,
    ``\\n``, ``\\uffff``), the backslash left as it is. With ``multi_line`` LF and tab are
    kept (a note's lines). For what a file brings (a library's names and notes)."""
    pattern = NOTE_FORBIDDEN if multi_line else UNPRINTABLE
    return pattern.sub(lambda m: m.group().encode("unicode_escape").decode("ascii"), text)
