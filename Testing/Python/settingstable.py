"""The table of setting names in docs/settings.md, read by TestNames.py (against
the XML and C++) and TestPluginProxies.py (against pvbatch's proxies)."""

import re

ROW = re.compile(r"\| `(\w+)` \(`(vtk\w+)`\) \| (.*) \|$")
REMARK = re.compile(r"\(C\+\+:[^)]*\)")


def setting_rows(path):
    """(proxy, class, settings, C++ methods named in "(C++: ...)" remarks) per row."""
    rows = []
    for line in open(path, encoding="utf-8"):
        row = ROW.match(line.strip())
        if row:
            remarks = " ".join(REMARK.findall(row.group(3)))
            settings = re.findall(r"`(\w+)`", REMARK.sub("", row.group(3)))
            rows.append((row.group(1), row.group(2), settings, re.findall(r"`(\w+)`", remarks)))
    return rows
