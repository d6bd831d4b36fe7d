"""A separate process that writes to a library, for the concurrency and kill tests.

``python library_writer.py LIBRARY PREFIX COUNT [--fast]`` adds COUNT entries named
PREFIX-0, PREFIX-1, … and prints each name on its own line right after its commit.
``--fast`` computes one entry and stores copies of it, so nearly all the time is
spent inside write transactions (where a kill should hurt most).
"""
import sys
from dataclasses import replace

from core.forces.masses import MassProperties
from core.library import Library
from core.linkage.spec import Spec


def main() -> int:
    path, prefix, count = sys.argv[1], sys.argv[2], int(sys.argv[3])
    fast = "--fast" in sys.argv
    masses = MassProperties(lever_mass_kg=20.0, lever_inertia_kg_m2=1.1, ram_mass_kg=70.0,
                            cut_force_N=7000.0)
    with Library(path) as lib:
        template = None
        for i in range(count):
            name = f"{prefix}-{i}"
            if fast:
                if template is None:
                    template = lib.make_entry(name, {"spec": Spec(), "rpm": [40.0, 60.0],
                                                     "step_deg": 1.0, "masses": masses},
                                              notes="x" * 2000, tags=["kill"])
                lib.add_entries([replace(template, name=name)])
            else:
                spec = Spec(time_ratio=1.3 + (i % 7) * 0.05, variant="rod" if i % 2 else "block")
                lib.add(name, {"spec": spec, "rpm": [40.0, 60.0], "step_deg": 1.0, "masses": masses})
            print(name, flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
