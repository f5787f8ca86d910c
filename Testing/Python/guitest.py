"""Helpers for the scripts that RunParaViewGUI.py runs inside the real ParaView GUI."""

import json
import os

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
