"""The README's table of setting names (From ParaView), read by TestNames.py (against
the XML and C++) and TestPluginProxies.py (against pvbatch's proxies)."""

import re

ROW = re.compile(r"\| `(\w+)` \(`(vtk\w+)`\) \| (.*) \|$")
REMARK = re.compile(r"\(C\+\+:[^)]*\)")


def setting_rows(readme):
    """(proxy, class, settings, C++ methods named in "(C++: ...)" remarks) per row."""
    rows = []
    for line in open(readme, encoding="utf-8"):
        row = ROW.match(line.strip())
        if row:
            remarks = " ".join(REMARK.findall(row.group(3)))
            settings = re.findall(r"`(\w+)`", REMARK.sub("", row.group(3)))
            rows.append((row.group(1), row.group(2), settings, re.findall(r"`(\w+)`", remarks)))
    return rows
