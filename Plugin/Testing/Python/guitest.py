"""Helpers for the scripts that RunParaViewGUI.py runs inside the real ParaView GUI."""

import json
import os
import time

ROOT = os.environ.get("RELIGHT_ROOT", ".")
OUTPUT_DIR = os.environ.get("RELIGHT_OUTPUT_DIR", ".")
NAME = os.environ.get("RELIGHT_TEST_NAME", "gui")


class Result:
    """Collects checks and notes; finish() writes them where the runner looks."""

    def __init__(self):
        self.failures = []
        self.notes = []

    def check(self, condition, message):
        if not condition:
            self.failures.append(message)
        return condition

    def note(self, message):
        self.notes.append(message)

    def finish(self):
        with open(os.path.join(OUTPUT_DIR, NAME + ".json"), "w") as f:
            json.dump({"failures": self.failures, "notes": self.notes}, f, indent=1)


def image_path():
    return os.path.join(OUTPUT_DIR, NAME + ".png")


def data_file(name):
    return os.path.join(ROOT, "Data", name)


def settle(seconds=0.3):
    """Runs the GUI's events for a while: its deferred work (the plugin's display
    defaults, a panel built for a new source, a render after a change) happens."""
    from PyQt5.QtWidgets import QApplication

    app = QApplication.instance()
    end = time.time() + seconds
    while time.time() < end:
        app.processEvents()
        time.sleep(0.01)
