"""File actions without dialogs: round trip, refusal of corrupt files, CSV like the CLI."""
import json

import pytest
from PySide6.QtCore import QSettings

from shaperapp.design.document import Document
from shaperapp.design.model import DesignModel

# What the CLI writes, through core.cli.main in this process (the console script as a process
# is tests/test_core/cli/test_cli.py's): no second start of Python for a CSV.
from cli_runner import shaper_run_in_process as shaper


@pytest.fixture
def doc(qtbot, tmp_path):
    model = DesignModel()
    settings = QSettings(str(tmp_path / "settings.ini"), QSettings.Format.IniFormat)
    return model, Document(model, settings)


def test_save_open_round_trip(doc, tmp_path, qtbot):
    model, document = doc
    model.set_spec(variant="rod", rod_input="length", rod_length=180.0, rod_side="leading", time_ratio=1.5)
    model.set_rpms([35, 70])
    model.set_step(0.5)
    assert model.dirty
    path = str(tmp_path / "a.shaper.json")
    assert document.save_to(path)
    assert not model.dirty and model.path == path
    other = DesignModel()
    Document(other, QSettings(str(tmp_path / "s2.ini"), QSettings.Format.IniFormat)).open_path(path)
    assert other.valid_spec == model.valid_spec and other.design == model.design
    assert other.rpms == (35.0, 70.0) and other.step_deg == 0.5 and not other.dirty
    assert document.recent_files()[0] == path


def test_saving_while_invalid_saves_the_design_on_screen(doc, tmp_path):
    model, document = doc
    model.set_spec(time_ratio=1.6)
    model.set_spec(stroke=-3.0)
    assert model.error is not None and model.valid_spec.time_ratio == 1.6
    path = str(tmp_path / "b.json")
    assert document.save_to(path)
    other = DesignModel()
    Document(other, QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat)).open_path(path)
    assert other.design.time_ratio == pytest.approx(1.6) and other.design.stroke == pytest.approx(300)


@pytest.mark.parametrize("content", ["{broken", '{"format": "shaper-design", "version": 1, "spec": {"stroke": -1}}'])
def test_corrupt_file_refused_and_nothing_changes(doc, tmp_path, qtbot, content):
    model, document = doc
    model.set_spec(time_ratio=1.6)
    before = (model.spec, model.design, model.rpms, model.dirty, model.path)
    bad = tmp_path / "bad.json"
    bad.write_text(content)
    with (qtbot.waitSignal(document.failed, timeout=10_000) as blocker,
          qtbot.assertNotEmitted(model.resultsChanged)):
        assert not document.open_path(str(bad))
    assert "bad.json" in blocker.args[0]
    assert (model.spec, model.design, model.rpms, model.dirty, model.path) == before
    assert bad.read_text() == content


def test_save_to_unwritable_place_reports(doc, tmp_path, qtbot):
    model, document = doc
    target = str(tmp_path / "missing-dir" / "x.json")
    with qtbot.waitSignal(document.failed, timeout=10_000) as blocker:
        assert not document.save_to(target)
    assert model.path == "" and target in blocker.args[0] and ".tmp" not in blocker.args[0]
    csv = str(tmp_path / "missing-dir" / "c.csv")
    with qtbot.waitSignal(document.failed, timeout=10_000) as blocker:
        assert not document.export_csv_to(csv)
    assert csv in blocker.args[0] and ".tmp" not in blocker.args[0]


def test_csv_export_equals_cli_output(doc, tmp_path):
    model, document = doc
    model.set_spec(variant="rod", rod_ratio=0.3, guide_rule="sagitta", time_ratio=1.5, stroke=320.0)
    model.set_rpms([40, 60, 80])
    model.set_step(2.0)
    path = tmp_path / "gui.csv"
    assert document.export_csv_to(str(path))
    cli = shaper("curves", "--crank", "100", "--K", "1.5", "--stroke", "320", "--rod-ratio", "0.3",
                 "--guide", "sagitta", "--rpm", "40", "60", "80", "--step", "2")
    assert cli.returncode == 0, cli.stderr
    assert path.read_text() == cli.stdout


def test_loads_are_saved_with_the_design(doc, tmp_path):
    model, document = doc
    model.set_masses(ram_mass_kg=55.0, cut_force_N=4000.0, ram_cg_mm=(10.0, -20.0))
    path = str(tmp_path / "loads.json")
    assert document.save_to(path)
    other = DesignModel()
    Document(other, QSettings(str(tmp_path / "s3.ini"), QSettings.Format.IniFormat)).open_path(path)
    assert other.masses == model.masses and other.masses.ram_cg_mm == (10.0, -20.0)


def test_forces_csv_export_equals_cli_output(doc, tmp_path):
    model, document = doc
    model.set_spec(variant="rod", rod_ratio=0.3)
    model.set_step(5.0)
    path = tmp_path / "forces.csv"
    assert document.export_forces_csv_to(str(path))
    m = model.masses
    cli = shaper("dynamics", "--crank", "100", "--K", "1.4", "--stroke", "300", "--rod-ratio", "0.3",
                 "--rpm", "40", "60", "--step", "5", "--lever-mass", m.lever_mass_kg,
                 "--lever-inertia", m.lever_inertia_kg_m2, "--ram-mass", m.ram_mass_kg,
                 "--cut-force", m.cut_force_N, "--cut-height", m.cut_height_mm, "--csv", "-")
    assert cli.returncode == 0, cli.stderr
    assert path.read_text() == cli.stdout


def test_open_then_save_keeps_the_gear_pair(doc, tmp_path):
    """A part of the design file that no model registered (here the "gear" object: the bare
    design model has no gear model, the window has one) comes back from Open then Save as it
    was written, never dropped (a lost part is a lost file); New forgets it."""
    import json
    model, document = doc
    gear = {"z1": 13, "z2": 40, "module_mm": 6, "centre_mm": 162}
    source = tmp_path / "g.shaper.json"
    assert document.save_to(str(source))
    data = json.loads(source.read_text(encoding="utf-8"))
    source.write_text(json.dumps({**data, "gear": gear}), encoding="utf-8")
    assert document.open_path(str(source))
    model.set_spec(time_ratio=1.5)                        # an edit, then Save elsewhere
    target = tmp_path / "h.shaper.json"
    assert document.save_to(str(target))
    assert json.loads(target.read_text(encoding="utf-8"))["gear"] == gear
    model.load_state(model.valid_spec, model.rpms, model.step_deg)   # as File › New does
    assert "gear" not in model.saved_parts()


def test_open_then_save_keeps_a_later_versions_part(doc, tmp_path):
    """A top-level key this program does not know (a part a later version adds to a
    version-1 file, as the cam and the gear were added) comes back from Open then Save as
    written, as ``shaper design --design`` keeps it: Open passed on only "cam" and "gear",
    and Save dropped the rest (hunt s13-hunt2)."""
    import json
    model, document = doc
    belt = {"pulley_mm": [80, 200], "note": "later"}
    source = tmp_path / "b.shaper.json"
    assert document.save_to(str(source))
    data = json.loads(source.read_text(encoding="utf-8"))
    source.write_text(json.dumps({**data, "belt": belt}), encoding="utf-8")
    assert document.open_path(str(source))
    model.set_spec(time_ratio=1.5)
    target = tmp_path / "c.shaper.json"
    assert document.save_to(str(target))
    saved = json.loads(target.read_text(encoding="utf-8"))
    assert saved["belt"] == belt and saved["spec"]["time_ratio"] == 1.5


def test_a_shaper_design_file_opens_in_the_gui_and_one_over_the_limit_is_refused(doc, tmp_path, qtbot):
    """One limit, core's (MAX_FILE_SAMPLES): the step ``shaper design`` advises for 16 speeds
    writes a file the GUI opens; a file over it (as ``shaper design`` wrote it before the
    limit: 16 × 7 201 = 115 216 samples) is refused on Open with core's reason, nothing changed."""
    import re
    model, document = doc
    speeds = [str(10 * (i + 1)) for i in range(16)]
    path = tmp_path / "fine.shaper.json"
    refused = shaper("design", "--crank", "100", "--K", "1.4", "--stroke", "300", "--rpm", *speeds,
                     "--step", "0.05", "-o", str(path))
    assert refused.returncode == 2 and not path.exists()
    advice = re.search(r"use a step of at least (\S+)°", refused.stderr).group(1)
    written = shaper("design", "--crank", "100", "--K", "1.4", "--stroke", "300", "--rpm", *speeds,
                     "--step", advice, "-o", str(path))
    assert written.returncode == 0, written.stderr
    assert document.open_path(str(path))
    assert model.step_deg == float(advice) and len(model.rpms) == 16 and model.error is None
    data = json.loads(path.read_text(encoding="utf-8"))
    over = tmp_path / "over.shaper.json"
    over.write_text(json.dumps({**data, "step_deg": 0.05}), encoding="utf-8")
    before = (model.spec, model.rpms, model.step_deg, model.path)
    with qtbot.waitSignal(document.failed, timeout=10_000) as blocker:
        assert not document.open_path(str(over))
    assert "115216" in blocker.args[0] and "60000" in blocker.args[0] and "0.0961" in blocker.args[0]
    assert (model.spec, model.rpms, model.step_deg, model.path) == before


def test_open_says_the_defaults_a_file_lacking_keys_takes(doc, tmp_path, qtbot):
    """A file without "stroke" opened with H = 300 mm without a word: Open now says what was
    taken (core's defaulted_keys), once; a complete file says nothing."""
    model, document = doc
    path = tmp_path / "nostroke.shaper.json"
    path.write_text(json.dumps({"format": "shaper-design", "version": 1, "rpm": [40.0], "step_deg": 1.0,
                                "spec": {"mode": "synthesis", "crank": 100, "time_ratio": 1.5, "variant": "block",
                                         "guide_rule": "chord"}}), encoding="utf-8")
    with qtbot.waitSignal(document.noted, timeout=10_000) as blocker:
        assert document.open_path(str(path))
    assert blocker.args == ["nostroke.shaper.json does not give spec.stroke = 300 mm; these were taken."]
    assert model.design.stroke == pytest.approx(300.0)
    full = tmp_path / "full.shaper.json"
    assert document.save_to(str(full))
    with qtbot.assertNotEmitted(document.noted):
        assert document.open_path(str(full))
