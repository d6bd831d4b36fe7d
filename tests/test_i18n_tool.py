"""tools/i18n.py release: a new .qm replaces the old file, never rewrites it in place."""
import importlib.util
import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def test_release_leaves_a_running_apps_catalogue_whole(tmp_path, monkeypatch):
    """An app maps its .qm into memory (QTranslator.load); release rewrote the file in place,
    so an app started from the checkout showed English in the Chinese window and then died
    of SIGBUS (seen while the catalogue was being edited). A reader of the old file now
    keeps reading it whole while release writes the new one."""
    spec = importlib.util.spec_from_file_location("i18n_tool", ROOT / "tools" / "i18n.py")
    tool = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(tool)
    ts, qm = tmp_path / "c.ts", tmp_path / "c.qm"
    shutil.copy(tool.TS, ts)
    shutil.copy(tool.QM, qm)
    monkeypatch.setattr(tool, "TS", ts)
    monkeypatch.setattr(tool, "QM", qm)
    script = ("import sys\nfrom PySide6.QtCore import QCoreApplication, QTranslator\n"
              "app = QCoreApplication([])\nt = QTranslator()\nassert t.load(sys.argv[1])\n"
              "app.installTranslator(t)\nprint('loaded', flush=True)\nsys.stdin.readline()\n"
              "print(QCoreApplication.translate('MainWindow', 'Go to crank angle'), flush=True)\n")
    reader = subprocess.Popen([sys.executable, "-c", script, str(qm)], stdin=subprocess.PIPE,
                              stdout=subprocess.PIPE, text=True, encoding="utf-8")
    try:
        assert reader.stdout.readline().strip() == "loaded"
        ts.write_text(ts.read_text(encoding="utf-8").replace(
            "<translation>转到曲柄转角</translation>", "<translation>转到曲柄角</translation>"), encoding="utf-8")
        tool.release()
        out, _ = reader.communicate("\n", timeout=60)
    finally:
        reader.kill()
    assert reader.returncode == 0 and out.strip() == "转到曲柄转角"       # the old catalogue, whole
    assert sorted(p.name for p in tmp_path.iterdir()) == ["c.qm", "c.ts"]
