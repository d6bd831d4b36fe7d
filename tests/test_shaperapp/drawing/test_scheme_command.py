"""``shaper drawing --content scheme``: the mechanism for CAD from the command line."""
import math

import ezdxf
import numpy as np
import pytest

from cli_runner import shaper, shaper_in_process
from dxf_checks import measurement
from core.linkage.geometry import from_dimensions
from core.linkage.kinematics import shape

ROD = ["--dims", "100,380,600,250", "--guide", "560", "--rpm", "40"]


def test_writes_the_design_at_the_angle(tmp_path):
    out = tmp_path / "机构.dxf"
    status, stdout, stderr = shaper_in_process("drawing", *ROD, "--content", "scheme",
                                               "--angle", "200", "-o", out)
    assert status == 0, stderr
    assert str(out) in stdout
    design = from_dimensions(100, 380, 600, rod=250, guide=560)
    doc = ezdxf.readfile(out)
    assert doc.header["$INSUNITS"] == 4 and not doc.audit().has_errors
    dims = {d.dxf.text.split(" = ")[0]: d for d in doc.modelspace().query("DIMENSION")}
    lengths = {"L1": 100, "L2": 380, "L3": 600, "L4": 250, "h": 560 - 380}
    for name, value in lengths.items():
        assert dims[name].get_measurement() == pytest.approx(value, abs=1e-6), name
    ends = [np.array(dims["L4"].dxf.defpoint2)[:2], np.array(dims["L4"].dxf.defpoint3)[:2]]
    b = shape(design, np.radians([200.0])).lever_tip[:, 0]
    assert any(np.allclose(p, b, atol=1e-9) for p in ends)
    assert math.isclose(measurement(dims["θ"]), math.degrees(design.theta), abs_tol=1e-9)


def test_default_angle_is_zero(tmp_path):
    out = tmp_path / "s.dxf"
    status, _, stderr = shaper_in_process("drawing", *ROD, "--content", "scheme", "-o", out)
    assert status == 0, stderr
    design = from_dimensions(100, 380, 600, rod=250, guide=560)
    dim = next(d for d in ezdxf.readfile(out).modelspace().query("DIMENSION") if d.dxf.text.startswith("L3"))
    tip = max((np.array(dim.dxf.defpoint2)[:2], np.array(dim.dxf.defpoint3)[:2]), key=lambda p: np.hypot(*p))
    # at φ = 0 the lever stands at its left limit: θ/2 left of the vertical
    assert tip == pytest.approx(design.lever * np.array([-math.sin(design.theta / 2),
                                                         math.cos(design.theta / 2)]), abs=1e-9)


@pytest.mark.parametrize("words, option", [
    (["--angle", "-1"], "--angle"),
    (["--angle", "360.5"], "--angle"),
    (["--angle", "nan"], "--angle"),
    (["--angle", "x"], "--angle"),
])
def test_bad_angle_exits_2_naming_it(words, option, tmp_path):
    out = tmp_path / "s.dxf"
    status, _, stderr = shaper_in_process("drawing", *ROD, "--content", "scheme", *words, "-o", out)
    lines = stderr.strip().splitlines()
    assert status == 2 and len(lines) == 1 and option in lines[0], stderr
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("name", ["s.pdf", "s.svg", "s", "missing/s.dxf"])
def test_other_suffix_or_missing_folder_exits_2_naming_output(name, tmp_path):
    status, _, stderr = shaper_in_process("drawing", *ROD, "--content", "scheme", "-o", tmp_path / name)
    lines = stderr.strip().splitlines()
    assert status == 2 and len(lines) == 1 and "--output" in lines[0], stderr
    assert list(tmp_path.iterdir()) == []


@pytest.mark.slow
def test_real_process(tmp_path):
    """The installed command, in its own process: no Qt needed, one line on stdout."""
    out = tmp_path / "s.dxf"
    result = shaper("drawing", "--crank", "100", "--K", "1.4", "--stroke", "300", "--content", "scheme",
                    "--angle", "90", "-o", out)
    assert result.returncode == 0 and result.stderr == "", result.stderr
    assert result.stdout.strip() == f"wrote {out} (scheme at φ = 90°, 1:1 in mm, DXF)"
    assert ezdxf.readfile(out).header["$INSUNITS"] == 4
