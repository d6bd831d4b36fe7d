"""What one line of user text (a name, a title, a tag, a cover field) may hold: one set of
rules for every text option and the library's names (issue 33)."""
from __future__ import annotations

import re

# The C0 and C1 control characters (U+0085, a line break, among them), DEL, and U+2028/U+2029:
# every line break str.splitlines() knows, and what no text option accepts.
CONTROL = re.compile("[\x00-\x1f\x7f-\x9f\u2028\u2029]")
# CONTROL, and a byte the system could not decode (Python keeps it as a lone surrogate, which
# no UTF-8 writer accepts: DXF and HTML failed on it, PDF and SVG wrote a replacement).
UNPRINTABLE = re.compile("[\x00-\x1f\x7f-\x9f\u2028\u2029\ud800-\udfff]")
UNDECODABLE = re.compile("[\ud800-\udfff]")
