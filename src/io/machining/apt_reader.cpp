#include "io/machining/apt_reader.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "base/number_text.hpp"
#include "base/error.hpp"
#include "base/limits.hpp"
#include "base/numbers.hpp"
#include "base/text_fields.hpp"
#include "io/machining/apt_statements.hpp"
#include "io/machining/gcode_arc.hpp"
#include "io/part_file.hpp"

namespace furrow {

namespace {

// A direction component this small is zero: CAM systems write unit vectors
// with 6-7 decimals, so a vertical axis reads 0.0000000 exactly.
constexpr double kAxisTolerance = 1e-6;
// Two cutters this close in diameter and corner radius are one tool: posts
// write 4 decimals, and inch values converted to mm differ by rounding.
constexpr double kToolTolerance = 1e-3;  // mm

[[noreturn]] void fail_line(const std::string& name, int line, const std::string& what) {
  throw InputError(name + ":" + std::to_string(line) + ": " + what);
}

std::string mm_text(double x) { return general(x) + " mm"; }

// The parameters of a statement as numbers; every one must be a finite
// number ("GOTO/1,,3", "GOTO/1,NAN,3" and 1e999 are refused).
std::vector<double> numbers(const AptStatement& s, const std::string& name, std::size_t first = 0) {
  std::vector<double> out;
  for (std::size_t k = first; k < s.params.size(); ++k) {
    const std::string& p = s.params[k];
    if (p.empty()) fail_line(name, s.line, s.major + "/: value " + std::to_string(k + 1) + " is missing");
    double x = 0;
    if (!parse_finite(p, x))
      fail_line(name, s.line, s.major + "/: value " + std::to_string(k + 1) + " " + quote_field(p) +
                                  " is not a finite number");
    out.push_back(x);
  }
  return out;
}

// A unit direction along +z, or the line is refused: the reader and every
// later stage cut with a vertical tool.
void require_vertical(double i, double j, double k, const std::string& what, const std::string& name, int line) {
  const double n = std::sqrt(i * i + j * j + k * k);
  if (!(n > 0)) fail_line(name, line, what + " (0,0,0) is not a direction");
  if (std::abs(i) > kAxisTolerance * n || std::abs(j) > kAxisTolerance * n || !(k > 0))
    fail_line(name, line, what + " is not the vertical +z (0,0,1): only 3-axis paths are read (no tilted tool)");
}

// Major words that cannot change the cut (docs/formats.md "Tool paths").
bool is_ignored_major(const std::string& major) {
  static const std::set<std::string> kIgnored = {
      "PARTNO", "PPRINT", "MACHIN", "LOADTL", "LOAD", "SPINDL", "COOLNT", "TOOL PATH", "END-OF-PATH",
      "PAINT",  "SELCTL", "OPSTOP", "STOP",   "END",  "DELAY",  "SEQNO",  "TPRINT",    "DISPLY",
      "OPSKIP"};
  return kIgnored.count(major) > 0;
}

struct PendingCircle {
  int line = 0;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // mm
  ArcPlane plane = ArcPlane::xy;
  bool clockwise = false;
  double radius = 0;  // mm
};

// Axis index (0 x, 1 y, 2 z) of a direction along a coordinate axis, and its
// sign; -1 when tilted.
int coordinate_axis(const Eigen::Vector3d& d, double& sign) {
  const double n = d.norm();
  if (!(n > 0)) return -1;
  for (int a = 0; a < 3; ++a) {
    bool others_zero = true;
    for (int b = 0; b < 3; ++b)
      if (b != a && std::abs(d[b]) > kAxisTolerance * n) others_zero = false;
    if (others_zero) {
      sign = d[a] > 0 ? 1.0 : -1.0;
      return a;
    }
  }
  return -1;
}

ArcPlane plane_of_axis(int axis) { return axis == 2 ? ArcPlane::xy : axis == 1 ? ArcPlane::zx : ArcPlane::yz; }

class AptReader {
 public:
  AptReader(const std::string& name, const ToolpathReadOptions& options) : name_(name) {
    path_.kind = ToolpathKind::tool_tips;
    path_.source = name;
    scale_ = units_to_mm(options.units, name + ": units");
    if (!(options.arc_tolerance > 0) || !std::isfinite(options.arc_tolerance))
      throw InputError(name + ": the arc chord tolerance must be a positive number of mm");
    arc_tolerances_.sag = options.arc_tolerance;
  }

  Toolpath read(const std::string& text) {
    const std::vector<AptStatement> statements = split_apt_statements(text, name_);
    bool finished = false;
    for (const AptStatement& s : statements) {
      if (finished) fail_line(name_, s.line, s.major + " after FINI (the end of the program)");
      if (s.major == "FINI") {
        finished = true;
        continue;
      }
      statement(s);
    }
    if (circle_) fail_line(name_, circle_->line, "CIRCLE/ is not followed by the GOTO/ that ends the arc");
    close_pass();
    if (path_.passes.empty()) throw InputError(name_ + ": no cutting moves (GOTO/, arcs) in the file");
    return std::move(path_);
  }

 private:
  void statement(const AptStatement& s) {
    const std::string& m = s.major;
    if (m.empty()) fail_line(name_, s.line, "a statement without a major word (expected e.g. GOTO/x,y,z)");
    for (char c : m)
      if (!(std::isalnum(static_cast<unsigned char>(c)) || c == ' ' || c == ',' || c == '-' || c == '_'))
        fail_line(name_, s.line, "not an APT statement (letters, digits, '-' or '_' before '/'): a binary or UTF-16 file?");
    if (m == "GOTO") return go_to(s);
    if (m == "FROM") return from(s);
    if (m == "GODLTA") return go_delta(s);
    if (m == "RAPID") {
      if (s.has_slash) fail_line(name_, s.line, "RAPID takes no values");
      rapid_next_ = true;
      return;
    }
    if (m == "CIRCLE") return circle(s);
    if (m == "INDIRV") return indirv(s);
    if (m == "TLON,GOFWD") return go_forward(s);
    if (m == "UNITS") return units(s);
    if (m == "FEDRAT") return feedrate(s);
    if (m == "CUTTER") return cutter(s);
    if (m == "TLDATA") return tldata(s);
    if (m == "TLAXIS") {
      const std::vector<double> v = numbers(s, name_);
      if (v.size() != 3) fail_line(name_, s.line, "TLAXIS/ takes i,j,k (3 values)");
      require_vertical(v[0], v[1], v[2], "TLAXIS/ tool axis", name_, s.line);
      return ignore(s);
    }
    if (m == "MULTAX") {
      // Every GOTO's axis is checked: MULTAX/ON with a vertical axis cuts the
      // same part as without.
      if (s.params.size() > 1 || (s.params.size() == 1 && s.params[0] != "ON" && s.params[0] != "OFF"))
        fail_line(name_, s.line, "MULTAX takes ON or OFF");
      return ignore(s);
    }
    if (m == "MSYS") return msys(s);
    if (m == "CUTCOM" || m == "CYCLE") {
      if (s.params.size() == 1 && s.params[0] == "OFF") return ignore(s);
      fail_line(name_, s.line, m + (m == "CUTCOM" ? " (cutter compensation) is not supported: the control would "
                                                   "offset the path by a radius that is not in the file"
                                                 : " (a canned cycle) is not supported: the control would expand "
                                                   "it into moves that are not in the file"));
    }
    if (is_ignored_major(m)) return ignore(s);
    fail_line(name_, s.line, "major word " + quote_field(m) +
                                 " is not supported (it may move or offset the tool in a way the file does not "
                                 "show; docs/formats.md \"Tool paths\" lists the APT words read)");
  }

  void ignore(const AptStatement& s) { path_.ignored.push_back({s.line, s.major}); }

  Eigen::Vector3d point(const std::vector<double>& v, std::size_t at, int line) const {
    Eigen::Vector3d p(v[at], v[at + 1], v[at + 2]);
    p *= scale_;
    for (int a = 0; a < 3; ++a)
      limits::check_coordinate(p[a], name_ + ":" + std::to_string(line) + ": " + char('x' + a));
    return p;
  }

  void go_to(const AptStatement& s) {
    const std::vector<double> v = numbers(s, name_);
    if (v.size() != 3 && v.size() != 6)
      fail_line(name_, s.line, "GOTO/ takes x,y,z or x,y,z,i,j,k (found " + std::to_string(v.size()) + " values)");
    if (v.size() == 6) require_vertical(v[3], v[4], v[5], "GOTO/ tool axis", name_, s.line);
    move(point(v, 0, s.line), s.line);
  }

  void from(const AptStatement& s) {
    const std::vector<double> v = numbers(s, name_);
    if (v.size() != 3 && v.size() != 6)
      fail_line(name_, s.line, "FROM/ takes x,y,z or x,y,z,i,j,k (found " + std::to_string(v.size()) + " values)");
    if (v.size() == 6) require_vertical(v[3], v[4], v[5], "FROM/ tool axis", name_, s.line);
    if (circle_) fail_line(name_, circle_->line, "CIRCLE/ is not followed by the GOTO/ that ends the arc");
    rapid_next_ = false;
    reposition(point(v, 0, s.line));
  }

  void go_delta(const AptStatement& s) {
    const std::vector<double> v = numbers(s, name_);
    if (v.size() != 1 && v.size() != 3)
      fail_line(name_, s.line, "GODLTA/ takes dx,dy,dz or a distance along the tool axis");
    if (!known_) fail_line(name_, s.line, "GODLTA/ before the position is known (give FROM/ or GOTO/ first)");
    const Eigen::Vector3d d = v.size() == 1 ? Eigen::Vector3d(0, 0, v[0]) : Eigen::Vector3d(v[0], v[1], v[2]);
    Eigen::Vector3d to = position_ + d * scale_;
    for (int a = 0; a < 3; ++a)
      limits::check_coordinate(to[a], name_ + ":" + std::to_string(s.line) + ": " + char('x' + a));
    move(to, s.line);
  }

  // A motion to `to`: a rapid when RAPID came before it, else a cut (an arc
  // when a CIRCLE is pending).
  void move(const Eigen::Vector3d& to, int line) {
    if (rapid_next_) {
      if (circle_) fail_line(name_, circle_->line, "CIRCLE/ is followed by a RAPID move instead of its GOTO/");
      rapid_next_ = false;
      RapidMove rapid;  // checked against the part like a G0 (io/machining/toolpath_file.hpp)
      rapid.line = line;
      rapid.tool = tool_;
      rapid.known = known_;
      if (known_) {
        rapid.from = position_;
        rapid.to = to;
      }
      if (!rapid.known || rapid.from != rapid.to) path_.rapids.push_back(rapid);
      reposition(to);
      return;
    }
    if (!known_)
      fail_line(name_, line, "cutting move from an unknown position (give FROM/ or RAPID and GOTO/ before it)");
    std::vector<Eigen::Vector3d> reached;
    if (circle_) {
      const PendingCircle c = *circle_;
      circle_.reset();
      ArcMove arc;
      arc.start = position_;
      arc.end = to;
      arc.plane = c.plane;
      arc.clockwise = c.clockwise;
      arc.centre_offset = c.centre - position_;
      check_radius(c, position_, line);
      reached = flatten(arc, line, "CIRCLE/ at line " + std::to_string(c.line));
    } else {
      reached.push_back(to);
    }
    cut(reached, line);
  }

  // The start's distance from the centre (in the arc's plane) must be the
  // radius the statement gives, within the tolerance gcode_arc.hpp allows
  // between start and end radius.
  void check_radius(const PendingCircle& c, const Eigen::Vector3d& start, int line) const {
    Eigen::Vector3d d = start - c.centre;
    d[c.plane == ArcPlane::xy ? 2 : c.plane == ArcPlane::zx ? 1 : 0] = 0;
    const ArcTolerances tol;
    const double allowed = std::max(tol.radius_absolute, tol.radius_relative * c.radius);
    if (std::abs(d.norm() - c.radius) > allowed)
      fail_line(name_, line, "the arc starts " + mm_text(d.norm()) + " from the centre of CIRCLE/ at line " +
                                 std::to_string(c.line) + ", whose radius is " + mm_text(c.radius));
  }

  std::vector<Eigen::Vector3d> flatten(const ArcMove& arc, int line, const std::string& what) const {
    try {
      return flatten_arc(arc, arc_tolerances_);
    } catch (const InputError& e) {
      fail_line(name_, line, what + ": " + e.what());
    }
  }

  void cut(const std::vector<Eigen::Vector3d>& reached, int line) {
    if (points_ + static_cast<long>(reached.size()) > limits::kMaxFilePoints)
      fail_line(name_, line, "more than " + std::to_string(limits::kMaxFilePoints) +
                                 " tool-path points (docs/formats.md \"Limits\")");
    auto tip = [&](const Eigen::Vector3d& p) {
      ToolpathPoint t;
      t.position = p;
      t.feed = feed_;
      t.line = line;
      return t;
    };
    if (current_.points.empty()) {
      current_.points.push_back(tip(position_));
      current_.tool = tool_;
    }
    for (const Eigen::Vector3d& p : reached)
      if ((p - current_.points.back().position).norm() > 0) {  // zero-length moves add nothing
        current_.points.push_back(tip(p));
        ++points_;
      }
    position_ = reached.back();
  }

  // A move that is not cut (RAPID GOTO, FROM): the pass ends, as at a G0.
  // FROM/ only states where the tool is: it is not a move and not a rapid.
  void reposition(const Eigen::Vector3d& to) {
    close_pass();
    position_ = to;
    known_ = true;
  }

  void close_pass() {
    if (current_.points.size() >= 2) path_.passes.push_back(std::move(current_));
    current_ = ToolpathPass{};
  }

  void circle(const AptStatement& s) {
    if (circle_) fail_line(name_, s.line, "CIRCLE/ follows the CIRCLE/ at line " + std::to_string(circle_->line) +
                                              " without the GOTO/ that ends it");
    const std::vector<double> v = numbers(s, name_);
    if (v.size() < 7)
      fail_line(name_, s.line, "CIRCLE/ before a GOTO/ takes xc,yc,zc,i,j,k,r (found " + std::to_string(v.size()) +
                                   " values)");
    PendingCircle c;
    c.line = s.line;
    c.centre = point(v, 0, s.line);
    double sign = 1;
    const int axis = coordinate_axis(Eigen::Vector3d(v[3], v[4], v[5]), sign);
    if (axis < 0)
      fail_line(name_, s.line, "CIRCLE/ axis is not along x, y or z: only 3-axis arcs in the XY, ZX or YZ plane are read");
    c.plane = plane_of_axis(axis);
    // Counter-clockwise about the axis; gcode_arc's sense is seen from the
    // plane normal's positive side.
    c.clockwise = sign < 0;
    c.radius = v[6] * scale_;
    if (!(c.radius > 0)) fail_line(name_, s.line, "CIRCLE/ radius must be positive");
    limits::check_coordinate(c.radius, name_ + ":" + std::to_string(s.line) + ": r");
    circle_ = c;
  }

  void indirv(const AptStatement& s) {
    const std::vector<double> v = numbers(s, name_);
    if (v.size() != 3) fail_line(name_, s.line, "INDIRV/ takes i,j,k (3 values)");
    const Eigen::Vector3d d(v[0], v[1], v[2]);
    if (!(d.norm() > 0)) fail_line(name_, s.line, "INDIRV/ (0,0,0) is not a direction");
    indirv_ = d.normalized();
    indirv_line_ = s.line;
  }

  // Inner (CIRCLE/...) or (LINE/...): its numbers.
  std::vector<double> inner(const std::string& group, const char* word, int line) const {
    const std::string prefix = std::string("(") + word + "/";
    if (group.size() < prefix.size() + 1 || group.compare(0, prefix.size(), prefix) != 0 || group.back() != ')')
      fail_line(name_, line, std::string("TLON,GOFWD/ expects (") + word + "/...) here, found " + quote_field(group));
    AptStatement s;
    s.line = line;
    s.major = word;
    s.has_slash = true;
    s.params = split_apt_params(group.substr(prefix.size(), group.size() - prefix.size() - 1), name_, line);
    return numbers(s, name_);
  }

  // TLON,GOFWD/(CIRCLE/xc,yc,zc,r),ON,(LINE/x1,y1,z1,x2,y2,z2): along the
  // circle from the current position, starting in the INDIRV direction, to
  // the first point where the circle meets the line.
  void go_forward(const AptStatement& s) {
    if (s.params.size() != 3 || s.params[1] != "ON")
      fail_line(name_, s.line, "TLON,GOFWD/ is read as (CIRCLE/xc,yc,zc,r),ON,(LINE/x1,y1,z1,x2,y2,z2) only");
    if (rapid_next_) fail_line(name_, s.line, "RAPID before an arc: a rapid moves in a straight line");
    if (circle_) fail_line(name_, circle_->line, "CIRCLE/ is not followed by the GOTO/ that ends the arc");
    if (!known_) fail_line(name_, s.line, "arc from an unknown position (give FROM/ or RAPID and GOTO/ before it)");
    if (!indirv_) fail_line(name_, s.line, "TLON,GOFWD/ without INDIRV/ before it: the arc's direction is not given");
    std::vector<double> cv = inner(s.params[0], "CIRCLE", s.line);
    if (cv.size() == 7) {
      double sign = 1;
      if (coordinate_axis(Eigen::Vector3d(cv[3], cv[4], cv[5]), sign) != 2)
        fail_line(name_, s.line, "TLON,GOFWD/ circle axis is not z: only arcs in the XY plane are read here");
      cv = {cv[0], cv[1], cv[2], cv[6]};
    }
    if (cv.size() != 4) fail_line(name_, s.line, "(CIRCLE/...) takes xc,yc,zc,r or xc,yc,zc,i,j,k,r");
    const std::vector<double> lv = inner(s.params[2], "LINE", s.line);
    if (lv.size() != 6) fail_line(name_, s.line, "(LINE/...) takes x1,y1,z1,x2,y2,z2");
    const Eigen::Vector3d c = point(cv, 0, s.line);
    const double r = cv[3] * scale_;
    if (!(r > 0)) fail_line(name_, s.line, "(CIRCLE/...) radius must be positive");
    limits::check_coordinate(r, name_ + ":" + std::to_string(s.line) + ": r");
    const Eigen::Vector3d l0 = point(lv, 0, s.line);
    const Eigen::Vector3d l1 = point(lv, 3, s.line);
    PendingCircle pc;
    pc.line = s.line;
    pc.centre = c;
    pc.radius = r;
    check_radius(pc, position_, s.line);
    const ArcTolerances tol;
    if (std::abs(position_.z() - c.z()) > tol.radius_absolute)
      fail_line(name_, s.line, "the tool tip is " + mm_text(std::abs(position_.z() - c.z())) +
                                   " off the circle's plane z = " + mm_text(c.z()));
    const Eigen::Vector2d s2 = (position_ - c).head<2>();
    const Eigen::Vector2d dir = indirv_->head<2>();
    const double turn = s2.x() * dir.y() - s2.y() * dir.x();  // > 0: counter-clockwise
    if (!(std::abs(turn) > kAxisTolerance * s2.norm()))
      fail_line(name_, indirv_line_, "INDIRV/ is not tangent to the circle of line " + std::to_string(s.line) +
                                         " at the tool's position");
    const bool clockwise = turn < 0;
    // The line in XY: l0 + t (l1 - l0); its points at distance r from c.
    const Eigen::Vector2d p0 = (l0 - c).head<2>();
    const Eigen::Vector2d dl = (l1 - l0).head<2>();
    if (!(dl.norm() > ArcTolerances().same_point)) fail_line(name_, s.line, "(LINE/...) has two equal points in XY");
    const double a = dl.squaredNorm(), b = 2 * p0.dot(dl), q = p0.squaredNorm() - r * r;
    const double disc = b * b - 4 * a * q;
    if (disc < 0) fail_line(name_, s.line, "(LINE/...) does not meet the circle");
    const double a0 = std::atan2(s2.y(), s2.x());
    double best = -1;
    Eigen::Vector2d end2 = s2;
    for (double sgn : {-1.0, 1.0}) {
      const double t = (-b + sgn * std::sqrt(disc)) / (2 * a);
      const Eigen::Vector2d e = p0 + t * dl;
      const double a1 = std::atan2(e.y(), e.x());
      double sweep = clockwise ? a0 - a1 : a1 - a0;
      while (sweep < 0) sweep += 2 * kPi;
      while (sweep >= 2 * kPi) sweep -= 2 * kPi;
      if (sweep * r <= tol.same_point) sweep = 2 * kPi;  // the start itself: once round
      if (best < 0 || sweep < best) {
        best = sweep;
        end2 = e;
      }
    }
    ArcMove arc;
    arc.start = position_;
    arc.end = Eigen::Vector3d(c.x() + end2.x(), c.y() + end2.y(), position_.z());
    arc.plane = ArcPlane::xy;
    arc.clockwise = clockwise;
    arc.centre_offset = c - position_;
    indirv_.reset();
    cut(flatten(arc, s.line, "TLON,GOFWD/"), s.line);
  }

  void units(const AptStatement& s) {
    if (s.params.size() != 1) fail_line(name_, s.line, "UNITS/ takes MM or INCHES");
    const std::string& u = s.params[0];
    if (u == "MM")
      scale_ = 1.0;
    else if (u == "INCHES" || u == "INCH")
      scale_ = 25.4;
    else
      fail_line(name_, s.line, "UNITS/" + quote_field(u) + ": expected MM or INCHES");
  }

  void feedrate(const AptStatement& s) {
    double value = 0;
    std::string mode;
    bool have_value = false;
    for (const std::string& p : s.params) {
      if (p == "IPM" || p == "MMPM" || p == "IPR" || p == "MMPR") {
        if (!mode.empty()) fail_line(name_, s.line, "FEDRAT/ gives its mode twice");
        mode = p;
        continue;
      }
      if (have_value) fail_line(name_, s.line, "FEDRAT/ takes one feed and an optional IPM, MMPM, IPR or MMPR");
      if (p.empty()) fail_line(name_, s.line, "FEDRAT/: the feed is missing");
      if (!parse_finite(p, value)) fail_line(name_, s.line, "FEDRAT/: feed " + quote_field(p) + " is not a finite number");
      have_value = true;
    }
    if (!have_value) fail_line(name_, s.line, "FEDRAT/: the feed is missing");
    if (!(value > 0)) fail_line(name_, s.line, "FEDRAT/: the feed must be positive");
    if (mode == "IPR" || mode == "MMPR")
      feed_ = 0;  // per revolution: mm/min needs the spindle speed
    else
      feed_ = value * (mode == "IPM" ? 25.4 : mode == "MMPM" ? 1.0 : scale_);
    if (!std::isfinite(feed_)) fail_line(name_, s.line, "FEDRAT/: the feed is too large");
  }

  void define_tool(const AptStatement& s, double d, double r) {
    d *= scale_;
    r *= scale_;
    ToolSpec tool;
    char buf[96];
    std::snprintf(buf, sizeof buf, "%s/%.6g,%.6g", s.major.c_str(), d, r);
    tool.name = buf;
    tool.diameter = d;
    tool.corner_radius = r;
    if (r == 0) {
      tool.type = ToolType::flat;
    } else if (std::abs(r - d / 2) <= kToolTolerance) {
      tool.type = ToolType::ball;
      tool.corner_radius = d / 2;
    } else {
      tool.type = ToolType::bull;
    }
    validate_tool(tool, name_ + ":" + std::to_string(s.line) + ": " + s.major);
    auto same = [&](const ToolSpec& t) {
      return std::abs(t.diameter - tool.diameter) <= kToolTolerance &&
             std::abs(t.corner_radius - tool.corner_radius) <= kToolTolerance;
    };
    // The same cutter again (posts repeat CUTTER/ per operation) changes
    // nothing; another one is a tool change: the passes after it are cut
    // with it, and a tool already defined keeps its number.
    if (tool_ > 0 && same(path_.defined_tools[static_cast<std::size_t>(tool_ - 1)].tool)) return;
    if (!path_.tool) {
      path_.tool = tool;
      path_.tool_line = s.line;
    }
    int number = 0;
    for (std::size_t k = 0; k < path_.defined_tools.size() && number == 0; ++k)
      if (same(path_.defined_tools[k].tool)) number = static_cast<int>(k + 1);
    if (number == 0) {
      path_.defined_tools.push_back({tool, s.line});
      number = static_cast<int>(path_.defined_tools.size());
    }
    if (tool_ > 0) {
      // The spindle goes to the change position: the pass ends, and where
      // the new tool is stays unknown until FROM/ or a RAPID GOTO/ says so.
      close_pass();
      RapidMove change;
      change.line = s.line;
      change.tool = tool_;
      path_.rapids.push_back(change);
      known_ = false;
    }
    tool_ = number;
    path_.tool_changes.push_back({s.line, number});
  }

  void cutter(const AptStatement& s) {
    const std::vector<double> v = numbers(s, name_);
    if (v.size() != 1 && v.size() != 2 && v.size() != 7)
      fail_line(name_, s.line, "CUTTER/ takes d, d,r or d,r,e,f,a,b,h (found " + std::to_string(v.size()) + " values)");
    const double d = v[0];
    const double r = v.size() >= 2 ? v[1] : 0.0;
    if (v.size() == 7) {
      // A cylindrical end mill: the corner centre sits d/2 - r from the axis
      // and r above the tip, with no taper (a = 0) and no flank angle (b = 0).
      const double tol = kToolTolerance / scale_;
      if (std::abs(v[2] - (d / 2 - r)) > tol || std::abs(v[3] - r) > tol || std::abs(v[4]) > kAxisTolerance ||
          std::abs(v[5]) > kAxisTolerance)
        fail_line(name_, s.line, "CUTTER/ is not a cylindrical ball, flat or bull end mill (e must be d/2 - r, f = r, "
                                 "a = b = 0): tapered and other cutters are not supported");
      if (v[6] < 0) fail_line(name_, s.line, "CUTTER/: the height h must not be negative");
    }
    define_tool(s, d, r);
  }

  // NX: TLDATA/MILL,d,r,length,taper angle,tip angle.
  void tldata(const AptStatement& s) {
    if (s.params.empty() || s.params[0] != "MILL")
      fail_line(name_, s.line, "TLDATA/ is read for MILL tools only");
    const std::vector<double> v = numbers(s, name_, 1);
    if (v.size() < 2) fail_line(name_, s.line, "TLDATA/MILL takes d,r[,length,taper,tip angle]");
    if ((v.size() > 3 && std::abs(v[3]) > kAxisTolerance) || (v.size() > 4 && std::abs(v[4]) > kAxisTolerance))
      fail_line(name_, s.line, "TLDATA/MILL with a taper or tip angle: tapered cutters are not supported");
    define_tool(s, v[0], v[1]);
  }

  // NX's machine coordinate system: origin, x axis, y axis. Only the part
  // frame itself is read; another one would move the whole path.
  void msys(const AptStatement& s) {
    const std::vector<double> v = numbers(s, name_);
    static const double kIdentity[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    bool identity = v.size() == 9;
    for (std::size_t k = 0; identity && k < 9; ++k)
      if (std::abs(v[k] - kIdentity[k]) > kAxisTolerance) identity = false;
    if (!identity)
      fail_line(name_, s.line, "MSYS/ other than the part frame (0,0,0,1,0,0,0,1,0) is not supported: the path "
                               "would have to be moved into the part frame");
    ignore(s);
  }

  std::string name_;
  Toolpath path_;
  ArcTolerances arc_tolerances_;
  double scale_ = 1;
  double feed_ = 0;
  bool rapid_next_ = false;
  bool known_ = false;
  Eigen::Vector3d position_ = Eigen::Vector3d::Zero();
  ToolpathPass current_;
  int tool_ = 0;  // number of the cutter in effect (Toolpath::defined_tools), 0 before the first
  long points_ = 0;
  std::optional<PendingCircle> circle_;
  std::optional<Eigen::Vector3d> indirv_;
  int indirv_line_ = 0;
};

}  // namespace

Toolpath parse_apt(const std::string& text, const std::string& name, const ToolpathReadOptions& options) {
  AptReader reader(name, options);
  return reader.read(text);
}

ToolSpec tool_for_path(const std::optional<ToolSpec>& given, const std::string& given_source, const Toolpath& path) {
  const std::string defined_at = path.source + ":" + std::to_string(path.tool_line);
  if (!given) {
    if (!path.tool)
      throw InputError(path.source + ": the tool path defines no cutter (APT CUTTER/): give the tool (--tool)");
    return *path.tool;
  }
  if (path.tool && (std::abs(given->diameter - path.tool->diameter) > kToolTolerance ||
                    std::abs(given->corner_radius - path.tool->corner_radius) > kToolTolerance))
    throw InputError(given_source + ": the tool (" + to_string(given->type) + ", diameter " +
                     mm_text(given->diameter) + ", corner radius " + mm_text(given->corner_radius) +
                     ") is not the cutter " + defined_at + " defines (" + to_string(path.tool->type) + ", diameter " +
                     mm_text(path.tool->diameter) + ", corner radius " + mm_text(path.tool->corner_radius) + ")");
  return *given;
}

}  // namespace furrow
