"""CPU time of one report built in process: ``python tools/report_cpu.py DESIGN.json [en|zh] [N]``.

Why: most of the suite's report time is reports built in the test's own process after
others (Qt, the imports, the cam's synthesis and the fonts already there), which a whole
``shaper report`` process does not show. This builds the report of a design file (its
cam and gear pair included, as ``shaper report --design`` does) and its PDF once to warm
up, then N times (default 3), and prints ``measured M ms``: the least CPU time (user +
system, of this process) of one build and PDF, which ``tools/perf_alternate.py`` reads.
Run it with ``PYTHONPATH`` on the tree to time. Only a developer's tool.
"""
from __future__ import annotations

import argparse
import sys
import time


def main(argv: list[str]) -> int:
    from shaperapp.report import command
    from shaperapp.widgets.command_line import start_qt
    words = argparse.ArgumentParser()
    words.add_argument("design")
    words.add_argument("lang", nargs="?", default="en")
    words.add_argument("rounds", nargs="?", type=int, default=3)
    mine = words.parse_args(argv)
    parser = argparse.ArgumentParser()
    command.configure(parser)
    args = parser.parse_args(["--design", mine.design, "--lang", mine.lang, "-o", "unused.pdf"])
    language = start_qt(args.lang)
    from core.cam.file import cam_from_dict
    from core.cli.common import design_file
    from core.gear.file import gear_from_dict
    from shaperapp.report.blocks import Cover
    from shaperapp.report.content import Options, build
    from shaperapp.report.pdf import pdf_bytes
    spec, rpms, masses = command.inputs_from_args(args)
    doc = design_file(args) or {}
    cam = cam_from_dict(doc["cam"]) if doc.get("cam") is not None else None
    gear = gear_from_dict(doc["gear"]) if doc.get("gear") is not None else None
    options = Options(12, None, (), Cover(), cam, gear)
    times = []
    for _ in range(mine.rounds + 1):
        start = time.process_time()
        pdf_bytes(build(spec, rpms, masses, "report", "2026-11-30", language, options))
        times.append(time.process_time() - start)
    print(f"measured {round(1000 * min(times[1:]))} ms")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
