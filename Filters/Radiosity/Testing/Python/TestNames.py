"""One set of names: the plugin's XML and the settings table (docs/settings.md) against the C++
classes (as VTK's Python wraps them). ParaView.TestPluginProxies checks the same table
against the proxies that pvbatch makes from the XML."""

import glob
import os
import xml.etree.ElementTree as ElementTree

import relight
from vtkmodules import vtkCommonCore
from settingstable import setting_rows
from testlib import check, finish

ROOT = os.environ.get("RELIGHT_ROOT", ".")
# The XML as the plugin is built from it: Plugin/ServerManager's files with the tables'
# facts filled in (RadiosityXmlTables), one for each file there.
XML_FILES = sorted(glob.glob(os.path.join(os.environ.get("RELIGHT_PLUGIN_XML") or
                                          os.path.join(ROOT, "build", "Plugin", "ServerManager"), "*.xml")))
TEMPLATES = sorted(glob.glob(os.path.join(ROOT, "Plugin", "ServerManager", "*.xml")))
SETTINGS = os.path.join(ROOT, "docs", "settings.md")


def plugin_xml():
    """The plugin's XML files (one per proxy, Plugin/ServerManager) as one configuration,
    each proxy with the properties of its base (base_proxygroup, base_proxyname) as
    ParaView gives them to it."""
    root = ElementTree.Element("ServerManagerConfiguration")
    for path in XML_FILES:
        root.extend(ElementTree.parse(path).getroot())
    bases = {(group.get("name"), proxy.get("name")): proxy for group in root.iter("ProxyGroup") for proxy in group}
    for proxy in root.iter():
        base = bases.get((proxy.get("base_proxygroup"), proxy.get("base_proxyname")))
        if base is not None:
            proxy.extend(list(base))
    return root


def proxies_with_classes(root):
    """The XML's proxies of the plugin's C++ classes: sources, filters, the writers wrapped by
    ParaView's vtkParallelSerialWriter (its own properties are ParaView's) and their helper."""
    tags = ("SourceProxy", "RadiosityRelightProxy", "WriterProxy", "Proxy")
    return [p for tag in tags for p in root.iter(tag) if (p.get("class") or "").startswith("vtkRadiosity")
            or p.get("class") == "vtkLightTaggedRadiosity"]


def xml_commands():
    """{class: {property: [commands]}} for every property that calls the C++ object."""
    proxies = {}
    root = plugin_xml()
    for proxy in proxies_with_classes(root):
        properties = proxies.setdefault(proxy.get("class"), {})
        for prop in proxy:
            commands = [prop.get(a) for a in ("command", "clean_command") if prop.get(a)]
            if commands:
                properties.setdefault(prop.get("name"), []).extend(commands)
    return proxies


def undocumented():
    """Properties of the XML without help text (the panel's tooltip and the ? button)."""
    missing = []
    root = plugin_xml()
    for proxy in proxies_with_classes(root):
        for prop in proxy:
            text = prop.findtext("Documentation") or ""
            # Ports and groups are not properties; time steps are ParaView's own.
            if prop.tag.endswith("Property") and prop.get("name") != "TimestepValues" and len(text.split()) < 8:
                missing.append(proxy.get("name") + "." + prop.get("name"))
    return missing


# One home per proxy: each file of Plugin/ServerManager is named for the one proxy it holds
# (a public one with the internal proxies it wraps, or one internal proxy), the menu apart.
for path in XML_FILES:
    proxies = {False: [], True: []}  # by internal group or not
    for group in ElementTree.parse(path).getroot().iter("ProxyGroup"):
        proxies[group.get("name").startswith("internal_")] += [p.get("name") for p in group if p.tag.endswith("Proxy")]
    stem = os.path.splitext(os.path.basename(path))[0]
    named = proxies[False] or proxies[True]
    check(not named if stem == "Menu" else len(named) == 1 and named[0].endswith(stem),
          f"{os.path.basename(path)} holds one proxy named for it ({proxies})")
with open(os.path.join(ROOT, "Plugin", "CMakeLists.txt")) as cmake:
    listed = cmake.read()
unlisted = [os.path.basename(p) for p in TEMPLATES if os.path.splitext(os.path.basename(p))[0] not in listed]
check(not unlisted, f"Plugin/CMakeLists.txt builds every file of Plugin/ServerManager (not: {unlisted})")
built = [os.path.basename(p) for p in XML_FILES]
check(built == [os.path.basename(p) for p in TEMPLATES] and all("@" not in open(p).read() for p in XML_FILES),
      f"the plugin is built from every file of Plugin/ServerManager, each fact filled in (built: {built})")
check(not undocumented(), f"every property has help text (missing: {undocumented()})")
commands = xml_commands()
check(sorted(commands) == ["vtkLightTaggedRadiosity", "vtkRadiosityAppendPieces", "vtkRadiosityEXRWriter",
                           "vtkRadiosityGLTFWriter", "vtkRadiosityLightMarker", "vtkRadiosityMesher",
                           "vtkRadiosityRelight", "vtkRadiositySceneReader", "vtkRadiosityWorkPlane"],
      f"the XML makes proxies of {sorted(commands)}")
for cls, properties in commands.items():
    wrapped = getattr(relight, cls)
    missing = [f"{name}: {c}" for name, cs in properties.items() for c in cs if not hasattr(wrapped, c)]
    check(not missing, f"{cls} has every command its XML calls ({len(properties)} properties; missing {missing})")

# ParaView calls an input property's command with the port first where port_index > 0
# (vtkSIProxy::AddInput): a one-argument setter there is never called, silently.
root = plugin_xml()
ported = [(p.get("name"), p.get("command")) for proxy in proxies_with_classes(root) for p in proxy.iter("InputProperty")
          if int(p.get("port_index") or 0) > 0]
check(ported and all(command in ("SetInputConnection", "AddInputConnection") for _, command in ported),
      f"inputs on other ports take the port with the connection: {ported}")

# The panel's ranges are the C++ ones: Get<Name>Min/MaxValue, the clamp vtkSetClampMacro
# makes or the range a filter checks with an error (EXR Size, the marker's Emission). A
# bound the XML gives equals it, and an enumeration spans exactly the clamp.
mismatched = []
for proxy in proxies_with_classes(root):
    wrapped = getattr(relight, proxy.get("class"))()
    for prop in proxy:
        name = (prop.get("command") or "")[3:]
        low, high = (getattr(wrapped, f"Get{name}{end}Value", None) for end in ("Min", "Max"))
        ranges = [d for d in prop if d.tag in ("IntRangeDomain", "DoubleRangeDomain")]
        if not (low and high):
            # A bounded panel over an unbounded setter lets Python set what the GUI cannot.
            mismatched += [f"{name}: XML range, no C++ range" for _ in ranges[:1]]
            continue
        for domain in ranges:
            # A finite clamp the XML leaves out: the panel would offer values C++ changes.
            mismatched += [f"{name}.{bound}: C++ {c():g}, not in the XML" for bound, c in (("min", low), ("max", high))
                           if domain.get(bound) is None and abs(c()) < 2 ** 31 - 1]
        for domain in prop:
            if domain.tag in ("IntRangeDomain", "DoubleRangeDomain"):
                given = [(bound, float(domain.get(bound).split()[0]), clamp())
                         for bound, clamp in (("min", low), ("max", high)) if domain.get(bound) is not None]
                mismatched += [f"{name}.{b}: XML {x:g}, C++ {c:g}" for b, x, c in given if x != c]
            if domain.tag == "EnumerationDomain":
                values = [int(entry.get("value")) for entry in domain.iter("Entry")]
                if (min(values), max(values)) != (low(), high()):
                    mismatched.append(f"{name}: entries {min(values)}..{max(values)}, C++ {low()}..{high()}")
check(not mismatched, f"the XML's ranges are the C++ clamps (differences: {mismatched})")

# Solver methods come from one table in the core (Solve/SolverMethods.cxx): the XML's
# enumeration, the filter's SetSolverMethodTo<Name> shortcuts and the docs name them all.
solver_class = relight.vtkLightTaggedRadiosity
table = {v: solver_class.GetSolverMethodName(v) for v in range(solver_class.GetNumberOfSolverMethods())}
entries = {int(e.get("value")): e.get("text") for p in root.iter("IntVectorProperty") if p.get("name") == "SolverMethod"
           for e in p.iter("Entry")}
check(entries == table, f"the XML's SolverMethod entries {entries} are the core's method table {table}")
shortcuts = [n for n in table.values() if not hasattr(solver_class(), "SetSolverMethodTo" + n)]
check(not shortcuts, f"SetSolverMethodTo<Name> for every method (missing: {shortcuts})")
named = []
for name in table.values():
    solver = solver_class()
    getattr(solver, "SetSolverMethodTo" + name)()
    named.append(solver.GetSolverMethodAsString())
check(named == list(table.values()) and solver_class().GetSolverMethodAsString() == "Auto",
      f"GetSolverMethodAsString names the method set ({named}; Auto by default)")
guide = open(os.path.join(ROOT, "docs", "design.md"), encoding="utf-8").read()
check(all(n in guide for n in table.values()), "docs/design.md names every solver method")

# Scene formats come from one table (IO/Formats/SceneFiles.cxx): the reader hint lists them all.
hints = [f.get("extensions") for f in root.iter("ReaderFactory")]
check(hints == [relight.vtkRadiositySceneReader.GetFileExtensions()],
      f"the XML's reader hint {hints} lists the reader's extensions {relight.vtkRadiositySceneReader.GetFileExtensions()!r}")
# The first row of the format table that lists an extension reads it: one listed in two
# rows would leave a new reader unused, or take its files from the old one, silently.
extensions = relight.vtkRadiositySceneReader.GetFileExtensions().split()
check(len(extensions) == len(set(extensions)),
      f"no extension is in two rows of the format table: {sorted(e for e in set(extensions) if extensions.count(e) > 1)}")

# A light's row has one width: the core's (kSettingRowCells, through vtkRadiosityLights) is the XML's.
widths = {p.get("number_of_elements_per_command") for p in root.iter("StringVectorProperty") if p.get("name") == "LightSettings"}
check(widths == {str(relight.vtkRadiosityLights.GetSettingRowCells())},
      f"LightRig.xml sends LightSettings rows of {widths} strings, the light rig reads "
      f"{relight.vtkRadiosityLights.GetSettingRowCells()}")
lights = relight.vtkRadiosityLights
kinds = {"VTK_STRING": "2", "VTK_DOUBLE": "1", "VTK_INT": "0"}
columns = " ".join(kinds[n] for i in range(lights.GetSettingRowCells()) for n in kinds
                   if lights.GetSettingRowColumnType(i) == getattr(vtkCommonCore, n))
types = {p.get("element_types") for p in root.iter("StringVectorProperty") if p.get("name") == "LightSettings"}
check(types == {columns} and len(columns.split()) == lights.GetSettingRowCells(),
      f"LightRig.xml's LightSettings cells are typed {types}, the light rig's columns {columns!r}")

rows = setting_rows(SETTINGS)
inputs = {"Input", "MovingLights", "DynamicObjects", "Selection", "DummyInput"}
with_settings = {cls for cls, properties in commands.items() if set(properties) - inputs}
check({cls for _, cls, _, _ in rows} == with_settings and len(rows) == len(with_settings),
      f"docs/settings.md has a row for each class whose proxy has settings: rows "
      f"{sorted(cls for _, cls, _, _ in rows)}, XML {sorted(with_settings)}")
for proxy, cls, settings, methods in rows:
    wrapped = getattr(relight, cls)
    settable = {name for name, cs in commands.get(cls, {}).items() if any(c.startswith(("Set", "Add")) for c in cs)}
    settable -= inputs
    check(set(settings) == settable, f"{proxy}: docs/settings.md lists the XML's settings "
                                     f"(only in docs {sorted(set(settings) - settable)}, "
                                     f"only in XML {sorted(settable - set(settings))})")
    plain = [name for name in settings if not hasattr(wrapped, "Set" + name)]
    named = [m for m in methods if not hasattr(wrapped, m)]
    # A setting without Set<Name> must say in its remark which C++ methods it calls.
    check(not named and all(any(m in commands[cls][name] for m in methods) for name in plain),
          f"{proxy}: Set<Name> in C++ for each setting, or the remark's methods ({plain}, missing {named})")
finish("TestNames")
