"""The design library in core: round trips, figures, queries, edits."""
import json
import math
import random

import pytest

from core.forces.masses import MassProperties

from core.base.errors import FileFormatError
from core.forces.flywheel import summarize
from core.files.io import load_design, masses_to_dict, save_design
from core.library import Library
from core.library.files import export_entries, import_entries, read_design_files
from core.library.names import check_tags, file_stem, safe_file_name, unique_name
from core.library.query import QueryError, parse_filter
from core.library.store import ENV_VAR, LibraryError, resolve_path
from core.linkage.metrics import analyze
from core.linkage.spec import Spec

LOADS = MassProperties(lever_mass_kg=20.0, lever_inertia_kg_m2=1.1, ram_mass_kg=70.0,
                       cut_force_N=7000.0, cut_height_mm=80.0)
SPECS = {
    "base": Spec(),
    "rod16": Spec(time_ratio=1.6, variant="rod", rod_ratio=0.35),
    "leading": Spec(time_ratio=1.5, stroke=320.0, variant="rod", rod_input="length",
                    rod_length=180.0, rod_side="leading", guide_rule="sagitta"),
    "dims": Spec(mode="dimensions", crank=110.0, frame=380.0, lever=600.0, guide_rule="height",
                 guide_height=585.0),
}


def loaded(spec, rpm=(40.0, 60.0), masses=LOADS, step=1.0):
    return {"spec": spec, "rpm": list(rpm), "step_deg": step, "masses": masses}


@pytest.fixture
def lib(tmp_path):
    with Library(tmp_path / "lib.sqlite") as library:
        yield library


def test_file_library_file_round_trip_keeps_the_meaning(tmp_path, lib):
    for name, spec in SPECS.items():
        source = tmp_path / f"{name}.shaper.json"
        save_design(source, spec, [33.0, 47.5, 60.0], 0.5,
                    extra={"forces": masses_to_dict(LOADS), "comment": {"by": "test", "n": [1, 2]}})
        before = load_design(source)
        lib.add(name, before)
        out = tmp_path / f"{name}.out.json"
        lib.export(name, out)
        after = load_design(out)
        for key in ("spec", "rpm", "step_deg", "masses", "comment", "format", "version"):
            assert after[key] == before[key], key
        # what the GUI saves for the same design is the same text
        assert out.read_text(encoding="utf-8") == source.read_text(encoding="utf-8")


def test_document_without_loads_stays_without_loads(tmp_path, lib):
    lib.add("plain", loaded(Spec(), masses=None))
    lib.export("plain", tmp_path / "p.json")
    assert "forces" not in json.loads((tmp_path / "p.json").read_text())
    entry = lib.get("plain")
    assert all(s.mean_torque_N_m is None and s.flywheel_inertia_kg_m2 is None for s in entry.figures.speeds)


def test_stored_figures_are_analyze_and_summarize(lib):
    for name, spec in SPECS.items():
        lib.add(name, loaded(spec))
        design = spec.design()
        metrics = analyze(design, [40.0, 60.0])
        dyn = summarize(design, [40.0, 60.0], LOADS)
        f = lib.get(name).figures
        assert f.K == metrics.time_ratio and f.stroke_mm == metrics.stroke_mm
        assert f.variant == design.variant and f.rod_mm == design.rod
        assert f.pressure_angle_max_deg == metrics.pressure_angle_max_deg
        for got, m, d in zip(f.speeds, metrics.speeds, dyn.speeds):
            assert (got.rpm, got.v_work_max_m_s, got.v_return_max_m_s, got.a_max_m_s2) == \
                (m.rpm, m.v_work_max_m_s, m.v_return_max_m_s, m.a_max_m_s2)
            assert (got.mean_torque_N_m, got.max_torque_N_m, got.flywheel_inertia_kg_m2) == \
                (d.mean_torque_N_m, d.max_torque_N_m, d.flywheel_inertia_kg_m2)


def test_seed003_figures_by_hand(lib):
    """Block variant at 40 r/min: v_max = ω·L3·L1/(L2 ± L1) (the hand check in docs/cli.md)."""
    lib.add("seed", loaded(Spec(), rpm=[40.0]))
    row = lib.query()[0]
    w = 40 * 2 * math.pi / 60
    l1, l3 = 100.0, 300.0 / (2 * math.sin(math.radians(15)))
    l2 = l1 / math.sin(math.radians(15))
    assert row["v_work_max_m_s"] == pytest.approx(w * l3 * l1 / (l2 + l1) / 1000, rel=1e-6)
    assert row["v_return_max_m_s"] == pytest.approx(w * l3 * l1 / (l2 - l1) / 1000, rel=1e-6)
    assert row["theta_deg"] == pytest.approx(30.0)
    assert row["K"] == pytest.approx(1.4, abs=1e-9)


def test_duplicate_names_are_refused_and_replace_keeps_created(lib):
    lib.add("a", loaded(Spec()))
    with pytest.raises(LibraryError) as err:
        lib.add("a", loaded(Spec(time_ratio=1.5)))
    assert err.value.kind == "exists"
    created = lib.get("a").created
    lib.add("a", loaded(Spec(time_ratio=1.5)), replace=True)
    entry = lib.get("a")
    assert entry.created == created and entry.modified >= created
    assert entry.figures.K == pytest.approx(1.5)
    assert lib.count() == 1


@pytest.mark.parametrize("name", ["", "   ", "a\nb", "x" * 201, 5])
def test_bad_names_are_refused(lib, name):
    with pytest.raises(LibraryError) as err:
        lib.add(name, loaded(Spec()))
    assert err.value.kind == "name"
    assert lib.count() == 0


def test_tags_are_cleaned_and_bad_ones_refused():
    assert check_tags([" b", "a", "b", ""]) == ("a", "b")
    with pytest.raises(LibraryError):
        check_tags(["a,b"])


def test_edit_operations(lib):
    lib.add("a", loaded(Spec()), notes="first", tags=["x"])
    lib.add("b", loaded(Spec(time_ratio=1.6)))
    with pytest.raises(LibraryError):
        lib.rename("a", "b")
    lib.rename("a", "c")
    assert lib.names() == ["b", "c"]
    assert lib.duplicate("c") == "c (2)"
    assert lib.get("c (2)").text == lib.get("c").text
    removed = lib.remove("c")
    assert "c" not in lib
    lib.restore(removed)
    assert lib.get("c") == removed                     # times, notes, tags, figures: all back
    lib.update("b", notes="changed", tags=["y", "z"])
    assert (lib.get("b").notes, lib.get("b").tags) == ("changed", ("y", "z"))
    with pytest.raises(LibraryError) as err:
        lib.remove("nope")
    assert err.value.kind == "missing"


def test_a_damaged_document_is_refused_like_a_file(lib):
    lib.add("a", loaded(Spec()))
    lib._conn.execute("UPDATE documents SET text = ?", ('{"format": "shaper-design", "version": 1, '
                                                        '"spec": {"crank": -1}}',))
    with pytest.raises(FileFormatError, match="library entry 'a'"):
        lib.load("a")


# ---- queries -------------------------------------------------------------------------
def _family(lib):
    rng = random.Random(7)
    for i in range(30):
        spec = Spec(time_ratio=round(rng.uniform(1.2, 1.7), 3), stroke=rng.choice([350.0, 400.0, 450.0]),
                    variant=rng.choice(["block", "rod"]), rod_ratio=0.35)
        lib.add(f"d{i:02d} {spec.variant}", loaded(spec, rpm=rng.choice([[40.0], [60.0, 40.0]]),
                                                   masses=rng.choice([LOADS, None])),
                tags=rng.sample(["final", "draft", "seed"], 1), notes=rng.choice(["", "cut test"]))


OPS = {"=": lambda a, b: a == b, "!=": lambda a, b: a != b, "<": lambda a, b: a < b,
       "<=": lambda a, b: a <= b, ">": lambda a, b: a > b, ">=": lambda a, b: a >= b}


@pytest.mark.parametrize("rpm", [None, 40.0, 60.0])
def test_filters_match_a_plain_python_filter(lib, rpm):
    _family(lib)
    everything = lib.query(rpm=rpm)
    assert len(everything) == 30
    rng = random.Random(1)
    for _ in range(60):
        field = rng.choice(["K", "stroke_mm", "a_max_m_s2", "flywheel_inertia_kg_m2", "rod_mm"])
        op = rng.choice(list(OPS))
        values = [r[field] for r in everything if r[field] is not None]
        value = rng.choice(values) if values else 1.0
        expected = {r["name"] for r in everything if r[field] is not None and OPS[op](r[field], value)}
        got = {r["name"] for r in lib.query(f"{field}{op}{value!r}", rpm=rpm)}
        assert got == expected, (field, op, value)
    rows = lib.query("variant=rod, name~D0, tag=final", rpm=rpm)
    assert {r["name"] for r in rows} == {r["name"] for r in everything if r["variant"] == "rod"
                                         and "d0" in r["name"].lower() and "final" in r["tags"]}
    assert {r["name"] for r in lib.query(search="CUT")} == {r["name"] for r in everything
                                                            if "cut" in r["notes"]}


def test_sorting_puts_empty_values_last(lib):
    _family(lib)
    rows = lib.query(sort="J_F", descending=True, rpm=60.0)
    values = [r["flywheel_inertia_kg_m2"] for r in rows]
    present = [v for v in values if v is not None]
    assert present == sorted(present, reverse=True)
    assert values[len(present):] == [None] * (len(values) - len(present))
    assert [r["name"] for r in lib.query(sort="name")] == sorted(r["name"] for r in rows)
    low = lib.query(sort="a_max", limit=1)[0]
    assert low["a_max_m_s2"] == min(r["a_max_m_s2"] for r in lib.query())


def test_speed_figures_follow_the_chosen_speed(lib):
    lib.add("two", loaded(Spec(), rpm=[60.0, 40.0]))
    lib.add("one", loaded(Spec(), rpm=[40.0]))
    by_first = {r["name"]: r["rpm"] for r in lib.query()}
    assert by_first == {"two": 60.0, "one": 40.0}
    at60 = {r["name"]: r["a_max_m_s2"] for r in lib.query(rpm=60.0)}
    assert at60["one"] is None and at60["two"] == pytest.approx(7.9267, abs=1e-4)
    assert [r["name"] for r in lib.query("rpm=40", rpm=40.0, sort="name")] == ["one", "two"]


@pytest.mark.parametrize("text", ["K>", "K>>1", "nosuch=1", "K~1", "K=abc", "K=nan", "tag<3",
                                  'name="open', 'name="a" b', "=3"])
def test_bad_filters_are_refused(text):
    with pytest.raises(QueryError):
        parse_filter(text)


def test_filter_values_are_parameters_not_sql(lib):
    lib.add("x'); DROP TABLE entries; --", loaded(Spec()))
    lib.add('quote " and, comma', loaded(Spec()))
    assert [r["name"] for r in lib.query("name=x'); DROP TABLE entries; --")] == ["x'); DROP TABLE entries; --"]
    assert [r["name"] for r in lib.query(r'name="quote \" and, comma"')] == ['quote " and, comma']
    assert [r["name"] for r in lib.query("name~50%")] == []         # % is a literal
    assert lib.count() == 2


def test_parse_filter_aliases_and_quotes():
    conditions = parse_filter(' k >= 1.4 , Variant=rod,name~"a,b" ,L3<600, j_f<=2e3')
    assert [(c.field, c.op, c.value) for c in conditions] == [
        ("K", ">=", 1.4), ("variant", "=", "rod"), ("name", "~", "a,b"), ("lever_mm", "<", 600.0),
        ("flywheel_inertia_kg_m2", "<=", 2000.0)]


# ---- files, names, location -------------------------------------------------------------
def test_import_and_export_folders(tmp_path, lib):
    src = tmp_path / "in"
    src.mkdir()
    for name, spec in SPECS.items():
        save_design(src / f"{name}.shaper.json", spec, [40.0], 1.0)
    (src / "junk.json").write_text("{not json")
    good, bad = read_design_files([src])
    assert sorted(p.name for p, _ in good) == sorted(f"{n}.shaper.json" for n in SPECS)
    assert [p.name for p, _ in bad] == ["junk.json"]
    import_entries(lib, good, rename_duplicates=False)
    assert lib.names() == sorted(SPECS)
    with pytest.raises(LibraryError):
        import_entries(lib, good[:1], rename_duplicates=False)
    assert lib.count() == len(SPECS)                      # all or nothing
    import_entries(lib, good[:1], rename_duplicates=True)
    assert lib.count() == len(SPECS) + 1
    out = tmp_path / "out"
    out.mkdir()
    paths = export_entries(lib, out).paths
    assert len(paths) == lib.count()
    for path in paths:
        assert load_design(path)["spec"] in SPECS.values()


def test_name_helpers():
    assert file_stem("/a/b/K 1.4.shaper.json") == "K 1.4"
    assert file_stem("x.JSON") == "x"
    assert unique_name("a", ["a", "a (2)"]) == "a (3)"
    assert safe_file_name('a/b:c*?"<>|') == "a_b_c______"
    assert safe_file_name("...") == "design"


def test_location_rules(tmp_path, monkeypatch):
    monkeypatch.setenv(ENV_VAR, str(tmp_path / "env.sqlite"))
    assert resolve_path(None) == tmp_path / "env.sqlite"
    assert resolve_path(tmp_path / "x.sqlite") == tmp_path / "x.sqlite"
    monkeypatch.setenv(ENV_VAR, "")
    default = resolve_path(None)
    assert default.name == "library.sqlite" and "shaper-designer" in str(default)


def test_missing_folder_is_not_created_for_an_explicit_path(tmp_path):
    with pytest.raises(LibraryError) as err:
        Library(tmp_path / "no" / "such" / "lib.sqlite")
    assert err.value.kind == "location" and not (tmp_path / "no").exists()


@pytest.mark.parametrize("existing", [True, False], ids=["into a folder", "a new folder"])
def test_export_all_is_all_or_nothing(lib, tmp_path, monkeypatch, existing):
    """A failure part way (the third file cannot be moved in / written) leaves no exported
    file, no temporary folder and, for a new folder, no folder."""
    import os as os_module
    import core.library.files as files
    for name, spec in SPECS.items():
        lib.add(name, loaded(spec))
    out = tmp_path / "out"
    if existing:
        out.mkdir()
        (out / "mine.txt").write_text("kept")
    calls = []
    real_rename, real_open = os_module.rename, open

    def failing_rename(src, dst):
        calls.append(dst)
        if existing and len(calls) == 3:
            raise OSError(28, "No space left on device")
        return real_rename(src, dst)

    def failing_open(path, *args, **kwargs):
        if not existing and str(path).endswith("2.tmp"):
            raise OSError(28, "No space left on device")
        return real_open(path, *args, **kwargs)
    monkeypatch.setattr(files.os, "rename", failing_rename)
    monkeypatch.setattr(files, "open", failing_open, raising=False)
    with pytest.raises(OSError):
        export_entries(lib, out)
    monkeypatch.undo()
    left = sorted(p.name for p in tmp_path.iterdir() if p.name.startswith((".shaper-export", "out")))
    assert left == (["out"] if existing else [])
    if existing:
        assert sorted(p.name for p in out.iterdir()) == ["mine.txt"]
    assert len(export_entries(lib, out).paths) == len(SPECS)      # and it works once the disk does


def test_exported_file_names_differ_in_more_than_letter_case(tmp_path, lib):
    """Entries 'K1.4' and 'k1.4' were exported as K1.4.shaper.json and k1.4.shaper.json:
    one file on Windows and macOS, whose file systems do not tell letter case apart, the
    second replacing the first or failing the export (hunt, 1 December). An existing
    'BASE.SHAPER.JSON' in the folder is taken too."""
    for name in ("K1.4", "k1.4", "K1.4 (2)", "base"):
        lib.add(name, loaded(Spec()))
    out = tmp_path / "out"
    out.mkdir()
    (out / "BASE.SHAPER.JSON").write_text("the teacher's")
    files = [p.name for p in export_entries(lib, out).paths]
    assert len({f.casefold() for f in files} | {"base.shaper.json"}) == len(files) + 1, files
    assert (out / "BASE.SHAPER.JSON").read_text() == "the teacher's"
    assert unique_name("a", ["A"], fold_case=True) == "a (2)" and unique_name("a", ["A"]) == "a"
