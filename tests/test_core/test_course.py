"""core.course_design.plan: the course design's list of files, what each needs of the design file,
and every refusal found before anything is written (issue 35, item 6)."""
import itertools
import json
import os

import pytest

from core.course_design.plan import (PARTS, REPORT, CourseError, Part, file_names, missing_parts,
                         plan_course, read_document)
from core.files.io import design_document, masses_to_dict
from core.linkage.spec import Spec

NEEDED = ("rpm", "forces", "cam", "gear")     # the keys besides "spec" some file needs
CAM = {"arm_mm": 150.0, "swing_deg": 15.0, "rise_deg": 60.0, "dwell_deg": 10.0, "return_deg": 60.0,
       "pressure_deg": 40.0, "return_pressure_deg": 70.0}
GEAR = {"z1": 13, "z2": 40, "module_mm": 6.0, "centre_mm": 162.0}


def document(drop=()):
    from core.forces.masses import MassProperties
    doc = design_document(Spec(), [40.0, 60.0], 1.0,
                          {"forces": masses_to_dict(MassProperties(cut_force_N=7000.0)), "cam": CAM,
                           "gear": GEAR})
    return {k: v for k, v in doc.items() if k not in drop}


def write(path, doc) -> str:
    path.write_text(json.dumps(doc), encoding="utf-8")
    return str(path)


def test_the_files_are_numbered_in_order_and_only_sheets_have_a_dxf():
    plain = [name for _, name in file_names(PARTS)]
    assert plain == ["00-report.pdf", "01-motion.pdf", "02-kinetostatic.pdf", "03-cam.pdf", "04-gear.pdf"]
    both = [name for _, name in file_names(PARTS, dxf=True)]
    assert both == ["00-report.pdf", "01-motion.pdf", "01-motion.dxf", "02-kinetostatic.pdf",
                    "02-kinetostatic.dxf", "03-cam.pdf", "03-cam.dxf", "04-gear.pdf", "04-gear.dxf"]
    assert [p.content for p in PARTS] == [REPORT, "motion", "forces", "cam", "gear"]


def test_a_new_sheet_joins_by_one_entry_and_is_refused_without_its_key():
    """A sheet joins by one entry, numbered after the others; a file without its key is
    refused naming it and the sheet."""
    parts = PARTS + (Part("extra", "motion", "the extra sheet", ("extra",)),)
    assert file_names(parts, dxf=True)[-2:] == [(parts[-1], "05-extra.pdf"), (parts[-1], "05-extra.dxf")]
    assert missing_parts({"spec", "rpm", "forces", "cam", "gear"}, parts) == (("extra", ("the extra sheet",)),)


def test_a_file_without_a_gear_pair_is_refused_naming_it(tmp_path):
    """The gear sheet is required like the others (the GUI always holds a pair): a file
    without "gear" is refused naming it and the sheet, before anything is written."""
    doc, keys = read_document(write(tmp_path / "d.json", document(("gear",))))
    with pytest.raises(CourseError) as caught:
        plan_course(doc, keys, "d.json", str(tmp_path / "out"), dxf=True)
    assert str(caught.value) == '--design: d.json has no "gear" (the gear pair): the gear sheet needs it'
    assert caught.value.missing == (("gear", ("the gear sheet",)),)
    assert os.listdir(tmp_path) == ["d.json"]


def test_a_gear_pair_that_cannot_be_made_is_refused_in_one_line_naming_the_centre(tmp_path):
    """Refused as the file is read (core's reader makes the pair, as the GUI's Open does),
    before any sheet is planned: the course command says why in one line and writes nothing."""
    from cli_runner import shaper_in_process
    from core.base.errors import FileFormatError
    doc = document()
    doc["gear"] = dict(GEAR, centre_mm=100.0)          # below (z1 + z2)·m/2 by far: shifts beyond the teeth
    path = write(tmp_path / "d.json", doc)
    with pytest.raises(FileFormatError, match=r"centre = 100: must be > a cos α"):
        read_document(path)
    status, _, err = shaper_in_process("course", "--design", path, "-o", tmp_path / "out")
    assert status == 2 and err.count("\n") == 1 and "--design" in err and "centre = 100" in err, err
    assert os.listdir(tmp_path) == ["d.json"]


@pytest.mark.parametrize("drop", [c for n in range(1, 4) for c in itertools.combinations(NEEDED, n)])
def test_every_missing_key_is_named_with_every_file_that_needs_it(drop, tmp_path):
    doc, keys = read_document(write(tmp_path / "d.json", document(drop)))
    assert set(drop).isdisjoint(keys)
    found = dict(missing_parts(keys))
    assert set(found) == set(drop)
    for key in drop:          # the reference: the parts whose needs name the key
        assert set(found[key]) == {p.title for p in PARTS if key in p.needs}
    with pytest.raises(CourseError) as caught:
        plan_course(doc, keys, "d.json", str(tmp_path / "out"))
    text = str(caught.value)
    assert text.startswith("--design: d.json has no ") and "\n" not in text
    assert all(f'"{key}"' in text for key in drop)
    assert os.listdir(tmp_path) == ["d.json"]


def test_speeds_the_reader_fills_in_are_not_the_files_own(tmp_path):
    """A file without "rpm" opens at 40 and 60 r/min; the course design refuses it rather
    than print speeds nobody chose."""
    doc, keys = read_document(write(tmp_path / "d.json", document(("rpm",))))
    assert doc["rpm"] == [40.0, 60.0] and "rpm" not in keys
    assert "rpm" in dict(missing_parts(keys))


def test_a_cam_that_cannot_be_made_is_refused_naming_the_sheet(tmp_path):
    doc = document()
    doc["cam"] = dict(CAM, roller_mm=500.0)          # far above any roller the profile allows
    read, keys = read_document(write(tmp_path / "d.json", doc))
    with pytest.raises(CourseError, match=r"^--design: d.json: the cam sheet: .*roller"):
        plan_course(read, keys, "d.json", str(tmp_path / "out"))


def test_a_folder_that_cannot_be_written_is_refused_before_anything(tmp_path):
    doc, keys = read_document(write(tmp_path / "d.json", document()))
    (tmp_path / "file").write_text("x")
    (tmp_path / "full").mkdir()
    (tmp_path / "full" / "02-kinetostatic.pdf").mkdir()          # a folder where a file goes
    cases = {str(tmp_path / "file"): "it is not a folder",
             str(tmp_path / "none" / "out"): "there is no folder",
             str(tmp_path / "file" / "out"): "is not a folder",
             str(tmp_path / ("x" * 300)): "too long",
             str(tmp_path / "full"): "02-kinetostatic.pdf: it is a folder"}
    for folder, words in cases.items():
        with pytest.raises(CourseError) as caught:
            plan_course(doc, keys, "d.json", folder)
        assert caught.value.option == "--output" and words in str(caught.value), (folder, caught.value)
    assert sorted(os.listdir(tmp_path)) == ["d.json", "file", "full"]
    assert os.listdir(tmp_path / "full") == ["02-kinetostatic.pdf"]


def test_a_complete_file_plans_every_file_in_the_folder(tmp_path):
    doc, keys = read_document(write(tmp_path / "d.json", document()))
    course = plan_course(doc, keys, "d.json", str(tmp_path / "out"), dxf=True)
    assert [os.path.basename(f.path) for f in course.files] == [n for _, n in file_names(PARTS, True)]
    assert {os.path.dirname(f.path) for f in course.files} == {str(tmp_path / "out")}
    assert course.rpms == (40.0, 60.0) and course.masses.cut_force_N == 7000.0
    assert course.drawn["cam"].inputs.arm_mm == 150.0
    assert course.drawn["gear"].centre_mm == pytest.approx(162.0)
    assert not (tmp_path / "out").exists()          # planning writes nothing
