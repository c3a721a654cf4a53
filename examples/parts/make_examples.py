#!/usr/bin/env python3
"""Writes the bundled example parts (part JSON, millimetres).

Run from anywhere: python3 examples/parts/make_examples.py
The JSON files are committed; this script documents how they were made and
re-creates them byte for byte.

  quarter_cylinder.json  rational quadratic quarter cylinder, R 20, length 40
                         (exact circle), convex (normal away from the axis)
  semi_cylinder.json     convex semi-cylinder, R 25.4, length 50.8: the
                         reference geometry of DESIGN.md's furrow figure
  mould.json             bicubic 100 x 80 mm mould-like patch with a dome
                         (convex), a dimple (concave) and saddle rings between
  two_face.json          two bicubic faces meeting along x = 50 with tangent
                         continuity and a curvature jump: a concave valley wall
                         (radius 25 across the edge) on one side, a convex crown
                         (radius 50) on the other
"""
import json
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def rational_arc(radius, a0, a1):
    """Degree-2 rational arc (pieces <= 90 deg): knots, 2-D points, weights."""
    sweep = a1 - a0
    pieces = max(1, math.ceil(abs(sweep) / (math.pi / 2) - 1e-9))
    step = sweep / pieces
    w_mid = math.cos(step / 2)
    knots = [0.0, 0.0, 0.0]
    for k in range(1, pieces):
        knots += [k / pieces, k / pieces]
    knots += [1.0, 1.0, 1.0]
    pts, wts = [], []
    for k in range(pieces):
        t0 = a0 + k * step
        if k == 0:
            pts.append((radius * math.cos(t0), radius * math.sin(t0)))
            wts.append(1.0)
        tm = t0 + step / 2
        pts.append((radius / w_mid * math.cos(tm), radius / w_mid * math.sin(tm)))
        wts.append(w_mid)
        t1 = t0 + step
        pts.append((radius * math.cos(t1), radius * math.sin(t1)))
        wts.append(1.0)
    return knots, pts, wts


def clean(x):
    """Round away float noise such as 1.5543e-15 so the files read well."""
    r = round(x, 12)
    return 0.0 if r == 0 else r


def cylinder_face(name, radius, length, a0, a1):
    """Cylinder about the y axis: u along the arc (x-z plane), v along y.
    With a1 < a0 (arc run clockwise) Su x Sv points away from the axis."""
    knots, pts, wts = rational_arc(radius, a0, a1)
    cps = [[[clean(px), clean(y), clean(pz)] for y in (0.0, length)] for (px, pz) in pts]
    weights = [[w, w] for w in wts]
    return {"name": name, "degree_u": 2, "degree_v": 1, "knots_u": knots,
            "knots_v": [0.0, 0.0, 1.0, 1.0], "control_points": cps, "weights": weights}


def clamped_uniform_knots(count, degree):
    spans = count - degree
    return [0.0] * (degree + 1) + [k / spans for k in range(1, spans)] + [1.0] * (degree + 1)


def greville(knots, degree, count):
    return [sum(knots[i + 1:i + degree + 1]) / degree for i in range(count)]


def mould_height(x, y):
    dome = 9.0 * math.exp(-((x - 30.0) ** 2 / (2 * 13.0 ** 2) + (y - 45.0) ** 2 / (2 * 12.0 ** 2)))
    dimple = 5.0 * math.exp(-((x - 72.0) ** 2 + (y - 30.0) ** 2) / (2 * 5.5 ** 2))
    return 20.0 + 0.04 * x + dome - dimple


def mould_face():
    nu, nv, p = 21, 17, 3
    ku, kv = clamped_uniform_knots(nu, p), clamped_uniform_knots(nv, p)
    gu, gv = greville(ku, p, nu), greville(kv, p, nv)
    # Control points at the Greville abscissae make x(u), y(v) exactly linear.
    cps = [[[clean(100.0 * a), clean(80.0 * b), clean(mould_height(100.0 * a, 80.0 * b))]
            for b in gv] for a in gu]
    return {"name": "mould", "degree_u": p, "degree_v": p, "knots_u": ku, "knots_v": kv,
            "control_points": cps}


def solve(matrix, rhs):
    """Gaussian elimination with partial pivoting (small dense systems)."""
    n = len(matrix)
    a = [row[:] + [r] for row, r in zip(matrix, rhs)]
    for c in range(n):
        p = max(range(c, n), key=lambda r: abs(a[r][c]))
        a[c], a[p] = a[p], a[c]
        for r in range(n):
            if r != c:
                f = a[r][c] / a[c][c]
                a[r] = [x - f * y for x, y in zip(a[r], a[c])]
    return [a[r][n] / a[r][r] for r in range(n)]


def bicubic_bezier_face(name, x0, x1, y0, y1, height):
    """Bicubic Bezier face over [x0,x1] x [y0,y1] reproducing z = height(x, y)
    exactly when height is a polynomial of degree <= 3 in x and in y: the
    ordinates come from interpolating 4 x 4 samples (Bernstein system)."""
    nodes = [0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0]
    bern = [[math.comb(3, k) * t ** k * (1 - t) ** (3 - k) for k in range(4)] for t in nodes]
    samples = [[height(x0 + (x1 - x0) * t, y0 + (y1 - y0) * s) for s in nodes] for t in nodes]
    # Solve along v for every u sample, then along u.
    rows = [solve(bern, samples[i]) for i in range(4)]
    ordinates = [[0.0] * 4 for _ in range(4)]
    for j in range(4):
        col = solve(bern, [rows[i][j] for i in range(4)])
        for i in range(4):
            ordinates[i][j] = col[i]
    cps = [[[clean(x0 + (x1 - x0) * i / 3.0), clean(y0 + (y1 - y0) * j / 3.0), clean(ordinates[i][j])]
            for j in range(4)] for i in range(4)]
    k = [0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0]
    return {"name": name, "degree_u": 3, "degree_v": 3, "knots_u": k, "knots_v": k,
            "control_points": cps}


def two_face_part():
    # Both faces are z = 10 at the common edge x = 50 with zero slope across it
    # (tangent continuous); the curvature jumps from concave to convex there.
    #   valley_wall, x in [0, 50]:   z = 10 + 0.02 (50 - x)^2 (1 + 0.5 ((y - 30)/30)^2)
    #   crown,       x in [50, 100]: z = 10 - 0.01 (x - 50)^2 (1 + 0.5 ((y - 30)/30)^2)
    def bulge(y):
        return 1.0 + 0.5 * ((y - 30.0) / 30.0) ** 2
    return [bicubic_bezier_face("valley_wall", 0.0, 50.0, 0.0, 60.0,
                                lambda x, y: 10.0 + 0.02 * (50.0 - x) ** 2 * bulge(y)),
            bicubic_bezier_face("crown", 50.0, 100.0, 0.0, 60.0,
                                lambda x, y: 10.0 - 0.01 * (x - 50.0) ** 2 * bulge(y))]


def dump(value, indent=0):
    """Same layout as Furrow's own writer: short arrays inline."""
    compact = json.dumps(value, separators=(",", ":"))
    if not isinstance(value, (list, dict)) or not value or (isinstance(value, list) and len(compact) <= 100):
        return compact
    pad = " " * (indent + 2)
    if isinstance(value, dict):
        items = [pad + json.dumps(k) + ": " + dump(v, indent + 2) for k, v in value.items()]
        return "{\n" + ",\n".join(items) + "\n" + " " * indent + "}"
    items = [pad + dump(v, indent + 2) for v in value]
    return "[\n" + ",\n".join(items) + "\n" + " " * indent + "]"


def write(name, faces):
    with open(os.path.join(HERE, name), "w") as f:
        f.write(dump({"units": "mm", "faces": faces}) + "\n")


if __name__ == "__main__":
    write("quarter_cylinder.json", [cylinder_face("quarter_cylinder", 20.0, 40.0, math.pi / 2, 0.0)])
    write("semi_cylinder.json", [cylinder_face("semi_cylinder", 25.4, 50.8, math.pi, 0.0)])
    write("mould.json", [mould_face()])
    write("two_face.json", two_face_part())
