#!/usr/bin/env python3
"""Writes the bad-input corpus of tests/bad_inputs/<reader>/ (docs/formats.md
"Limits"): small malformed files for every reader, each refused with exit
status 2 by tests/cli/test_cli_bad_input.cpp. Hostile numbers, truncation,
wrong types, byte-order marks, CRLF, empty and binary files.

The regions, prediction, comparison and plan cases are mutations of files
furrow writes itself: pass a folder holding regions.json, prediction.json,
comparison.json and plan.json (tests/bad_inputs/make_bases.sh makes them).
Re-running writes the same bytes. The bases come from furrow itself:

  furrow partition examples/parts/quarter_cylinder.json --grid 20 --out B/regions.json
  furrow toolpath examples/parts/quarter_cylinder.json --tool examples/tools/ball_d6.json \
      --scallop 0.05 --out B/path.nc
  furrow predict examples/parts/quarter_cylinder.json --tool examples/tools/ball_d6.json \
      --toolpath B/path.nc --out B/prediction.json
  furrow plan examples/parts/quarter_cylinder.json --regions B/regions.json --points 12 --out B/plan
  cp B/plan/plan.json B/plan.json
  furrow simulate-measurement examples/parts/quarter_cylinder.json --plan B/plan.json --out B/m.csv
  furrow compare examples/parts/quarter_cylinder.json --measurements B/m.csv --plan B/plan.json \
      --out B/comparison.json
"""
import json
import os
import sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "bad_inputs")
BOM = b"\xef\xbb\xbf"
GARBAGE = bytes((i * 37 + 11) % 256 for i in range(512))
HUGE_NUMBER = "9" * 20000  # a 20 kB numeric field: the message must quote at most 80 characters


def put(reader, name, data):
    folder = os.path.join(ROOT, reader)
    os.makedirs(folder, exist_ok=True)
    if isinstance(data, str):
        data = data.encode("utf-8")
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data)


def dumps(doc):
    return json.dumps(doc, indent=1, allow_nan=True)


# ------------------------------------------------------------------ part JSON
def patch(points=None, weights=None, **extra):
    face = {
        "name": "patch", "degree_u": 1, "degree_v": 1,
        "knots_u": [0, 0, 1, 1], "knots_v": [0, 0, 1, 1],
        "control_points": points or [[[0, 0, 0], [0, 10, 0]], [[10, 0, 0], [10, 10, 1]]],
    }
    if weights is not None:
        face["weights"] = weights
    face.update(extra)
    return face


def part(*faces, units="mm"):
    return {"units": units, "faces": list(faces)}


def part_cases():
    good = dumps(part(patch()))
    cases = {
        "empty.json": "",
        "blank.json": "  \r\n\t\n",
        "bom_only.json": BOM,
        "bom_truncated.json": BOM + good[: len(good) // 2].encode(),
        "truncated.json": good[: len(good) // 2],
        "garbage.json": GARBAGE,
        "nul_bytes.json": b"\x00" * 64,
        "root_array.json": "[]",
        "root_number.json": "1e308",
        "no_units.json": dumps({"faces": [patch()]}),
        "units_number.json": dumps(part(patch(), units=25.4)),
        "units_furlong.json": dumps(part(patch(), units="furlong")),
        "units_huge_string.json": dumps(part(patch(), units="x" * 20000)),
        "no_faces.json": dumps({"units": "mm"}),
        "faces_empty.json": dumps(part()),
        "faces_object.json": dumps({"units": "mm", "faces": {"a": 1}}),
        "point_1e308_times_weight.json": dumps(part(patch(
            points=[[[0, 0, 0], [0, 1000, 0]], [[1000, 0, 0], [1000, 1000, 1000]]],
            weights=[[1e308, 1e308], [1e308, 1e308]]))),
        "coordinate_1e308.json": dumps(part(patch(
            points=[[[0, 0, 0], [0, 1e308, 0]], [[1e308, 0, 0], [1e308, 1e308, 1e308]]]))),
        "coordinate_2e6.json": dumps(part(patch(points=[[[0, 0, 0], [0, 10, 0]], [[2e6, 0, 0], [10, 10, 1]]]))),
        "inch_overflow.json": dumps(part(patch(points=[[[0, 0, 0], [0, 10, 0]], [[1e307, 0, 0], [10, 10, 1]]]), units="inch")),
        "inch_beyond_range.json": dumps(part(patch(points=[[[0, 0, 0], [0, 10, 0]], [[50000, 0, 0], [10, 10, 1]]]), units="inch")),
        "coordinate_nan.json": dumps(part(patch(points=[[[0, 0, 0], [0, 10, 0]], [[10, 0, 0], [10, float("nan"), 1]]]))),
        "coordinate_1e999.json": dumps(part(patch())).replace("10,", "1e999,", 1),
        "coordinate_huge_digits.json": dumps(part(patch())).replace("10,", HUGE_NUMBER + ",", 1),
        "coordinate_string.json": dumps(part(patch(points=[[[0, 0, 0], [0, 10, 0]], [[10, 0, 0], [10, "ten", 1]]]))),
        "coordinate_two_values.json": dumps(part(patch(points=[[[0, 0, 0], [0, 10]], [[10, 0, 0], [10, 10, 1]]]))),
        "net_ragged.json": dumps(part(patch(points=[[[0, 0, 0], [0, 10, 0]], [[10, 0, 0]]]))),
        "net_empty.json": dumps(part(patch(points=[[]]))),
        "weight_zero.json": dumps(part(patch(weights=[[1, 1], [1, 0]]))),
        "weight_negative.json": dumps(part(patch(weights=[[1, 1], [1, -2]]))),
        "weight_1e308.json": dumps(part(patch(weights=[[1, 1], [1, 1e308]]))),
        "weight_1e-300.json": dumps(part(patch(weights=[[1, 1], [1, 1e-300]]))),
        "weight_ratio.json": dumps(part(patch(weights=[[1e-5, 1], [1, 1e5]]))),
        "weight_shape.json": dumps(part(patch(weights=[[1, 1]]))),
        "weight_string.json": dumps(part(patch(weights=[[1, 1], [1, "1"]]))),
        "knots_short.json": dumps(part(patch(knots_u=[0, 0, 1]))),
        "knots_decreasing.json": dumps(part(patch(knots_u=[0, 1, 0, 1]))),
        "knots_1e308.json": dumps(part(patch(knots_u=[-1e308, -1e308, 1e308, 1e308]))),
        "knots_tiny_domain.json": dumps(part(patch(knots_u=[0, 0, 1e-300, 1e-300]))),
        "knots_zero_domain.json": dumps(part(patch(knots_u=[0, 0, 0, 0]))),
        "degree_zero.json": dumps(part(patch(degree_u=0))),
        "degree_huge.json": dumps(part(patch(degree_u=2000000000))),
        "degree_fraction.json": dumps(part(patch(degree_u=1.5))),
        "degree_1e308.json": dumps(part(patch(degree_v=1e308))),
        "trim_two_vertices.json": dumps(part(patch(trim=[[[0.1, 0.1], [0.9, 0.1]]]))),
        "trim_nan.json": dumps(part(patch(trim=[[[0.1, 0.1], [float("nan"), 0.1], [0.5, 0.9]]]))),
        "name_missing.json": dumps(part({k: v for k, v in patch().items() if k != "name"})),
        "name_duplicate.json": dumps(part(patch(), patch())),
        "reversed_string.json": dumps(part(patch(reversed="yes"))),
        "crlf_truncated.json": good.replace("\n", "\r\n")[: len(good) - 7],
        "trailing_garbage.json": good + "\n}{",
        "comment.json": "// a part\n" + good,
        "utf16.json": good.encode("utf-16"),
    }
    for name, data in cases.items():
        put("part", name, data)


# ------------------------------------------------------------------ tools
def tool_cases():
    ball = {"name": "B", "type": "ball", "diameter": 6}
    cases = {
        "empty.json": "",
        "bom_only.json": BOM,
        "garbage.json": GARBAGE,
        "truncated.json": '{"name": "B", "type": "ball", "diam',
        "library_not_tool.json": dumps([ball]),
        "diameter_1e-300.json": dumps(dict(ball, diameter=1e-300)),
        "diameter_1e300.json": dumps(dict(ball, diameter=1e300)),
        "diameter_1e-4.json": dumps(dict(ball, diameter=1e-4)),
        "diameter_2e4.json": dumps(dict(ball, diameter=2e4)),
        "diameter_zero.json": dumps(dict(ball, diameter=0)),
        "diameter_negative.json": dumps(dict(ball, diameter=-6)),
        "diameter_nan.json": dumps(dict(ball, diameter=float("nan"))),
        "diameter_inf.json": dumps(dict(ball, diameter=float("-inf"))),
        "diameter_string.json": dumps(dict(ball, diameter="6")),
        "diameter_huge_digits.json": dumps(ball).replace("6", HUGE_NUMBER),
        "inch_overflow.json": dumps(dict(ball, diameter=1e307, units="inch")),
        "bull_corner_1e-300.json": dumps({"name": "R", "type": "bull", "diameter": 10, "corner_radius": 1e-300}),
        "bull_corner_too_big.json": dumps({"name": "R", "type": "bull", "diameter": 10, "corner_radius": 6}),
        "bull_no_corner.json": dumps({"name": "R", "type": "bull", "diameter": 10}),
        "ball_wrong_corner.json": dumps(dict(ball, corner_radius=1)),
        "flat_with_corner.json": dumps({"name": "F", "type": "flat", "diameter": 8, "corner_radius": 1}),
        "unknown_type.json": dumps(dict(ball, type="drill")),
        "misspelt_member.json": dumps(dict(ball, corner_raduis=3)),
        "name_empty.json": dumps(dict(ball, name="")),
        "no_name.json": dumps({"type": "ball", "diameter": 6}),
        "units_bad.json": dumps(dict(ball, units="cubits")),
    }
    for name, data in cases.items():
        put("tool", name, data)
    lib = {
        "empty_array.json": "[]",
        "one_object.json": dumps(ball),
        "duplicate_names.json": dumps([ball, ball]),
        "member_1e300.json": dumps([ball, {"name": "BIG", "type": "ball", "diameter": 1e300}]),
        "member_nan.json": dumps([ball, {"name": "N", "type": "ball", "diameter": float("nan")}]),
        "bom_truncated.json": BOM + b'[{"name": "B", "type": "ball", ',
        "garbage.json": GARBAGE[::-1],
        "nested_array.json": dumps([[ball]]),
    }
    for name, data in lib.items():
        put("tool_library", name, data)


# ------------------------------------------------------------------ G-code
def gcode_cases():
    head = "%\nO1000 (CAM OUTPUT)\nN10 G21 G90 G17\nN20 G0 X0 Y0 Z30\n"
    cut = "N30 G1 X10 Y10 Z20 F800\nN40 G1 X20 Y10 Z20\n"
    tail = "N50 G0 Z30\nN60 M30\n%\n"
    cases = {
        "empty.nc": "",
        "bom_only.nc": BOM,
        "blank_crlf.nc": "\r\n\r\n",
        "garbage.nc": GARBAGE,
        "nul.nc": b"G1 X1\x00 Y2\n",
        "no_cut.nc": head + tail,
        "only_comments.nc": "(nothing)\n; nothing\n%\n",
        # The end is 11.2 mm from the centre, the start 5 mm: not one circle.
        "arc_g2.nc": head + "N30 G2 X10 Y10 I5 J0 F800\n" + tail,
        "arc_r_full_circle.nc": head + "N30 G2 X0 Y0 R5 F800\n" + tail,
        "arc_absolute_centres.nc": head + "N25 G90.1\nN30 G2 X10 Y0 I5 J0 F800\n" + tail,
        "arc_wrong_plane.nc": head + "N30 G2 X10 Y0 I5 K0 F800\n" + tail,
        "canned_cycle_g81.nc": head + "N25 G81 X5 Y5 Z-2 R1 F100\n" + cut + tail,
        "work_offset_switch.nc": head + "N25 G54\n" + cut + "N45 G55\n" + cut + tail,
        "arc_bom_crlf.nc": BOM + (head + "N30 G03 X10 Y10 R5 F800\n" + tail).replace("\n", "\r\n").encode(),
        "cutter_comp.nc": head + "N25 G41 D1\n" + cut + tail,
        # After G28 the position is machine home: Z is unknown at the cut.
        "home_g28.nc": head + "N25 G28\nN30 G1 X10 Y10 F800\n" + tail,
        "rotary_a.nc": head + "N30 G1 X10 Y10 Z20 A45 F800\n" + tail,
        "x_1e308.nc": head + "N30 G1 X1e308 Y10 Z20 F800\n" + tail,
        "x_2e6.nc": head + "N30 G1 X2000000 Y10 Z20 F800\n" + tail,
        "inch_overflow.nc": "G20 G90\nG0 X0 Y0 Z1\nG1 X1e307 Y0 Z1 F10\nG1 X2 Y0 Z1\n",
        "relative_overflow.nc": "G21 G90\nG0 X0 Y0 Z1\nG91\n" + "G1 X900000 F100\n" * 3,
        "x_nan.nc": head + "N30 G1 Xnan Y10 Z20 F800\n" + tail,
        "x_huge_digits.nc": head + "N30 G1 X" + HUGE_NUMBER + " Y10 Z20 F800\n" + tail,
        "word_no_number.nc": head + "N30 G1 X Y10 Z20 F800\n" + tail,
        "word_twice.nc": head + "N30 G1 X10 X11 Y10 Z20 F800\n" + tail,
        "feed_zero.nc": head + "N30 G1 X10 Y10 Z20 F0\n" + tail,
        "feed_negative.nc": head + "N30 G1 X10 Y10 Z20 F-5\n" + tail,
        "unclosed_comment.nc": head + "N30 G1 X10 (unclosed Y10 Z20 F800\n" + tail,
        "stray_paren.nc": head + "N30 G1 X10 Y10) Z20 F800\n" + tail,
        "cut_before_known.nc": "G21 G90\nG1 X1 Y1 F100\nG1 X2 Y2\n",
        "relative_first.nc": "G21 G91\nG0 X1 Y1 Z1\nG1 X1 F100\n",
        "coordinates_before_mode.nc": "G21 G90\nX1 Y1 Z1\n",
        "unknown_g.nc": head + "N25 G65 P9000\n" + cut + tail,
        "lowercase_arc.nc": head.lower() + "n30 g2 x10 y10 i5 j0 f800\n" + tail,
        "binary_tail.nc": (head + cut).encode() + GARBAGE[:40],
        "utf16.nc": (head + cut + tail).encode("utf-16"),
    }
    for name, data in cases.items():
        put("gcode", name, data)


# ------------------------------------------------------------------ APT CL data
def apt_cases():
    head = "PARTNO BAD\nUNITS/MM\nCUTTER/6,3\nRAPID\nGOTO/60,28,40\n"
    cut = "GOTO/60,28,21.9\nGOTO/64,28,21.2\n"
    cases = {
        "empty.cl": "",
        "bom_only.cl": BOM,
        "garbage.cl": GARBAGE,
        "nul.cl": b"GOTO/1\x00,2,3\n",
        "no_cut.cl": head + "FINI\n",
        "x_1e308.cl": head + "GOTO/1e308,28,20\n",
        "x_2e6.cl": head + "GOTO/2000000,28,20\n",
        "x_nan.cl": head + "GOTO/nan,28,20\n",
        "x_huge_digits.cl": head + "GOTO/" + HUGE_NUMBER + ",28,20\n",
        "inch_overflow.cl": "UNITS/INCHES\nCUTTER/0.25\nRAPID\nGOTO/0,0,1\nGOTO/1e307,0,1\n",
        "missing_value.cl": head + "GOTO/60,,20\n",
        "trailing_comma.cl": head + "GOTO/60,28,\n",
        "two_values.cl": head + "GOTO/60,28\n",
        "tilted_axis.cl": head + "GOTO/60,28,20,0,0.5,0.866\n",
        "tilted_tlaxis.cl": head + "TLAXIS/0,1,1\n" + cut,
        "tapered_cutter.cl": "CUTTER/10,1,4,1,10,0,50\nRAPID\nGOTO/60,28,40\n" + cut,
        "two_cutters.cl": head + cut + "CUTTER/10\n" + cut,
        "cutter_1e308.cl": "CUTTER/1e308\nRAPID\nGOTO/60,28,40\n" + cut,
        "unknown_major.cl": head + "RETRCT\n" + cut,
        "insert.cl": head + "INSERT G41 D1\n" + cut,
        "cutcom.cl": head + "CUTCOM/LEFT\n" + cut,
        "circle_alone.cl": head + cut + "CIRCLE/64,30,21.2,0,0,1,2\nFINI\n",
        "circle_radius.cl": head + cut + "CIRCLE/64,30,21.2,0,0,1,3\nGOTO/64,32,21.2\n",
        "after_fini.cl": head + cut + "FINI\nGOTO/1,1,1\n",
        "continued_at_end.cl": head + cut + "GOTO/1,2,$\n",
        "unknown_position.cl": "CUTTER/6,3\n" + cut,
        "feed_zero.cl": head + "FEDRAT/0\n" + cut,
        "units_feet.cl": "UNITS/FEET\n" + head + cut,
        "crlf_bom_tilted.cl": BOM + (head + "GOTO/60,28,20,0.1,0,1\n").replace("\n", "\r\n").encode(),
        "utf16.cl": (head + cut).encode("utf-16"),
    }
    for name, data in cases.items():
        put("apt", name, data)


# ------------------------------------------------------------------ tool-path CSV
def toolpath_csv_cases():
    cases = {
        "empty.csv": "",
        "bom_only.csv": BOM,
        "header_only.csv": "x,y,z\n",
        "bom_header_only_crlf.csv": BOM + b"x,y,z\r\n",
        "garbage.csv": GARBAGE,
        "unknown_column.csv": "x,y,z,w\n0,0,1,0\n1,0,1,0\n",
        "missing_z.csv": "x,y\n0,0\n1,0\n",
        "duplicate_column.csv": "x,y,z,x\n0,0,1,0\n1,0,1,0\n",
        "one_point_pass.csv": "0,0,1\n\n1,0,1\n2,0,1\n",
        "two_columns.csv": "0,0\n1,0\n",
        "ragged.csv": "0,0,1\n1,0\n",
        "nan.csv": "0,0,1\nnan,0,1\n",
        "inf.csv": "0,0,1\n-inf,0,1\n",
        "x_1e308.csv": "0,0,1\n1e308,0,1\n",
        "x_2e6.csv": "0,0,1\n2e6,0,1\n",
        "huge_digits.csv": "0,0,1\n" + HUGE_NUMBER + ",0,1\n",
        "decimal_comma.csv": "x;y;z\n0,5;0;1\n1,5;0;1\n",
        "zero_normal.csv": "x,y,z,nx,ny,nz\n0,0,1,0,0,0\n1,0,1,0,0,1\n",
        "some_normals.csv": "x,y,z,nx\n0,0,1,0\n1,0,1,0\n",
        "pass_fraction.csv": "pass,x,y,z\n0.5,0,0,1\n0.5,1,0,1\n",
        "pass_decreasing.csv": "pass,x,y,z\n1,0,0,1\n1,1,0,1\n0,2,0,1\n0,3,0,1\n",
        "pass_1e300.csv": "pass,x,y,z\n1e300,0,0,1\n1e300,1,0,1\n",
        "u_without_v.csv": "x,y,z,u\n0,0,1,0\n1,0,1,0\n",
        "face_without_uv.csv": "x,y,z,face\n0,0,1,a\n1,0,1,a\n",
        "empty_face.csv": "x,y,z,u,v,face\n0,0,1,0,0,\n1,0,1,1,0,\n",
        "bom_unknown_column_crlf.csv": BOM + b"x,y,z,speed\r\n0,0,1,5\r\n1,0,1,5\r\n",
        "utf16.csv": "x,y,z\n0,0,1\n1,0,1\n".encode("utf-16"),
    }
    for name, data in cases.items():
        put("toolpath_csv", name, data)


# ------------------------------------------------------------------ contact points
def contact_cases():
    cases = {
        "empty.csv": "",
        "bom_only.csv": BOM,
        "comments_only.csv": "# nothing\n# here\n",
        "garbage.csv": GARBAGE,
        "two_values.csv": "1,2\n",
        "four_values.csv": "1,2,3,4\n",
        "nan.csv": "50,40,nan\n",
        "inf.csv": "50,inf,20\n",
        "x_1e308.csv": "1e308,40,20\n",
        "x_2e6.csv": "2e6,40,20\n",
        "huge_digits.csv": HUGE_NUMBER + ",40,20\n",
        "unknown_column_bom_crlf.csv": BOM + b"id;x;y;z;w\r\nP1;50;40;20;1\r\n",
        "duplicate_column.csv": "x,y,z,z\n1,2,3,4\n",
        "some_normals.csv": "x,y,z,nx,ny\n1,2,3,0,0\n",
        "zero_normal.csv": "x,y,z,nx,ny,nz\n50,40,20,0,0,0\n",
        "header_no_z.csv": "x,y,id\n1,2,P\n",
        "decimal_comma.csv": "x;y;z\n50,5;40;20\n",
        "off_part.csv": "0,0,500\n",
        "utf16.csv": "x,y,z\n1,2,3\n".encode("utf-16"),
        "nul.csv": b"1,2,\x003\n",
    }
    for name, data in cases.items():
        put("contact_csv", name, data)


# ------------------------------------------------------------------ measurements
def measurement_cases():
    csv = {
        "empty.csv": "",
        "bom_only.csv": BOM,
        "no_header.csv": "1,2,3\n",
        "unknown_column_bom.csv": BOM + b"\xef\xbb\xbfid,x,y,z\nP1,1,2,3\n",
        "missing_z.csv": "id,x,y\nP1,1,2\n",
        "duplicate_column.csv": "id,x,y,z,x\nP1,1,2,3,4\n",
        "ragged.csv": "id,x,y,z\nP1,1,2\n",
        "nan.csv": "id,x,y,z\nP1,1,nan,3\n",
        "inf.csv": "id,x,y,z\nP1,1,2,-inf\n",
        "x_1e308.csv": "id,x,y,z\nP1,1e308,2,3\n",
        "x_2e6.csv": "id,x,y,z\nP1,2e6,2,3\n",
        "inch_overflow.csv": "id,x,y,z\nP1,1e307,2,3\n",
        "huge_digits.csv": "id,x,y,z\nP1," + HUGE_NUMBER + ",2,3\n",
        "duplicate_id.csv": "id,x,y,z\nP1,1,2,3\nP1,1,2,3\n",
        "empty_id.csv": "id,x,y,z\n,1,2,3\n",
        "zero_direction.csv": "id,x,y,z,i,j,k\nP1,1,2,3,0,0,0\n",
        "some_directions.csv": "id,x,y,z,i\nP1,1,2,3,0\n",
        "decimal_comma_twice.csv": BOM + b"id;x;y;z\r\nP1;1,5,2;2;3\r\n",
        "table_without_actual_z.csv": "Name;Nominal X;Nominal Y;Nominal Z;Actual X;Actual Y\nP1;1;2;3;1,1;2,1\n",
        "unclosed_quote.csv": 'id,x,y,z\n"P1,1,2,3\n',
        "text_after_quote.csv": 'id;x;y;z\n"P1"x;1;2;3\n',
        "header_only_crlf.csv": "id,x,y,z\r\n",
        "garbage.csv": GARBAGE,
        "utf16.csv": "id,x,y,z\nP1,1,2,3\n".encode("utf-16"),
    }
    for name, data in csv.items():
        put("measurements_csv", name, data)
    xyz = {
        "empty.xyz": "",
        "bom_only.xyz": BOM,
        "two_fields.xyz": "1 2\n",
        "five_fields.xyz": "1 2 3 4 5\n",
        "ragged.xyz": "1 2 3\n1 2 3 0 0 1\n",
        "nan.xyz": "1 nan 3\n",
        "x_1e308.xyz": "1e308 2 3\n",
        "huge_digits.xyz": HUGE_NUMBER + " 2 3\n",
        "zero_direction.xyz": "1 2 3 0 0 0\n",
        "comma_separated.xyz": "1,2,3\n",
        "garbage.txt": GARBAGE,
    }
    for name, data in xyz.items():
        put("measurements_xyz", name, data)
    dmis = {
        "empty.dmi": "",
        "bom_only.dmi": BOM,
        "no_points.dmi": "DMISMN/'x',05.0\nUNITS/MM,ANGDEG\nENDFIL\n",
        "units_furlong.dmi": "UNITS/FURLONG,ANGDEG\nFA(P1)=FEAT/POINT,CART,1,2,3,0,0,1\n",
        "polar.dmi": "FA(P1)=FEAT/POINT,POL,1,2,3,0,0,1\n",
        "too_few.dmi": "FA(P1)=FEAT/POINT,CART,1,2,3,0,0\n",
        "nan.dmi": "FA(P1)=FEAT/POINT,CART,1,nan,3,0,0,1\n",
        "x_1e308.dmi": "FA(P1)=FEAT/POINT,CART,1e308,2,3,0,0,1\n",
        "inch_overflow.dmi": "UNITS/INCH,ANGDEG\nFA(P1)=FEAT/POINT,CART,1e307,2,3,0,0,1\n",
        "inch_beyond_range.dmi": "UNITS/INCH,ANGDEG\nFA(P1)=FEAT/POINT,CART,50000,2,3,0,0,1\n",
        "huge_digits.dmi": "FA(P1)=FEAT/POINT,CART," + HUGE_NUMBER + ",2,3,0,0,1\n",
        "zero_direction.dmi": "FA(P1)=FEAT/POINT,CART,1,2,3,0,0,0\n",
        "duplicate_label.dmi": "FA(P1)=FEAT/POINT,CART,1,2,3,0,0,1\nFA(P1)=FEAT/POINT,CART,1,2,3,0,0,1\n",
        "empty_label_crlf.dmi": BOM + b"FA()=FEAT/POINT,CART,1,2,3,0,0,1\r\n",
        "duplicate_nominal.dmi": "F(P1)=FEAT/POINT,CART,1,2,3,0,0,1\nF(P1)=FEAT/POINT,CART,1,2,3,0,0,1\nFA(P1)=FEAT/POINT,CART,1,2,3,0,0,1\n",
        "garbage.dmi": GARBAGE,
        "circle_without_inner.dmo": "FA(C1)=FEAT/CIRCLE,CART,0,0,0,0,0,1,10\nFA(P1)=FEAT/POINT,CART,1,2,3,0,0,1\n",
        "cylinder_too_few.out": "FA(C1)=FEAT/CYLNDR,INNER,CART,0,0,0,0,0,1\nFA(P1)=FEAT/POINT,CART,1,2,3,0,0,1\n",
        "plane_zero_normal.dms": "FA(S1)=FEAT/PLANE,CART,0,0,0,0,0,0\nFA(P1)=FEAT/POINT,CART,1,2,3,0,0,1\n",
    }
    for name, data in dmis.items():
        put("measurements_dmis", name, data)
    ippdme = {
        "empty.log": "",
        "error_no_point.res": '00010 &\r\n00010 ! Error(2, 0500, "PtMeas", "Probe hit not detected")\r\n00010 %\r\n',
        "reused_tag.log": "00010 &\n00010 &\n",
        "missing_z.log": "00010 # X(1), Y(2)\n",
        "nan.log": "00010 # X(1), Y(nan), Z(3)\n",
        "not_a_response.ipp": "hello\n",
        "huge.log": "00010 # X(1e400), Y(2), Z(3)\n",
        "zero_direction.log": "00010 # X(1), Y(2), Z(3), IJK(0, 0, 0)\n",
        "garbage.log": GARBAGE,
    }
    for name, data in ippdme.items():
        put("measurements_ippdme", name, data)


# ------------------------------------------------------------------ job
def job_cases():
    good = {"part": "../../../examples/parts/quarter_cylinder.json", "tool": "../../../examples/tools/ball_d6.json",
            "toolpath": {"generate": {}}, "tolerance": 0.05, "output": "out"}
    cases = {
        "empty.json": "",
        "bom_only.json": BOM,
        "garbage.json": GARBAGE,
        "truncated.json": dumps(good)[:40],
        "root_array.json": "[1, 2]",
        "misspelt_member.json": dumps(dict(good, plan={"densty": 1})),
        "unknown_top_member.json": dumps(dict(good, colour="red")),
        "no_part.json": dumps({k: v for k, v in good.items() if k != "part"}),
        "no_output.json": dumps({k: v for k, v in good.items() if k != "output"}),
        "tolerance_nan.json": dumps(dict(good, tolerance=float("nan"))),
        "tolerance_negative.json": dumps(dict(good, tolerance=-1)),
        "tolerance_string.json": dumps(dict(good, tolerance="0.05")),
        "grid_huge.json": dumps(dict(good, partition={"grid": [2000000000, 2000000000]})),
        "density_1e300.json": dumps(dict(good, plan={"density": 1e300})),
        "points_huge.json": dumps(dict(good, plan={"points": 1e15})),
        "version_2.json": dumps(dict(good, version=2)),
        "scallop_1e-300.json": dumps(dict(good, toolpath={"generate": {"scallop": 1e-300}})),
    }
    for name, data in cases.items():
        put("job", name, data)


# ------------------------------------------------------------------ STEP / IGES
STEP_HEAD = ("ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION((''),'2;1');\n"
             "FILE_NAME('x','2024-01-01T00:00:00',(''),(''),'','','');\n"
             "FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));\nENDSEC;\n")


def cad_cases():
    cases = {
        "empty.step": "",
        "bom_only.stp": BOM,
        "not_step.step": "solid cube\n  facet normal 0 0 1\nendsolid\n",
        "garbage.step": GARBAGE,
        "header_only.step": STEP_HEAD,
        "no_data.step": STEP_HEAD + "DATA;\nENDSEC;\nEND-ISO-10303-21;\n",
        "points_only.step": STEP_HEAD + "DATA;\n#1=CARTESIAN_POINT('',(0.,0.,0.));\nENDSEC;\nEND-ISO-10303-21;\n",
        "truncated_data.step": STEP_HEAD + "DATA;\n#1=CARTESIAN_POINT('',(0.,0.,",
        "empty.igs": "",
        "not_iges.igs": "hello\n",
        "garbage.iges": GARBAGE,
    }
    for name, data in cases.items():
        put("cad", name, data)


# ------------------------------------------------------------------ mutations of furrow's own files
def mutate(reader, base_path, changes, ext=".json"):
    with open(base_path, "rb") as f:
        raw = f.read()
    doc = json.loads(raw)
    put(reader, "empty" + ext, "")
    put(reader, "bom_only" + ext, BOM)
    put(reader, "garbage" + ext, GARBAGE)
    put(reader, "truncated" + ext, raw[: len(raw) // 2])
    put(reader, "bom_crlf_truncated" + ext, BOM + raw.replace(b"\n", b"\r\n")[: len(raw) // 3])
    put(reader, "root_array" + ext, "[]")
    for name, change in changes.items():
        d = json.loads(raw)
        change(d)
        put(reader, name + ext, dumps(d))


def set_path(path, value):
    def change(d):
        node = d
        for key in path[:-1]:
            node = node[key]
        node[path[-1]] = value
    return change


def drop(path):
    def change(d):
        node = d
        for key in path[:-1]:
            node = node[key]
        del node[path[-1]]
    return change


def mutation_cases(bases):
    plan = json.load(open(os.path.join(bases, "plan.json")))
    mutate("plan", os.path.join(bases, "plan.json"), {
        "no_points": drop(["points"]),
        "points_empty": set_path(["points"], []),
        "probe_diameter_1e300": set_path(["probe", "diameter"], 1e300),
        "probe_diameter_nan": set_path(["probe", "diameter"], float("nan")),
        "xyz_1e308": set_path(["points", 0, "xyz"], [1e308, 0, 0]),
        "approach_2e6": set_path(["points", 0, "approach"], [2e6, 0, 0]),
        "units_inch_overflow": lambda d: (d.__setitem__("units", "inch"), d["points"][0].__setitem__("xyz", [1e307, 0, 0])),
        "ijk_zero": set_path(["points", 0, "ijk"], [0, 0, 0]),
        "duplicate_id": set_path(["points", 1, "id"], plan["points"][0]["id"]),
        "id_with_comma": set_path(["points", 0, "id"], "P,1"),
        "order_zero": set_path(["points", 0, "order"], 0),
        "order_1e300": set_path(["points", 0, "order"], 1e300),
        "face_index_wrong": set_path(["points", 0, "face_index"], 7),
        "version_2": set_path(["version"], 2),
    })
    regions = json.load(open(os.path.join(bases, "regions.json")))
    changes = {
        "no_faces": drop(["faces"]) if "faces" in regions else set_path(["format"], 1),
        "format_number": set_path(["format"], 3),
        "format_other": set_path(["format"], "furrow-regions-0"),
    }
    if "regions" in regions:
        changes["regions_string"] = set_path(["regions"], "none")
        changes["region_class_bad"] = set_path(["regions", 0, "class"], "wavy")
    mutate("regions", os.path.join(bases, "regions.json"), changes)
    prediction = json.load(open(os.path.join(bases, "prediction.json")))
    changes = {"keys_" + k: drop([k]) for k in list(prediction.keys())[:4]}
    changes["tool_diameter_1e300"] = set_path(["tool"], {"name": "B", "type": "ball", "diameter": 1e300,
                                                          "corner_radius": 5e299}) if "tool" in prediction else set_path(["x"], 1)
    mutate("prediction", os.path.join(bases, "prediction.json"), changes)
    comparison = json.load(open(os.path.join(bases, "comparison.json")))
    changes = {"keys_" + k: drop([k]) for k in list(comparison.keys())[:4]}
    mutate("comparison", os.path.join(bases, "comparison.json"), changes)


def main():
    part_cases()
    tool_cases()
    gcode_cases()
    apt_cases()
    toolpath_csv_cases()
    contact_cases()
    measurement_cases()
    job_cases()
    cad_cases()
    if len(sys.argv) > 1:
        mutation_cases(sys.argv[1])


if __name__ == "__main__":
    main()
