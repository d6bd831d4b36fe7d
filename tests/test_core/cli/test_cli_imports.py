"""``shaper curves`` imports only what it needs (issue 24, item 1): a short command's
time is mostly start-up, and every module it loads is paid on every call."""
from __future__ import annotations

import subprocess
import sys

PROBE = """
import sys
from core.cli import main
status = main(["curves", "--crank", "100", "--K", "1.4", "--stroke", "300", "--rpm", "40", "60",
               "--step", "1", "--csv", sys.argv[1]])
WATCHED = ("core.linkage.metrics", "core.forces.dynamics", "core.cam", "core.library",
           "core.space.sweep", "core.space.optimize", "core.drawing", "core.forces.flywheel", "scipy", "ezdxf",
           "numpy.ma.", "importlib.metadata", "hashlib", "secrets")
print(status, sorted(m for m in sys.modules if m.startswith(WATCHED)))
"""


def test_curves_imports_no_metrics_loads_cam_or_library(tmp_path):
    out = subprocess.run([sys.executable, "-c", PROBE, str(tmp_path / "c.csv")], capture_output=True,
                         text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "0 []"
    assert (tmp_path / "c.csv").read_text().count("\n") == 2 * 361 + 1


def test_a_design_file_with_loads_and_a_cam_still_reads_them(tmp_path):
    """The cam's and the loads' modules come in when a file holds them (the lazy imports
    in core.files.design_file must not lose their checks)."""
    from core.cli import main
    from core.files.io import save_design
    from core.linkage.spec import Spec
    path = tmp_path / "d.json"
    save_design(path, Spec(), [40.0], 1.0, extra={"forces": {"ram_mass_kg": "heavy"}})
    assert main(["curves", "--design", str(path), "--csv", str(tmp_path / "c.csv")]) == 2
    save_design(path, Spec(), [40.0], 1.0, extra={"cam": {"arm_mm": -1}})
    assert main(["curves", "--design", str(path), "--csv", str(tmp_path / "c.csv")]) == 2
    assert not (tmp_path / "c.csv").exists()


ENTRY_PROBE = """
import gc, sys
collections = []
gc.callbacks.append(lambda phase, info: phase == "stop" and collections.append(info["generation"]))
from core.__main__ import load
collections.clear()
run = load()
print("numpy" in sys.modules, collections, gc.isenabled(), gc.get_freeze_count() > 1000)
print(run(["curves", "--crank", "100", "--K", "1.4", "--stroke", "300", "--rpm", "40",
           "--step", "1", "--csv", sys.argv[1]]))
"""


def test_the_command_loads_without_garbage_collection_and_then_collects_as_usual(tmp_path):
    """The ``shaper`` entry point (pyproject's script, ``python -m core``) loads numpy and
    the engine with Python's collector paused (about 5 ms of a short command), freezes
    what loading made, and leaves collection on for the run."""
    out = subprocess.run([sys.executable, "-c", ENTRY_PROBE, str(tmp_path / "c.csv")],
                         capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip().splitlines() == ["True [] True True", "0"]
    assert (tmp_path / "c.csv").read_text().count("\n") == 361 + 1


def test_the_installed_command_is_that_entry_point():
    import tomllib
    from pathlib import Path
    project = tomllib.loads((Path(__file__).parents[3] / "pyproject.toml").read_text())
    assert project["project"]["scripts"]["shaper"] == "core.__main__:main"


REPORT_PROBE = """
import contextlib, io, sys
from core.cli import main
with contextlib.redirect_stdout(io.StringIO()) as out:
    try:
        main(["report", "--help"])
    except SystemExit as exc:
        print("exit", exc.code, file=sys.stderr)
print("--positions" in out.getvalue(),
      sorted(m for m in sys.modules if m.startswith(("ezdxf", "shaperapp.drawing", "shaperapp.course",
                                                     "core.cli.cmd_sweep", "core.cli.cmd_optimize"))))
"""


def test_an_entry_point_command_loads_its_own_module_only():
    """``shaper report`` loads the report's entry point, not the drawing's (ezdxf, the
    sheets) and the course's, nor the core commands it does not use: about 0.3 s of
    every ``shaper report`` (0.50 → 0.18 s for ``shaper report --help``)."""
    out = subprocess.run([sys.executable, "-c", REPORT_PROBE], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert "exit 0" in out.stderr
    assert out.stdout.strip() == "True []"


HELP_PROBE = """
import sys
from core.__main__ import main
try:
    main([sys.argv[1], "--help"])
except SystemExit as done:
    status = done.code
print(status, sorted({m.split(".")[0] for m in sys.modules} & {"PySide6", "ezdxf", "scipy", "pyqtgraph"}))
"""


def test_a_commands_help_imports_no_qt_ezdxf_or_scipy():
    """``shaper COMMAND --help`` prints its parser's help without Qt, ezdxf or scipy (issue
    43 item 5: ``shaper drawing --help`` imported both Qt and ezdxf, 1.5-3 s here)."""
    for command in ("analyze", "cam", "report", "drawing", "course", "class"):
        out = subprocess.run([sys.executable, "-c", HELP_PROBE, command], capture_output=True, text=True,
                             timeout=120)
        assert out.returncode == 0, out.stderr
        assert out.stdout.splitlines()[-1] == "0 []", command


ENGINE_PROBE = """
import sys
from core.__main__ import main
try:
    main(["gear", "--help"])
except SystemExit as done:
    status = done.code
print(status, sorted(m for m in sys.modules if m.split(".")[0] in ("numpy", "scipy", "ezdxf", "PySide6")
                     or m.startswith(("core.gear.", "core.linkage.", "core.files.io", "core.forces."))))
"""


def test_gear_help_imports_neither_numpy_nor_the_engine():
    """``shaper gear --help`` prints its parser's texts without numpy, the gear pair's
    modules or the linkage (issue 43 item 5: every command's shared module imported them,
    0.6 s against 1.5 s for the help at load 5)."""
    out = subprocess.run([sys.executable, "-c", ENGINE_PROBE], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert "--contact-limit" in out.stdout
    assert out.stdout.splitlines()[-1] == "0 []"


HEAVY = ("numpy", "scipy", "ezdxf", "pikepdf", "PySide6")


def _command_paths(parser, path=()):
    """Every (sub)command the parser knows, as the words that name it: () for ``shaper``
    itself, ("library", "add") for an action."""
    import argparse
    yield path
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for name, sub in action.choices.items():
                yield from _command_paths(sub, (*path, name))


def test_every_commands_help_imports_no_numpy_scipy_ezdxf_pikepdf_or_qt():
    """``shaper COMMAND --help`` (and ``shaper --help``, ``shaper library add --help`` …)
    prints its parser's texts with none of the engine's heavy packages (issue 43 item 5:
    every command but gear's imported numpy and the engine for it, ~1.5 s on a quiet
    machine against 0.31 s for numpy alone). The commands are those the parser knows,
    entry points included, so a new one is checked without naming it here."""
    from core.cli import build_parser
    paths = list(_command_paths(build_parser()))
    assert ("library", "add") in paths and ("report",) in paths     # the walk reaches actions and entry points
    heavy = {}
    for words in paths:
        done = subprocess.run([sys.executable, "-X", "importtime", "-m", "core", *words, "--help"],
                              capture_output=True, text=True, timeout=120)
        assert done.returncode == 0, (words, done.stderr[-2000:])
        assert done.stdout.startswith(" ".join(("usage: shaper", *words))), words
        loaded = sorted({line.rsplit("|", 1)[-1].strip().split(".")[0] for line in done.stderr.splitlines()
                         if line.startswith("import time:")} & set(HEAVY))
        if loaded:
            heavy[" ".join(words) or "shaper"] = loaded
    assert heavy == {}
