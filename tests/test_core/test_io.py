"""Design files and CSV: atomic saves, refusal of corrupt or foreign files."""
import json

import numpy as np
import pytest

from core.base.errors import FileFormatError
from core.files.io import atomic_write, curve_table, curves_csv, load_design, save_design
from core.linkage.geometry import synthesize
from core.linkage.kinematics import crank_angles, solve
from core.linkage.spec import Spec


def test_round_trip(tmp_path):
    spec = Spec(variant="rod", rod_ratio=0.35, time_ratio=1.6, guide_rule="sagitta")
    path = tmp_path / "d.json"
    save_design(path, spec, [30, 45.5], 0.5)
    doc = load_design(path)
    assert doc["spec"] == spec and doc["rpm"] == [30, 45.5] and doc["step_deg"] == 0.5


@pytest.mark.parametrize("content", [
    b"", b"\x00\xff\xfe", b"not json", b"[]", b'{"format": "other"}',
    b'{"format": "shaper-design", "version": 99, "spec": {}}',
    b'{"format": "shaper-design", "version": 1, "spec": {"time_ratio": 0.5}}',
    b'{"format": "shaper-design", "version": 1, "spec": {"time_ratio": "x"}}',
    b'{"format": "shaper-design", "version": 1, "spec": {"colour": 1}}',
    b'{"format": "shaper-design", "version": 1, "spec": {"crank": NaN}}',
    b'{"format": "shaper-design", "version": 1, "spec": {}, "rpm": [0]}',
    b'{"format": "shaper-design", "version": 1, "spec": {}, "rpm": "fast"}',
    b'{"format": "shaper-design", "version": 1, "spec": {}, "step_deg": -1}',
])
def test_corrupt_files_are_refused(tmp_path, content):
    path = tmp_path / "bad.json"
    path.write_bytes(content)
    with pytest.raises(FileFormatError) as info:
        load_design(path)
    assert str(path) in str(info.value)
    assert path.read_bytes() == content  # untouched


def test_missing_file(tmp_path):
    with pytest.raises(FileFormatError):
        load_design(tmp_path / "nope.json")


def test_atomic_write_keeps_old_file_on_failure(tmp_path, monkeypatch):
    path = tmp_path / "f.txt"
    path.write_text("old")

    class Boom(Exception):
        pass

    def failing_fsync(fd):
        raise Boom()

    monkeypatch.setattr("os.fsync", failing_fsync)
    with pytest.raises(Boom):
        atomic_write(path, "new content")
    assert path.read_text() == "old"
    assert [p.name for p in tmp_path.iterdir()] == ["f.txt"]  # no temp file left behind


def test_csv_table_is_long_form():
    motion = solve(synthesize(100, 1.4, 300), crank_angles(30), [40, 60, 80])
    names, data = curve_table(motion)
    assert data.shape == (3 * 13, len(names))
    assert np.array_equal(data[:13, 0], np.full(13, 40.0))
    assert np.array_equal(data[13:26, 1], np.degrees(motion.crank_angle))
    text = curves_csv(motion)
    parsed = np.loadtxt(text.splitlines()[1:], delimiter=",")
    assert np.allclose(parsed, data, rtol=1e-9, atol=1e-12)
    assert json.dumps(list(names))  # names are plain ASCII identifiers with units
    assert all(n.isascii() for n in names)


def test_loads_round_trip_and_refusal(tmp_path):
    from core.forces.masses import MassProperties
    from core.files.io import masses_to_dict
    masses = MassProperties(lever_mass_kg=22.5, lever_cg_mm=250.0, ram_mass_kg=60, ram_cg_mm=(-30.0, 45.0),
                            cut_force_N=5000, gravity=False, delta=0.05)
    path = tmp_path / "m.json"
    save_design(path, Spec(), [40], 1.0, extra={"forces": masses_to_dict(masses)})
    assert load_design(path)["masses"] == masses
    doc = json.loads(path.read_text())
    for bad in ({"ram_mass_kg": -1}, {"delta": 0}, {"ram_cg_mm": [1]}, {"wheels": 4}, {"cut_force_N": "big"}, []):
        doc["forces"] = bad
        path.write_text(json.dumps(doc))
        with pytest.raises(FileFormatError):
            load_design(path)
