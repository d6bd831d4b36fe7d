"""``python -m core`` is the ``shaper`` command, and ``main`` here is its entry point.

Why not ``core.cli.main`` directly: the command's own process loads numpy and the
engine without Python's automatic garbage collection. Their modules' objects stay alive,
so the ~40 collections among them took about 5 ms, a fortieth of a short command, to
find 285 objects of garbage. What loading made is then frozen (later collections skip
it; those few objects stay until the command ends) and collection runs as usual. Code
that imports ``core.cli`` keeps its collector as it is.
"""
from __future__ import annotations

import gc
import sys
from collections.abc import Callable, Sequence


def load(engine: bool = True) -> Callable[[Sequence[str] | None], int]:
    """Import the command line (``core.cli.main``) as described above, and with it numpy
    and the engine's first floors that every command computing something needs (the
    command line's own modules import them where used, so that ``shaper COMMAND --help``
    loads none of them: ``engine=False``)."""
    collecting = gc.isenabled()
    gc.disable()
    from .cli import main as run
    if engine:
        import core.files.io  # noqa: F401  (numpy, the linkage, the design files)
        import core.linkage.kinematics  # noqa: F401
    gc.freeze()
    if collecting:
        gc.enable()
    return run


def main(argv: Sequence[str] | None = None) -> int:
    words = sys.argv[1:] if argv is None else list(argv)
    if list(words) == ["--version"]:
        return print_version()
    # a help (and ``shaper`` alone, which prints one) loads no engine: see ``load``
    return load(engine=bool(words) and not {"-h", "--help"} & set(words))(argv)


def print_version() -> int:
    """``shaper --version`` prints the installed version without loading the command line:
    building the parser of every subcommand imports every command's module and the entry
    points' (``importlib.metadata``), about half a second of start-up at load 6, to print
    one line (issue 43 item 5; numpy, ezdxf and Qt too before the commands' helps shed them)."""
    from .version import version_text
    print(version_text("shaper"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
