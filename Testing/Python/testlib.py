"""What every Python test here shares: checks that report and collect, and one verdict."""

import sys

failures = []


def check(condition, message):
    """Prints the check's outcome and keeps going, so one run lists every failure;
    returns the condition, for checks that later ones depend on."""
    print(("ok   " if condition else "FAIL ") + message)
    if not condition:
        failures.append(message)
    return bool(condition)


def finish(name):
    """Exits non-zero if any check failed."""
    if failures:
        print(f"{name}: {len(failures)} check(s) failed")
        sys.exit(1)
    print(f"{name}: all checks passed")
