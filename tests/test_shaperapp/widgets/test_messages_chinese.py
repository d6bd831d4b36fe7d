"""Every message of widgets/messages.py reaches a Chinese user in Chinese (issue 32, item 5):
the templates for core's DesignError texts, the names of the fields, and the reasons a
design file is refused (core.base.errors.FILE_REASONS), each scanned for English words."""
import re
from dataclasses import fields

import pytest

from core.base.errors import FILE_REASONS, DesignError, FileFormatError
from core.linkage.spec import Spec
from language_checks import english_words, words_of
from shaperapp.widgets import file_messages, i18n, messages


@pytest.fixture
def chinese(qapp):
    assert i18n.set_language("zh_CN")
    yield
    i18n.set_language("en")


def test_every_template_is_chinese(chinese):
    templates = {**messages._translated_templates(), **file_messages._file_templates()}
    untranslated = {source: text for source, text in templates.items()
                    if english_words(text) or text == source}
    assert untranslated == {}


def test_every_reason_a_file_is_refused_has_a_template():
    assert set(file_messages._file_templates()) == set(FILE_REASONS)


def test_every_field_a_file_can_name_is_named_in_chinese(chinese):
    from core.cam.file import cam_to_dict
    from core.cam import CamInputs, Program
    from core.forces.masses import MassProperties
    names = [f.name for f in fields(Spec)] + [f.name for f in fields(MassProperties)] + ["rpm", "step", "forces", "cam"]
    names += list(cam_to_dict(CamInputs(arm_mm=120.0, program=Program(15.0, 60.0, 10.0, 60.0)), None))
    shown = {name: messages.field_name(name) for name in names}
    assert {n: s for n, s in shown.items() if s == n or english_words(s)} == {}


@pytest.mark.parametrize("reason", sorted(FILE_REASONS))
def test_a_refused_file_is_described_in_chinese(chinese, reason):
    values = {"too_large": [1], "version": ["2", 1], "no_version": [1], "unreadable": ["No such file"],
              "too_deep": [16], "constant": ["NaN"], "long_integer": [400], "huge_number": ["1e400"],
              "rpm_value": ['"40"'], "duplicate_key": ['"z1"'], "invalid": ["crank = 0: must be > 0 and ≤ 10000 mm"]}.get(reason, [])
    error = FileFormatError(reason, "/tmp/设计.json", *values, errno=2,
                            cause=DesignError("crank", 0.0, "must be > 0 and ≤ 10000 mm"))
    text = file_messages.describe_file_error(error)
    assert "/tmp/设计.json" in text
    assert english_words(text, words_of("/tmp/设计.json")) == [], text
    assert str(error) == FILE_REASONS[reason].format(*[str(v) for v in values], name="/tmp/设计.json")


def test_a_library_entry_is_named_as_one(chinese):
    error = FileFormatError("not_json", "library entry 'gear'", entry="gear")
    assert file_messages.describe_file_error(error).startswith("设计库条目“gear”")
    assert english_words(file_messages.describe_file_error(error), {"gear"}) == []


def test_english_keeps_cores_sentence():
    error = FileFormatError("not_json", "/tmp/a.json")
    assert file_messages.describe_file_error(error) == str(error) == "/tmp/a.json is not a design file (not valid JSON)"


@pytest.mark.parametrize("spec, said", [
    # L2 + L1 = 400 mm; the least stroke 2·(L1 + L2)·sin(θ/2) = 2·L1·(1 + sin 15°) = 251.764 mm at K = 1.4
    (Spec(mode="dimensions", crank=100.0, frame=300.0, lever=350.0, guide_rule="height", guide_height=350.0),
     "须大于 L2 + L1 = 400 mm，以使曲柄销始终在导杆上，并在 L2 + L1 与导杆端部之间留出滑枕导路的高度"),
    (Spec(mode="dimensions", crank=100.0, frame=300.0, lever=500.0, guide_rule="height", guide_height=600.0),
     "须高于 L2 + L1 = 400 mm 且不高于导杆长度 500 mm"),
    (Spec(crank=100.0, time_ratio=1.4, stroke=100.0, guide_rule="height", guide_height=300.0),
     "对此曲柄和 K 须大于 251.764 mm，以使曲柄销始终在导杆上"),
    (Spec(variant="rod", rod_input="length", rod_length=20.0, guide_rule="height", guide_height=579.5),
     "请将连杆加长到不小于 %1 mm，或移动导路线"),
    (Spec(variant="rod", rod_input="ratio", rod_ratio=0.034, guide_rule="height", guide_height=579.5),
     "请将 L4/L3 增大到不小于 %1，或移动导路线"),
    (Spec(mode="dimensions", crank=34000.0, frame=40000.0, lever=76000.0, variant="rod", guide_rule="height",
          guide_height=95000.0, rod_input="length", rod_length=80000.0),
     "连杆长度在 100000 mm 以内时，连杆与导杆总会经过死点位置；请移动导路线"),
])
def test_the_block_and_dead_centre_refusals_are_chinese_with_their_numbers(chinese, spec, said):
    """The refusals that name the block's lever or guide range, and the dead centre's least
    rod (in mm, or as L4/L3 for a rod given so, or none up to 100 000 mm), as the form shows
    them: in Chinese, every number of core's sentence kept (%1: the least rod, core's)."""
    with pytest.raises(DesignError) as refused:
        spec.design()
    error = refused.value
    text = messages.describe(error)
    assert english_words(text) == [], text
    numbers = re.compile(r"\d+\.\d+|\d{3,}")          # the lengths and ratios, not L2, L1, L4/L3
    assert set(numbers.findall(error.allowed)) <= set(numbers.findall(text)), text
    least = re.search(r"at least (\S+?) ", error.allowed)
    assert said.replace("%1", least.group(1) if least else "%1") in text, text


def test_a_class_rows_value_from_the_base_is_said_in_chinese(chinese):
    """The Class dialog's Chinese line for a value a row left to its design file: the table's
    refusal names the column and "(got 300 from --base)"; the dialog gives both in Chinese
    (the value kept, its source said), as it gives the row's own values."""
    from shaperapp.course.class_messages import table_message
    text = table_message("tasks.csv line 28, column stroke: must be > 300.007 mm for this crank and K, so that "
                         "the ram guide its rule places clears the crank (got 300 from --base)")
    assert text.startswith("tasks.csv 第 28 行，stroke 列：") and text.endswith("（输入的是 300，取自 --base 文件）")
    assert "from" not in text and "got" not in text
    mine = table_message("tasks.csv line 3, column K: must be > 1 and ≤ 5 (got 0.9)")
    assert mine.endswith("（输入的是 0.9）")
    theirs = table_message("tasks.csv line 3, column K: must be > 1 and ≤ 5 (got 0.9 from the design file)")
    assert theirs.endswith("（输入的是 0.9，取自设计文件）")


def test_a_class_rows_shortened_number_is_said_in_chinese(chinese):
    """The refusal of a student number a spreadsheet wrote short reaches the Chinese Class
    dialog in Chinese, the number kept as it was read."""
    from shaperapp.course.class_messages import table_message
    text = table_message("tasks.csv line 2, column student-number: 2.02301E+11 is a number a spreadsheet wrote "
                         "short, its digits lost; format the column as text and save the table again")
    assert text == ("tasks.csv 第 2 行，student-number 列：2.02301E+11 是电子表格缩写了的数字，已丢失数位；"
                    "请把该列设为文本格式后重新保存表格")


def test_a_class_rows_gear_refusal_is_said_in_chinese(chinese, tmp_path):
    """A row whose gear pair core refuses (teeth that never touch, a pointed tip) reached the
    Chinese Class dialog in English (hunt, 1 December): the table's real refusal, read as
    `shaper class` reads it, now in the Gear tab's words."""
    from core.cli.tasks import read_tasks
    from shaperapp.course.class_messages import table_message
    table = tmp_path / "tasks.csv"
    table.write_text("student,student-number,crank,K,stroke,z1,z2,module,x1,x2\n"
                     "A,1,100,1.4,300,13,40,6,5,5\nB,2,100,1.4,300,13,40,6,5,-1\n",
                     encoding="utf-8")
    errors = [s.error for s in read_tasks(str(table), None)[0]]
    assert "teeth never touch" in errors[0] and "pointed" in errors[1], errors
    for error in errors:
        text = table_message(error)
        assert text.startswith("tasks.csv 第 ") and "请取 x1 ≤ " in text and text.endswith("（输入的是 5）"), text
        assert not re.search(r"[a-z]{4,}", text.replace("tasks.csv", "")), text


def test_a_class_output_it_cannot_write_is_said_in_chinese(chinese):
    """The run's refusals of --output and a student's failed write reached the Chinese Class
    dialog in English, reason and all (`--output：cannot write into 机械2101: permission
    denied`; hunt, 1 December): each now in Chinese, its path kept."""
    from shaperapp.course.class_messages import table_message
    said = {
        "--output: cannot write into 机械2101: permission denied": "--output：无法写入文件夹 机械2101：没有权限",
        "--output: cannot write 机械2101/tasks.pdf: it is a folder": "--output：无法写入 机械2101/tasks.pdf：它是文件夹",
        "--output: cannot write into a.txt: it is not a folder": "--output：无法写入文件夹 a.txt：它不是文件夹",
        "--output: cannot make 机械2101: permission denied": "--output：无法创建 机械2101：没有权限",
        "1-a: cannot write k/1-a/00-report.pdf: the disk is full (no space left on the device)":
            "1-a：无法写入 k/1-a/00-report.pdf：磁盘已满（设备上没有剩余空间）",
        "1-a: cannot make the folder k/1-a: a file of that name is in the way; move it, then run the class again":
            "1-a：无法创建文件夹 k/1-a：已有同名文件挡住；请将其移走后重新运行本班",
    }
    for english, chinese_text in said.items():
        assert table_message(english) == chinese_text


def test_a_class_tables_unclosed_quote_is_said_in_chinese(chinese):
    from shaperapp.course.class_messages import table_message
    assert table_message("t.csv line 3: a quote opens a cell that no quote closes before the table ends; close it, "
                         "or write a quote that belongs to the text twice") == (
        "t.csv 第 3 行：有一个引号开始的单元格直到表格结束都没有闭合；请补上闭合的引号，或把属于文字本身的引号写成两个")
