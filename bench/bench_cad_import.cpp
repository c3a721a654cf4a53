// Benchmark: importing a 150-face STEP part (target: under 2 s), and a
// 1000-face IGES surface model with sewing and orientation (under 10 s, 1 GB).
//
// The part is built here with OpenCASCADE: a 250 x 190 x 20 mm plate with 36
// cylindrical bosses, 36 through-holes and 36 spherical dimples (6 + 72 + 36 +
// 36 = 150 faces: planes with 108 circular trim loops, cylinders, spheres),
// written to STEP (and IGES), then imported with the default options. Prints
// the median wall time of several imports, OpenCASCADE's own share (reading
// and translating the file without converting anything), and the trim sizes.
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <IGESControl_Writer.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <STEPControl_Reader.hxx>
#include <STEPControl_Writer.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>


#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "bench_clock.hpp"
#include "io/cad/cad_import.hpp"
#include "occ_booleans.hpp"

using furrow::bench::peak_rss_mb;

namespace {

// nx x ny features on a 20 mm pitch: bosses, through-holes, dimples in turn.
TopoDS_Shape make_plate(int nx = 12, int ny = 9) {
  TopTools_ListOfShape cutters, bosses;
  int k = 0;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j, ++k) {
      const double x = 15 + 20 * i, y = 15 + 20 * j;
      if (k % 3 == 0)
        bosses.Append(BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, y, 20), gp::DZ()), 5, 10).Shape());
      else if (k % 3 == 1)
        cutters.Append(BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, y, -1), gp::DZ()), 4, 22).Shape());
      else
        cutters.Append(BRepPrimAPI_MakeSphere(gp_Pnt(x, y, 23), 6).Shape());
    }
  return furrow::bench::cut_then_fuse(BRepPrimAPI_MakeBox(10 + 20 * nx, 10 + 20 * ny, 20).Shape(), cutters, bosses);
}

double median_seconds(int runs, const std::function<void()>& work) {
  std::vector<double> times;
  for (int r = 0; r < runs; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    work();
    times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

}  // namespace

int main() {
  Message::DefaultMessenger()->ChangePrinters().Clear();
  const std::string dir = (std::filesystem::temp_directory_path() / "furrow_bench_cad_import").string();
  std::filesystem::create_directories(dir);
  const std::string step = dir + "/plate.step", iges = dir + "/plate.igs";

  const TopoDS_Shape part = make_plate();
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(part, TopAbs_FACE, faces);
  STEPControl_Writer writer;
  writer.Transfer(part, STEPControl_AsIs);
  writer.Write(step.c_str());
  IGESControl_Writer iges_writer("MM", 0);
  iges_writer.AddShape(part);
  iges_writer.ComputeModel();
  iges_writer.Write(iges.c_str());
  std::printf("part: %d faces (plate with 36 bosses, 36 holes, 36 dimples), STEP %.1f MB\n",
              faces.Extent(), std::filesystem::file_size(step) / 1e6);

  const int runs = 5;
  furrow::CadImportResult result;
  const double t_step = median_seconds(runs, [&] { result = furrow::import_cad(step); });
  std::map<std::string, int> types;
  long vertices = 0;
  int trimmed = 0, exact = 0;
  double worst_trim = 0, worst_deviation = 0;
  for (const auto& f : result.faces) {
    ++types[f.source_type];
    vertices += f.trim_vertices;
    trimmed += f.loops > 0;
    exact += f.exact;
    worst_trim = std::max(worst_trim, f.trim_deviation);
    worst_deviation = std::max(worst_deviation, f.deviation);
  }
  std::printf("import STEP: %zu faces in %.3f s (median of %d; target < 2 s)\n", result.part.faces.size(),
              t_step, runs);
  std::printf("  types:");
  for (const auto& [type, count] : types) std::printf(" %s %d", type.c_str(), count);
  std::printf("\n  %d exact, largest conversion deviation %.2g mm\n", exact, worst_deviation);
  std::printf("  %d trimmed faces, %ld trim vertices, largest trim deviation %.2g mm (tolerance %.0e)\n",
              trimmed, vertices, worst_trim, furrow::CadImportOptions().trim_chord_tolerance);

  const double t_occt = median_seconds(runs, [&] {
    STEPControl_Reader reader;
    reader.ReadFile(step.c_str());
    reader.TransferRoots();
  });
  std::printf("  of which OpenCASCADE reading and translating the STEP file: %.3f s\n", t_occt);

  furrow::CadImportOptions fine;
  fine.trim_chord_tolerance = 1e-6;
  const double t_fine = median_seconds(runs, [&] { furrow::import_cad(step, fine); });
  std::printf("  with trim tolerance 1e-6 mm instead: %.3f s\n", t_fine);

  const double t_iges = median_seconds(runs, [&] { result = furrow::import_cad(iges); });
  std::printf("import IGES: %zu faces in %.3f s (median of %d), a surface model: sewn into %d shells, %d closed\n",
              result.part.faces.size(), t_iges, runs, result.sewn_shells, result.closed_shells);

  // About 1000 faces: the plate patterned 31 x 24, as an IGES surface model
  // (every face loose, so the import sews and orients all of them).
  const TopoDS_Shape big = make_plate(31, 24);
  IGESControl_Writer big_writer("MM", 0);
  big_writer.AddShape(big);
  big_writer.ComputeModel();
  const std::string big_iges = dir + "/plate_1000.igs";
  big_writer.Write(big_iges.c_str());
  const double rss_before = peak_rss_mb();
  const double t_big = median_seconds(3, [&] { result = furrow::import_cad(big_iges); });
  int flipped = 0, undecided = 0;
  for (const auto& f : result.faces) {
    flipped += f.flipped;
    undecided += f.orientation == furrow::CadFaceOrientation::file;
  }
  std::printf("import IGES, %zu faces: %.2f s (median of 3; target < 10 s), sewn into %d shells, %d closed, "
              "%d faces turned, %d undecided; peak RSS %.0f MB (before the import %.0f MB; target < 1 GB)\n",
              result.part.faces.size(), t_big, result.sewn_shells, result.closed_shells, flipped, undecided,
              peak_rss_mb(), rss_before);
  furrow::CadImportOptions no_sewing;
  no_sewing.sewing_tolerance = 0;
  const double t_unsewn = median_seconds(3, [&] { furrow::import_cad(big_iges, no_sewing); });
  std::printf("  the same without sewing (--sewing-tolerance 0): %.2f s\n", t_unsewn);
  std::filesystem::remove_all(dir);
  return 0;
}
