#pragma once
// The CAD benches' parts are a plate with features, built as a CAD system
// builds them: every cutter subtracted in one boolean, then every boss added
// in one (OpenCASCADE's multi-argument booleans, much faster than one
// operation per feature).
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS_Shape.hxx>

namespace furrow::bench {

inline TopoDS_Shape cut_then_fuse(const TopoDS_Shape& base, const TopTools_ListOfShape& cutters,
                                  const TopTools_ListOfShape& bosses) {
  TopTools_ListOfShape arguments;
  arguments.Append(base);
  BRepAlgoAPI_Cut cut;
  cut.SetArguments(arguments);
  cut.SetTools(cutters);
  cut.Build();
  TopTools_ListOfShape cut_list;
  cut_list.Append(cut.Shape());
  BRepAlgoAPI_Fuse fuse;
  fuse.SetArguments(cut_list);
  fuse.SetTools(bosses);
  fuse.Build();
  return fuse.Shape();
}

}  // namespace furrow::bench
