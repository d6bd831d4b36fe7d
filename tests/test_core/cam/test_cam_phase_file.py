"""A design file's cam is validated once, the same for every subcommand (issue 33, item 6):
a phase that is no angle (1e308°) is refused by all of them, naming the file; a cam value
from the file that does not fit the design names the file's key, not an option nobody gave."""
import json

import pytest

from cli_runner import shaper_in_process
from core.cam import Program
from core.cam.cam import CamInputs
from core.cam.file import cam_from_dict, cam_to_dict
from core.cam.timing import timing
from core.base.errors import DesignError
from core.linkage.spec import Spec

DESIGN = ["--crank", "100", "--K", "1.4", "--stroke", "300", "--rpm", "40"]


@pytest.mark.parametrize("phase", [1e308, -1e308, 36000.000001, -36000.5])
def test_a_phase_beyond_36000_degrees_is_refused(phase):
    data = cam_to_dict(CamInputs(), phase)
    with pytest.raises(DesignError) as info:
        cam_from_dict(data)
    assert info.value.parameter == "phase"
    with pytest.raises(DesignError) as info:
        timing(Program(), Spec().design(), 0.05, phase)
    assert info.value.parameter == "phase"


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    """A design file with loads (from a library) and copies with a cam: phase 1e308, and
    phase 100° (inside the cut of this design)."""
    folder = tmp_path_factory.mktemp("cam")
    lib, base = folder / "lib.sqlite", folder / "base.shaper.json"
    assert shaper_in_process("library", "add", *DESIGN, "--name", "d", "--library", lib)[0] == 0
    assert shaper_in_process("library", "export", "d", "-o", base, "--library", lib)[0] == 0
    doc = json.loads(base.read_text(encoding="utf-8"))
    out = {}
    for name, phase in (("huge", 1e308), ("cut", 100.0)):
        doc["cam"] = cam_to_dict(CamInputs(), phase)
        out[name] = folder / f"{name}.shaper.json"
        out[name].write_text(json.dumps(doc), encoding="utf-8")
    return out


@pytest.mark.parametrize("words", [["analyze"], ["curves"], ["table"], ["dynamics"], ["synth"], ["cam"],
                                   ["library", "add", "--name", "x", "--library", "{tmp}/l.sqlite"]])
def test_every_subcommand_refuses_the_file_alike(files, words, tmp_path):
    words = [w.replace("{tmp}", str(tmp_path)) for w in words]
    status, out, err = shaper_in_process(*words, "--design", files["huge"])
    assert status == 2 and out == ""
    assert err == (f"shaper: error: --design: {files['huge']}: invalid design "
                   "(phase = 1e+308: must be ≥ -36000 and ≤ 36000 °)\n")


def test_a_cam_value_of_the_file_is_named_as_the_files(files):
    status, _, err = shaper_in_process("cam", "--design", files["cut"])
    assert status == 2
    assert err.startswith("shaper: error: --design (cam.phase_deg): feeds during the cut") and "(got 100)" in err
    status, _, err = shaper_in_process("cam", "--design", files["cut"], "--phase", "90")
    assert status == 2 and err.startswith("shaper: error: --phase: feeds during the cut")
