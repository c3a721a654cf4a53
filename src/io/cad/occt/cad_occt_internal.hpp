#pragma once
// Shared by the files of CAD import that talk to OpenCASCADE (src/io/cad/occt/,
// the CAD module; not part of Furrow's interface, see cad_import.hpp for that).
//
// FaceFailure is how a file below import_with_occt() says "this face cannot be
// imported, and here is why": the message reads on from "face <name>: ", and
// import_with_occt() adds the file and the face (or, with skip_bad_faces, lists the
// face as skipped). A plain exception type rather than InputError because the
// code that finds the problem does not know the file or the face's name.
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include <Eigen/Core>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace furrow::cad {

// A face-level failure; the caller adds the file and the face's name.
class FaceFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A length or deviation [mm] in a message: three significant digits.
inline std::string number_text(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

inline Eigen::Vector3d to_eigen(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }
inline Eigen::Vector3d to_eigen(const gp_Vec& v) { return {v.X(), v.Y(), v.Z()}; }

}  // namespace furrow::cad
