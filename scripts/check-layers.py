#!/usr/bin/env python3
"""Lint: every source file includes only its own layer and the layers below it
(docs/architecture.md "Module order"), and third-party libraries stay in the
few files that own them. Exits 1 with one line per violation."""
import os, re, sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
# Lowest first. A sub-folder is a layer of its own inside its module.
LAYERS = [
    "base", "geometry", "io/cad", "io/scan", "io", "io/machining", "io/qif", "io/cmm", "render", "partition",
    "machining/cutter", "machining/gouge", "machining/prediction", "machining/toolpath",
    "machining/compensation", "planning", "inspection", "results", "report", "stage", "job", "cli",
]
# Layers that sit side by side: neither may include the other.
MACHINING = {"machining/cutter", "machining/gouge", "machining/prediction", "machining/toolpath",
             "machining/compensation"}
SIBLINGS = [({"partition"}, MACHINING), ({"planning"}, {"inspection"})]
# Third-party headers and the only places allowed to include them.
OWNERS = {
    r"<(Standard|TopoDS|TopExp|TopAbs|BRep|Geom|GeomAbs|GeomAPI|GeomConvert|gp|STEP|IGES|XSControl|Interface|ShapeFix|ShapeAnalysis|ShapeUpgrade|TColgp|TColStd|Precision|BRepAdaptor|BRepTools|BRepBuilderAPI|BRepGProp|GProp|Message|Extrema|Adaptor)[A-Za-z0-9_]*\.hxx>": ("src/io/cad/occt/",),
    r"<nanoflann": ("src/geometry/point_search.",),
    r"<pcl/|<flann/|<vtk": ("src/io/scan/pcl/",),
    r"<ceres/": ("src/inspection/",),
    r"<png\.h>|<opencv2/imgcodecs": ("src/render/png.",),
    r"<pugixml": ("src/io/qif/",),
    r"<sqlite3\.h>": ("src/results/sqlite_",),
    r"<libpq-fe\.h>|<pqxx/": ("src/results/postgres_",),
}

def layer_of(rel):  # rel: path below src/
    parts = rel.split("/")
    best = None
    for layer in LAYERS:
        lp = layer.split("/")
        if parts[:len(lp)] == lp and (best is None or len(lp) > len(best.split("/"))):
            best = layer
    return best

def rank(layer):
    return LAYERS.index(layer)

def main():
    bad = []
    src = os.path.join(ROOT, "src")
    for dirpath, _, files in os.walk(src):
        for fn in sorted(files):
            if not fn.endswith((".hpp", ".cpp")):
                continue
            path = os.path.join(dirpath, fn)
            rel = os.path.relpath(path, src).replace(os.sep, "/")
            mine = layer_of(rel)
            text = open(path, encoding="utf-8").read()
            for no, line in enumerate(text.splitlines(), 1):
                m = re.match(r'\s*#include\s+"([^"]+)"', line)
                if m:
                    target = layer_of(m.group(1))
                    if target is None:
                        continue
                    side = any((mine in a and target in b) or (mine in b and target in a)
                               for a, b in SIBLINGS)
                    if rank(target) > rank(mine) or side:
                        bad.append(f"src/{rel}:{no}: layer '{mine}' includes '{m.group(1)}' from layer '{target}'")
                for pattern, owners in OWNERS.items():
                    if re.search(r'#include\s+' + pattern, line) and not any(
                            ("src/" + rel).startswith(o) for o in owners):
                        bad.append(f"src/{rel}:{no}: {line.strip()} is allowed only in {', '.join(owners)}")
    for b in bad:
        print(b)
    if bad:
        sys.exit(1)
    print("check-layers: every include looks down, third-party headers stay with their owners")

main()
