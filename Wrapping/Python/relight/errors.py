"""Errors in the user's words: VTK's messages caught from a filter, and checked numbers."""

import math
import re

from vtkmodules.vtkCommonCore import vtkCommand


class ErrorCatcher:
    """Collects a VTK object's error and warning messages instead of printing them.

    >>> catcher = ErrorCatcher(some_filter)
    >>> some_filter.Update()
    >>> catcher.errors  # list of message strings

    For a filter, the executive's own report that it failed ("returned failure for
    request", which follows the filter's message) is kept apart, in `reports`.
    """

    def __init__(self, vtk_object):
        self.errors = []
        self.warnings = []
        self.reports = []
        vtk_object.AddObserver(vtkCommand.ErrorEvent, self._error)
        vtk_object.AddObserver(vtkCommand.WarningEvent, self._warning)
        executive = vtk_object.GetExecutive() if hasattr(vtk_object, "GetExecutive") else None
        if executive is not None:
            executive.AddObserver(vtkCommand.ErrorEvent, self._report)

    def _error(self, _obj, _event, message=None):
        self.errors.append(str(message))

    def _warning(self, _obj, _event, message=None):
        self.warnings.append(str(message))

    def _report(self, _obj, _event, message=None):
        self.reports.append(str(message))

    # VTK passes the message as call data only to callbacks that ask for a string.
    _error.CallDataType = "string0"
    _warning.CallDataType = "string0"
    _report.CallDataType = "string0"

    def failed(self):
        """Whether the object failed: its own error, or (a filter given the failed output of
        another as its input) only the executive's report that it returned failure."""
        return bool(self.errors or self.reports)

    def first_error(self):
        """The first error's own words, without VTK's file, line and object prefix."""
        if self.errors:
            return own_words(self.errors[0])
        said = [r for r in self.reports if "returned failure for request" not in r]
        if said:  # the executive's own reason (an input port left unconnected)
            return own_words(said[0])
        return "the input is the output of a filter that failed (see that filter's error)" if self.reports \
            else "unknown error"


def own_words(message):
    """A VTK message without its file, line and object prefix."""
    line = message.strip().split("\n")[-1] if message.strip() else message  # not splitlines: a name may hold U+2028
    return re.sub(r"^\w+ \(0x[0-9a-fA-F]+\): ", "", line)


def _numbers(value, count, what, low=-math.inf):
    """`value` as `count` finite floats of at least `low`; ValueError naming `what` if not."""
    try:
        values = tuple(value)  # a tuple, list or numpy array
    except TypeError:
        values = (value,) if count == 1 else None
    try:
        floats = tuple(float(v) for v in values) if values is not None and len(values) == count else None
    except (TypeError, ValueError):
        floats = None
    if floats is None or not all(math.isfinite(v) and v >= low for v in floats):
        numbers = "a finite number" if count == 1 else f"{count} finite numbers"
        bound = "" if low == -math.inf else f" of at least {low:g}" if count == 1 else f", each at least {low:g}"
        raise ValueError(f"{what} needs {numbers}{bound}, not {value!r}")
    return floats
