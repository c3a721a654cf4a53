// Regions merged across faces on a real CAD part: a block with every edge
// filleted, built and written to STEP by OpenCASCADE. Its 12 edge fillets
// and 8 corner blends are convex and meet one another tangentially, so they
// are one surface (one group); each of the 6 flat sides meets the fillets
// tangentially too but is planar, and meets no other side, so each is a
// group of its own. Without fillets the six sides meet at right angles:
// six groups.
#include <doctest/doctest.h>

#include <BRepFilletAPI_MakeFillet.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS_Edge.hxx>

#include "cad_reference.hpp"
#include "io/cad/cad_import.hpp"
#include "partition/partition.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

RegionMap partition_of(const TopoDS_Shape& shape, const std::string& name) {
  const std::string path = scratch_dir("cad-region-groups-" + name) + "/" + name + ".step";
  write_step(shape, path);
  const Part part = import_cad(path).part;
  PartitionOptions o;
  o.spacing = 0.5;
  return partition_part(part, o).map;
}

}  // namespace

TEST_CASE("region groups: a block with filleted edges has one blend surface and six flat sides") {
  const TopoDS_Shape block = BRepPrimAPI_MakeBox(60, 40, 25).Shape();
  BRepFilletAPI_MakeFillet fillet(block);
  for (TopExp_Explorer e(block, TopAbs_EDGE); e.More(); e.Next()) fillet.Add(4.0, TopoDS::Edge(e.Current()));
  const TopoDS_Shape rounded = fillet.Shape();
  REQUIRE(faces_of(rounded).size() == 26);

  const RegionMap map = partition_of(rounded, "filleted");
  int planar_groups = 0, blend_groups = 0;
  double blend_area = 0;
  for (const RegionGroup& g : map.groups) {
    CAPTURE(g.id);
    if (g.curvature_class == CurvatureClass::planar) {
      ++planar_groups;
      CHECK(g.faces.size() == 1);
    } else {
      ++blend_groups;
      CHECK(g.curvature_class == CurvatureClass::convex);
      blend_area += g.area;
      CHECK(g.faces.size() == 20);  // every fillet and corner in it
    }
  }
  CHECK(planar_groups == 6);
  CHECK(blend_groups == 1);
  // The blend surface's area from OpenCASCADE: the block's area less its
  // six flat sides (each a rectangle shortened by the radius at every edge).
  double flat = 0;
  for (const TopoDS_Face& f : faces_of(rounded))
    if (BRepAdaptor_Surface(f).GetType() == GeomAbs_Plane) flat += occt_area(f);
  double total = 0;
  for (const TopoDS_Face& f : faces_of(rounded)) total += occt_area(f);
  CHECK(blend_area == doctest::Approx(total - flat).epsilon(0.01));
}

TEST_CASE("region groups: the sides of a sharp block meet at right angles and stay apart") {
  const RegionMap map = partition_of(BRepPrimAPI_MakeBox(60, 40, 25).Shape(), "sharp");
  CHECK(map.regions.size() == 6);
  CHECK(map.groups.size() == 6);
}
