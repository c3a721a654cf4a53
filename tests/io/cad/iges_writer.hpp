#pragma once
// A small IGES 5.3 writer for the tests: fixed-column 80-character records in
// the Start, Global, Directory Entry, Parameter Data and Terminate sections,
// with the entities CAD systems use for trimmed surfaces of revolution
// (100 circular arc, 102 composite curve, 106 copious data, 110 line, 120
// surface of revolution, 124 transformation, 126 rational B-spline curve,
// 128 rational B-spline surface, 142 curve on a parametric surface, 144
// trimmed surface). It writes files the way
// CATIA/NX-class systems do, which OpenCASCADE's own IGES writer does not
// (docs/formats.md "CAD import"): the reader is then tested on input it did
// not produce itself.
#include <Eigen/Core>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace furrow::test {

class IgesFile {
 public:
  // IGES real: always with an exponent, so it is never read as an integer.
  static std::string real(double x) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.16E", x);
    return buf;
  }
  static std::string integer(long x) { return std::to_string(x); }
  static std::string hollerith(const std::string& s) { return std::to_string(s.size()) + "H" + s; }

  // Adds an entity; returns its directory entry pointer (the sequence number
  // of its first DE line: 1, 3, 5, ...). `status` is the DE status number
  // (blank, subordinate, use, hierarchy: 2 digits each).
  int add(int type, int form, const std::vector<std::string>& params, const std::string& status = "00000000",
          int transform = 0, const std::string& label = "") {
    entities_.push_back({type, form, params, status, transform, label});
    return static_cast<int>(2 * entities_.size() - 1);
  }

  std::string text() const {
    std::string out;
    int s = 0;
    out += record("Furrow test IGES writer (CATIA/NX-style trimmed surfaces of revolution)", 'S', ++s);
    // Global section.
    const std::vector<std::string> global = {
        hollerith(","), hollerith(";"), hollerith("furrow-test"), hollerith("test.igs"),
        hollerith("furrow test writer"), hollerith("1.0"), "32", "38", "6", "308", "15",
        hollerith("furrow-test"), real(1), "2", hollerith("MM"), "1", real(1),
        hollerith("20260101.120000"), real(1e-7), real(1e6), hollerith("furrow"), hollerith("furrow"),
        "11", "0", hollerith("20260101.120000")};
    int g = 0;
    for (const std::string& line : pack(global, 72)) out += record(line, 'G', ++g);
    // Parameter data first (the DE lines point into it).
    std::vector<std::string> pd_lines;
    std::vector<int> pd_start, pd_count;
    for (std::size_t k = 0; k < entities_.size(); ++k) {
      const Entity& e = entities_[k];
      std::vector<std::string> fields{std::to_string(e.type)};
      fields.insert(fields.end(), e.params.begin(), e.params.end());
      const std::vector<std::string> lines = pack(fields, 64);
      pd_start.push_back(static_cast<int>(pd_lines.size()) + 1);
      pd_count.push_back(static_cast<int>(lines.size()));
      const int de = static_cast<int>(2 * k + 1);
      for (const std::string& l : lines) {
        char tail[16];
        std::snprintf(tail, sizeof tail, " %7d", de);
        pd_lines.push_back(pad(l, 64) + tail);
      }
    }
    int d = 0;
    for (std::size_t k = 0; k < entities_.size(); ++k) {
      const Entity& e = entities_[k];
      char line[96];
      std::snprintf(line, sizeof line, "%8d%8d%8d%8d%8d%8d%8d%8d%8s", e.type, pd_start[k], 0, 0, 0, 0, e.transform,
                    0, e.status.c_str());
      out += record(line, 'D', ++d);
      std::snprintf(line, sizeof line, "%8d%8d%8d%8d%8d%8s%8s%8s%8d", e.type, 0, 0, pd_count[k], e.form, "", "",
                    e.label.substr(0, 8).c_str(), 0);
      out += record(line, 'D', ++d);
    }
    int p = 0;
    for (const std::string& l : pd_lines) out += record(l, 'P', ++p);
    char term[96];
    std::snprintf(term, sizeof term, "S%07dG%07dD%07dP%07d", s, g, d, p);
    out += record(term, 'T', 1);
    return out;
  }

  void write(const std::string& path) const {
    std::ofstream f(path, std::ios::binary);
    f << text();
    if (!f) throw std::runtime_error("cannot write " + path);
  }

 private:
  struct Entity {
    int type, form;
    std::vector<std::string> params;
    std::string status;
    int transform;
    std::string label;
  };

  static std::string pad(const std::string& s, std::size_t width) {
    if (s.size() > width) throw std::logic_error("IGES record too long: " + s);
    return s + std::string(width - s.size(), ' ');
  }
  static std::string record(const std::string& data, char section, int sequence) {
    char tail[16];
    std::snprintf(tail, sizeof tail, "%c%7d\n", section, sequence);
    return pad(data, 72) + tail;
  }
  // Fields joined by ',' and ended by ';', broken into lines of at most
  // `width` columns only between fields (a field never spans two lines).
  static std::vector<std::string> pack(const std::vector<std::string>& fields, std::size_t width) {
    std::vector<std::string> lines{""};
    for (std::size_t k = 0; k < fields.size(); ++k) {
      const std::string piece = fields[k] + (k + 1 == fields.size() ? ";" : ",");
      if (lines.back().size() + piece.size() > width) lines.emplace_back();
      lines.back() += piece;
    }
    return lines;
  }

  std::vector<Entity> entities_;
};

// Entity builders. Points are (x, y, z); parameter-space curves are written
// with z = 0 in the surface's (u, v), as IGES 142 requires.
class IgesBuilder {
 public:
  IgesFile file;

  // Status of entities that only exist as parts of others (physically
  // dependent); parameter-space curves also carry use flag 05 (2-D parametric).
  static constexpr const char* kDependent = "00010000";
  static constexpr const char* kParametric = "00010500";

  int line(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const char* status = kDependent) {
    return file.add(110, 0, {r(a.x()), r(a.y()), r(a.z()), r(b.x()), r(b.y()), r(b.z())}, status);
  }
  // Type 100: counterclockwise arc in the plane z = zt of its definition
  // space, from `start` to `end` around `centre`.
  int arc(double zt, const Eigen::Vector2d& centre, const Eigen::Vector2d& start, const Eigen::Vector2d& end,
          int transform = 0, const char* status = kDependent) {
    return file.add(100, 0,
                    {r(zt), r(centre.x()), r(centre.y()), r(start.x()), r(start.y()), r(end.x()), r(end.y())},
                    status, transform);
  }
  // Type 124 form 0: x_world = R x_def + T (R orthonormal, det +1).
  int transformation(const Eigen::Matrix3d& rot, const Eigen::Vector3d& t) {
    std::vector<std::string> p;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) p.push_back(r(rot(i, j)));
      p.push_back(r(t(i)));
    }
    return file.add(124, 0, p, kDependent);
  }
  // Type 126: B-spline curve of `degree` over `knots` (poles.size() + degree
  // + 1 of them), rational when weights differ from 1, parameter range
  // [knots[degree], knots[poles.size()]].
  int bspline(int degree, const std::vector<double>& knots, const std::vector<Eigen::Vector3d>& poles,
              const std::vector<double>& weights, bool planar_xy, const char* status = kDependent) {
    const int n = static_cast<int>(poles.size());
    if (static_cast<int>(knots.size()) != n + degree + 1 || static_cast<int>(weights.size()) != n)
      throw std::logic_error("bad B-spline");
    bool polynomial = true;
    for (double w : weights) polynomial = polynomial && w == 1;
    const bool closed = (poles.front() - poles.back()).norm() < 1e-12;
    std::vector<std::string> p{std::to_string(n - 1), std::to_string(degree), planar_xy ? "1" : "0",
                               closed ? "1" : "0", polynomial ? "1" : "0", "0"};
    for (double k : knots) p.push_back(r(k));
    for (double w : weights) p.push_back(r(w));
    for (const auto& q : poles)
      for (int i = 0; i < 3; ++i) p.push_back(r(q(i)));
    p.push_back(r(knots[degree]));
    p.push_back(r(knots[n]));
    p.push_back(r(0));
    p.push_back(r(0));
    p.push_back(r(planar_xy ? 1 : 0));
    return file.add(126, 0, p, status);
  }
  // A straight segment as a degree-1 B-spline over [t0, t1].
  int bspline_line(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double t0, double t1, bool planar_xy,
                   const char* status = kDependent) {
    return bspline(1, {t0, t0, t1, t1}, {a, b}, {1, 1}, planar_xy, status);
  }
  // Circular arc `centre + radius (cos a x + sin a y)`, a from a0 to a1
  // (either direction), as a rational quadratic B-spline with knots in
  // radians (the parameter is not the angle inside a span).
  int bspline_arc(const Eigen::Vector3d& centre, const Eigen::Vector3d& x, const Eigen::Vector3d& y, double radius,
                  double a0, double a1) {
    const int spans = std::max(1, static_cast<int>(std::ceil(std::abs(a1 - a0) / (M_PI / 2) - 1e-9)));
    const double step = (a1 - a0) / spans;
    std::vector<Eigen::Vector3d> poles;
    std::vector<double> weights, knots{a0, a0, a0};
    auto at = [&](double a) { return Eigen::Vector3d(centre + radius * (std::cos(a) * x + std::sin(a) * y)); };
    for (int s = 0; s < spans; ++s) {
      const double b0 = a0 + s * step, b1 = b0 + step, w = std::cos(step / 2);
      if (s == 0) {
        poles.push_back(at(b0));
        weights.push_back(1);
      }
      poles.push_back(centre + radius / w * (std::cos(b0 + step / 2) * x + std::sin(b0 + step / 2) * y));
      weights.push_back(w);
      poles.push_back(at(b1));
      weights.push_back(1);
      if (s + 1 < spans) {
        knots.push_back(b1);
        knots.push_back(b1);
      }
    }
    knots.insert(knots.end(), {a1, a1, a1});
    if (a1 < a0) {  // knots must increase: run the parameter as -a
      for (double& k : knots) k = -k;
    }
    return bspline(2, knots, poles, weights, false);
  }
  // Type 106 form 11: a 2-D linear path through `points` (z = 0).
  int polyline_2d(const std::vector<Eigen::Vector2d>& points, const char* status = kDependent) {
    std::vector<std::string> p{"1", std::to_string(points.size()), r(0)};
    for (const auto& q : points) {
      p.push_back(r(q.x()));
      p.push_back(r(q.y()));
    }
    return file.add(106, 11, p, status);
  }
  int composite(const std::vector<int>& curves, const char* status = kDependent) {
    std::vector<std::string> p{std::to_string(curves.size())};
    for (int c : curves) p.push_back(std::to_string(c));
    return file.add(102, 0, p, status);
  }
  // Type 120: `generatrix` rotated about the line `axis` (its start to its
  // end) from `start_angle` to `end_angle`.
  int revolution(int axis, int generatrix, double start_angle, double end_angle) {
    return file.add(120, 0, {std::to_string(axis), std::to_string(generatrix), r(start_angle), r(end_angle)},
                    kDependent);
  }
  // Type 126 of degree `degree` given by OpenCASCADE-style distinct knots
  // and multiplicities (expanded here into IGES's flat knot sequence).
  int bspline_flat(int degree, const std::vector<double>& knots, const std::vector<int>& multiplicities,
                   const std::vector<Eigen::Vector3d>& poles, const std::vector<double>& weights) {
    std::vector<double> flat;
    for (std::size_t k = 0; k < knots.size(); ++k) flat.insert(flat.end(), multiplicities[k], knots[k]);
    return bspline(degree, flat, poles, weights, false);
  }
  // Type 128: a rational B-spline surface of degrees `du` x `dv` over flat
  // knot sequences; poles[i][j] with i along u (IGES runs u fastest);
  // `closed_u`/`periodic_u` are PROP1/PROP4 (the surface closes on itself
  // in u; it is periodic there, as a cylinder's angle is).
  int bspline_surface(int du, int dv, const std::vector<double>& knots_u, const std::vector<double>& knots_v,
                      const std::vector<std::vector<Eigen::Vector3d>>& poles,
                      const std::vector<std::vector<double>>& weights, bool closed_u, bool periodic_u) {
    const int nu = static_cast<int>(poles.size()), nv = static_cast<int>(poles.front().size());
    if (static_cast<int>(knots_u.size()) != nu + du + 1 || static_cast<int>(knots_v.size()) != nv + dv + 1)
      throw std::logic_error("bad B-spline surface");
    bool polynomial = true;
    for (const auto& row : weights)
      for (double w : row) polynomial = polynomial && w == 1;
    std::vector<std::string> p{std::to_string(nu - 1), std::to_string(nv - 1), std::to_string(du),
                               std::to_string(dv), closed_u ? "1" : "0", "0", polynomial ? "1" : "0",
                               periodic_u ? "1" : "0", "0"};
    for (double k : knots_u) p.push_back(r(k));
    for (double k : knots_v) p.push_back(r(k));
    for (int j = 0; j < nv; ++j)
      for (int i = 0; i < nu; ++i) p.push_back(r(weights[i][j]));
    for (int j = 0; j < nv; ++j)
      for (int i = 0; i < nu; ++i)
        for (int c = 0; c < 3; ++c) p.push_back(r(poles[i][j](c)));
    for (double x : {knots_u[du], knots_u[nu], knots_v[dv], knots_v[nv]}) p.push_back(r(x));
    return file.add(128, 0, p, kDependent);
  }
  // Type 142: CRTN (how the curve was made: 0 unspecified, 1 projection,
  // 2 intersection of two surfaces, 3 isoparametric), surface,
  // parameter-space curve B, model-space curve C, preferred representation
  // PREF: 0 unspecified, 1 the parameter-space curve (S o B), 2 the
  // model-space curve C, 3 both alike. (OpenCASCADE follows PREF 2 to C:
  // with a B whose u is normalised, only PREF 2 files import right; see the
  // tests.) `b` = 0 writes no parameter-space curve (PPTR 0), as CATIA does:
  // C alone bounds the face.
  int curve_on_surface(int surface, int b, int c, int pref, int crtn = 0) {
    return file.add(142, 0,
                    {std::to_string(crtn), std::to_string(surface), std::to_string(b), std::to_string(c),
                     std::to_string(pref)},
                    kDependent);
  }
  int trimmed_surface(int surface, int outer, const std::vector<int>& inner = {}) {
    std::vector<std::string> p{std::to_string(surface), "1", std::to_string(inner.size()), std::to_string(outer)};
    for (int i : inner) p.push_back(std::to_string(i));
    return file.add(144, 0, p, "00000000");
  }

 private:
  static std::string r(double x) { return IgesFile::real(x); }
};

}  // namespace furrow::test
