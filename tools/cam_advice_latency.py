"""Edit to the advice on screen: the Cam tab at 1000 × 650, core's caches emptied before each edit."""
import statistics, time
from PySide6.QtWidgets import QApplication
app = QApplication([])
from core.cam import extremes, synthesis
from shaperapp.cam.model import DEFAULTS
from shaperapp.design.model import DesignModel
from shaperapp.cam.tab import CamTab
t = CamTab(DesignModel()); t.resize(1000, 650); t.show(); app.processEvents()
for name, before, edit in (("boss-500", {}, {"boss": 500.0}), ("boss-90-roller-5", {"roller": 5.0}, {"boss": 90.0}),
                           ("both-allowances", {"swing": 30.0, "rise": 40.0, "return": 40.0, "pressure": 10.0}, {"return_pressure": 5.0})):
    walls = []
    for _ in range(5):
        t.cam_model.set_fields(**DEFAULTS); t.cam_model.set_fields(**before)
        while t.cam_model.searching(): app.processEvents()
        for c in (synthesis.synthesize, extremes.pressure_peaks, extremes.min_convex_radius): c.cache_clear()
        start = time.perf_counter()
        t.cam_model.set_fields(**edit); app.processEvents()
        while "looking for" in t.cam_model.error.allowed: app.processEvents(); time.sleep(0.001)
        walls.append(time.perf_counter() - start)
    print(f"{name}: edit to advice on screen, median {statistics.median(walls)*1000:.0f} ms (min {min(walls)*1000:.0f}, max {max(walls)*1000:.0f})")
t.cam_model.shutdown()
