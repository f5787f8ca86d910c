"""What every Python test here shares: checks that report and collect, and one verdict."""

import sys

failures = []


def check(condition, message):
    """Prints the check's outcome and keeps going, so one run lists every failure."""
    print(("ok   " if condition else "FAIL ") + message)
    if not condition:
        failures.append(message)


def finish(name):
    """Exits non-zero if any check failed."""
    if failures:
        print(f"{name}: {len(failures)} check(s) failed")
        sys.exit(1)
    print(f"{name}: all checks passed")
