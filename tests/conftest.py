"""Every test runs headless: Qt draws offscreen, so no screen is needed."""
import os

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
