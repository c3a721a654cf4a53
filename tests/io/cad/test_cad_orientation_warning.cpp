// The planner's "normals into the material?" warning on parts built with
// OpenCASCADE (docs/cmm.md "Faces that face down"): a face of a closed,
// consistently oriented solid is an underside when it faces down and is never
// named; a face whose orientation the import could not establish (an open
// shell of loose faces) is. The oracle is the topology the test builds: which
// shapes are solids, which faces are open, which faces point down.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "cad_reference.hpp"
#include "io/cad/cad_import.hpp"
#include "io/part_file.hpp"
#include "partition/partition.hpp"
#include "planning/probe_planner.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

// A T-shaped block (a 60 x 40 slab over a 40 x 40 pedestal, overhanging by
// 10 mm on both sides) with a pocket in its top: three faces point down (the
// pedestal's foot and the two overhangs' undersides).
TopoDS_Shape overhang_block_with_pocket() {
  TopoDS_Shape block = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), gp_Pnt(40, 40, 10)).Shape();
  block = BRepAlgoAPI_Fuse(block, BRepPrimAPI_MakeBox(gp_Pnt(-10, 0, 10), gp_Pnt(50, 40, 20)).Shape()).Shape();
  return BRepAlgoAPI_Cut(block, BRepPrimAPI_MakeBox(gp_Pnt(10, 12, 12), gp_Pnt(30, 28, 25)).Shape()).Shape();
}

// The same block's faces without the slab's end face at x = 50, as loose
// faces: they sew into an open shell, whose inside nothing tells.
TopoDS_Shape open_shell() {
  std::vector<TopoDS_Shape> faces;
  for (const TopoDS_Face& f : faces_of(overhang_block_with_pocket())) {
    BRepAdaptor_Surface s(f);
    const gp_Pnt c = s.Value((s.FirstUParameter() + s.LastUParameter()) / 2, (s.FirstVParameter() + s.LastVParameter()) / 2);
    if (std::abs(c.X() - 50) > 1e-9) faces.push_back(f);
  }
  return compound_of(faces);
}

bool faces_down(const Face& f) {
  const ParameterDomain& d = f.domain();
  return f.geometry((d.u0 + d.u1) / 2, (d.v0 + d.v1) / 2).normal.z() < -0.99;
}

struct Planned {
  Part part;
  PlanResult plan;
};

Planned plan_step(const TopoDS_Shape& shape, const std::string& name) {
  const std::string path = scratch_dir("orientation-warning") + "/" + name + ".step";
  write_step(shape, path);
  Planned out;
  out.part = import_cad(path).part;
  PartitionOptions po;
  po.grid = GridSize{40, 40};
  const RegionMap map = partition_part(out.part, po).map;
  PlannerOptions o;
  o.points = 120;
  o.min_per_region = 3;
  out.plan = plan_probe_points(out.part, map, o);
  return out;
}

// The faces facing down whose every candidate the planner dropped: those
// the warning looks at.
std::vector<std::size_t> dropped_down_faces(const Planned& p) {
  std::vector<std::size_t> out;
  for (std::size_t f = 0; f < p.part.faces.size(); ++f) {
    if (!faces_down(p.part.faces[f])) continue;
    int sampled = 0, planned = 0;
    for (const RegionPlanSummary& r : p.plan.regions)
      if (r.face == static_cast<int>(f)) {
        sampled += r.sampled;
        planned += r.planned;
      }
    if (sampled >= 3 && planned == 0) out.push_back(f);
  }
  return out;
}

int candidates(const PlanResult& r) {
  int n = 0;
  for (const RegionPlanSummary& s : r.regions) n += s.sampled;
  return n;
}

}  // namespace

TEST_CASE("the import establishes the orientation of a solid's faces and not of an open shell's, and the part file keeps it") {
  silence_occt();
  const std::string dir = scratch_dir("orientation-established");
  write_step(overhang_block_with_pocket(), dir + "/solid.step");
  write_step(open_shell(), dir + "/open.step");
  const CadImportResult solid = import_cad(dir + "/solid.step");
  const CadImportResult open = import_cad(dir + "/open.step");
  REQUIRE(solid.solids == 1);
  REQUIRE(open.solids == 0);
  REQUIRE(open.free_faces == solid.part.faces.size() - 1);
  for (const Face& f : solid.part.faces) CHECK(f.orientation_established());
  for (const Face& f : open.part.faces) CHECK_FALSE(f.orientation_established());

  // Round trip through the part file.
  const Part back = parse_part_json(part_to_json_text(solid.part), "solid.json");
  for (const Face& f : back.faces) CHECK(f.orientation_established());
  const Part back_open = parse_part_json(part_to_json_text(open.part), "open.json");
  for (const Face& f : back_open.faces) CHECK_FALSE(f.orientation_established());
}

TEST_CASE("a closed solid's downward faces draw no orientation warning, an open shell's downward face does") {
  silence_occt();
  const Planned solid = plan_step(overhang_block_with_pocket(), "solid");
  // The warning is looked for (most candidates dropped) and the three
  // downward faces of the solid are among those it would have named.
  REQUIRE(2 * static_cast<int>(solid.plan.plan.points.size()) < candidates(solid.plan));
  CHECK(dropped_down_faces(solid).size() == 3);
  for (const PlanIssue& i : solid.plan.issues) CHECK(i.kind != PlanIssue::Kind::face_facing_down);

  // The open shell: the same downward faces, but nothing established that
  // they should face down, so each is named.
  const Planned open = plan_step(open_shell(), "open");
  REQUIRE(2 * static_cast<int>(open.plan.plan.points.size()) < candidates(open.plan));
  const std::vector<std::size_t> down = dropped_down_faces(open);
  REQUIRE(down.size() == 3);
  std::vector<std::size_t> named;
  for (const PlanIssue& i : open.plan.issues)
    if (i.kind == PlanIssue::Kind::face_facing_down) {
      named.push_back(static_cast<std::size_t>(i.face));
      CHECK(i.reason.find("normals into the material?") != std::string::npos);
    }
  CHECK(named == down);
}
