"""``shaper``: the whole computation without a screen.

One module per subcommand (``cmd_*.py``), each with ``configure(parser)`` and
``run(args)``; this module only builds the parser and turns every failure
into one line on stderr. Bad input exits with status 2 and names the option;
nothing ever prints a traceback.

Subcommands whose code lives outside ``core`` (the report needs Qt) are
found through the ``shaper.commands`` entry-point group, so ``core`` itself
never imports Qt.
"""
from __future__ import annotations

import argparse
import os
import sys
from importlib import import_module, metadata
from types import ModuleType
from typing import Sequence

from ..errors import DesignError, FileFormatError
from .common import Parser, UsageError, design_error_text, fail, version_text
from .output import GuardedStdout, OutputError, StdoutError, install_safe_output

# Order is the order of ``shaper --help``.
CORE_COMMANDS = ("synth", "curves", "analyze", "dynamics", "table", "sweep", "optimize", "library")


def _command_modules() -> dict[str, ModuleType]:
    modules = {name: import_module(f"{__name__}.cmd_{name}") for name in CORE_COMMANDS}
    try:
        entries = metadata.entry_points(group="shaper.commands")
    except Exception:  # a broken installation must not stop the core commands
        entries = ()
    for entry in entries:
        if entry.name not in modules:
            try:
                modules[entry.name] = import_module(entry.value)
            except ImportError:
                continue
    return modules


def build_parser(modules: dict[str, ModuleType] | None = None) -> argparse.ArgumentParser:
    modules = _command_modules() if modules is None else modules
    parser = Parser(prog="shaper",
                    description="Shaper quick-return mechanism (crank, slotted lever, ram): "
                                "synthesis, kinematics, forces and files, without a screen.",
                    epilog="Run 'shaper COMMAND --help' for the options and an example of each command.")
    parser.add_argument("--version", action="version", version=version_text("shaper"))
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=Parser)
    for name, module in modules.items():
        p = sub.add_parser(name, help=module.HELP, description=module.DESCRIPTION,
                           epilog="example:\n  " + "\n  ".join(module.EXAMPLES),
                           formatter_class=argparse.RawDescriptionHelpFormatter)
        module.configure(p)
        p.set_defaults(_run=module.run)
    return parser


def run(argv: Sequence[str] | None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    if args.command is None:
        parser.print_help()
        return 0
    return args._run(args)


def main(argv: Sequence[str] | None = None) -> int:
    install_safe_output()
    stdout = sys.stdout
    sys.stdout = GuardedStdout(stdout)  # type: ignore[assignment]
    try:
        status = run(argv)
        sys.stdout.flush()
        return status
    except UsageError as exc:
        return fail(str(exc))
    except DesignError as exc:
        return fail(design_error_text(exc))
    except FileFormatError as exc:
        return fail(f"--design: {exc}")
    except StdoutError as exc:
        _silence_stdout()
        return fail(str(exc))
    except OutputError as exc:
        return fail(str(exc))
    except BrokenPipeError:
        # The reader went away (``shaper curves | head``): nothing more can be written.
        _silence_stdout()
        return 0
    except MemoryError:
        return fail("not enough memory for this request; ask for fewer crank angles or speeds")
    except KeyboardInterrupt:
        return fail("interrupted", status=130)
    except Exception as exc:  # never a traceback; the one line says what broke
        return fail(f"internal error ({type(exc).__name__}: {exc}); please report it", status=1)
    finally:
        if isinstance(sys.stdout, GuardedStdout):
            sys.stdout = stdout


def _silence_stdout() -> None:
    """Point stdout at /dev/null, so that the interpreter's final flush of what is still
    buffered cannot fail a second time and print a traceback-like warning at exit."""
    try:
        fd = sys.stdout.fileno()
    except (AttributeError, ValueError, OSError):
        return          # not a real descriptor (tests capture into a StringIO)
    try:
        null = os.open(os.devnull, os.O_WRONLY)
        os.dup2(null, fd)
        os.close(null)
    except OSError:
        pass


if __name__ == "__main__":
    sys.exit(main())
