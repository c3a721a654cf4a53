// A Furrow plan answered by an I++ DME server in every layout a session
// comes in (NIST .res, plain, client log, server log; CR LF, LF, CR CR LF)
// reads back to the same points bit for bit, with the PtMeas targets as
// nominals; an error answer is a point not measured, never a pass; the
// frame the program sets is honoured; and the answers' ER() compensates the
// ball centres exactly as the probe diameter does for CSV centres, checked
// against an analytic sphere and bore (oracle: their known radii).
#include <doctest/doctest.h>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "base/error.hpp"
#include "inspection/fixed_alignment.hpp"
#include "io/cmm/ippdme_response_log.hpp"
#include "io/cmm/ippdme_session.hpp"
#include "io/cmm/ippdme_writer.hpp"
#include "io/cmm/measurement_file.hpp"
#include "cad_part_fixture.hpp"
#include "program_fixtures.hpp"
#include "support/run_cli.hpp"

using namespace furrow;

namespace {

std::string num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.15g", v);
  return buf;
}

// The answer of a PtMeas: its target moved by `radius` along its direction
// plus a few micrometres that differ per point, as X(), Y(), Z(), IJK(), ER().
struct Answer {
  std::string tag;
  std::string data;  // without the tag
};

std::vector<Answer> answers_for(const IppdmeSession& s, double radius) {
  std::vector<Answer> out;
  int k = 0;
  for (const IppdmePtMeas& p : s.ptmeas) {
    const Eigen::Vector3d c = *p.target + (radius + 0.001 * ++k) * *p.ijk;
    out.push_back({p.tag, "X(" + num(c.x()) + "), Y(" + num(c.y()) + "), Z(" + num(c.z()) + "), IJK(" +
                              num(p.ijk->x()) + ", " + num(p.ijk->y()) + ", " + num(p.ijk->z()) + "), ER(" +
                              num(radius) + ")"});
  }
  return out;
}

// The program's commands in order, each answered & [#] %.
struct Exchange {
  std::string command;                  // "TTTTT Command(...)"
  std::vector<std::string> responses;  // "TTTTT &" ...
};

std::vector<Exchange> exchanges(const std::string& program, const std::vector<Answer>& answers,
                                const std::string& error_tag = "") {
  std::vector<Exchange> out;
  std::size_t next = 0;
  std::size_t start = 0;
  while (start < program.size()) {
    std::size_t end = program.find("\r\n", start);
    const std::string line = program.substr(start, end - start);
    start = end + 2;
    if (line.size() < 7 || line[5] != ' ') continue;
    const std::string tag = line.substr(0, 5);
    Exchange e{line, {tag + " &"}};
    if (line.compare(6, 7, "PtMeas(") == 0) {
      if (tag == error_tag) e.responses.push_back(tag + " ! Error(2, 1006, \"PtMeas\", \"Surface not found\")");
      else e.responses.push_back(tag + " # " + answers.at(next).data);
      ++next;
    }
    e.responses.push_back(tag + " %");
    out.push_back(e);
  }
  return out;
}

enum class Layout { nist_res, plain, client_log, server_log };

std::string layout_text(const std::vector<Exchange>& ex, Layout layout, const std::string& eol) {
  std::string out;
  int second = 0;
  auto stamp = [&] {
    char buf[32];
    std::snprintf(buf, sizeof buf, "04:08:18_%02d:%02d:%02d ", (second / 3600) % 24, (second / 60) % 60, second % 60);
    ++second;
    return std::string(buf);
  };
  // Logs as NIST's are: CR CR LF with CR LF between entries; a LF log the same with LF.
  const std::string log_eol = eol == "\r\n" ? "\r\r\n\r\n" : "\n\n";
  if (layout == Layout::client_log || layout == Layout::server_log)
    out += stamp() + "*********** Starting DME file: x.prg **********" + log_eol;
  for (const Exchange& e : ex) {
    switch (layout) {
      case Layout::nist_res:
        for (const std::string& r : e.responses) out += r + eol + "\\\\" + eol;
        break;
      case Layout::plain:
        for (const std::string& r : e.responses) out += r + eol;
        break;
      case Layout::client_log:
        out += stamp() + "Sent: " + e.command + log_eol;
        for (const std::string& r : e.responses) out += stamp() + "Received: " + r + log_eol;
        break;
      case Layout::server_log:
        out += stamp() + "received: " + e.command + log_eol;
        for (const std::string& r : e.responses) out += stamp() + "Sent: " + r + log_eol;
        break;
    }
  }
  if (layout == Layout::nist_res) out += ":" + eol + ":" + eol;
  if (layout == Layout::client_log || layout == Layout::server_log)
    out += stamp() + "Final Tag: 00042" + log_eol + stamp() + "Session completed" + log_eol;
  return out;
}

MeasurementSet read(const std::string& text, const IppdmeSession* program) {
  MeasurementSet set;
  parse_ippdme_response_log(text, "run.log", program, "t.prg", set);
  return set;
}

}  // namespace

TEST_CASE("a Furrow plan answered in every layout and line end reads back to the same points bit for bit") {
  const std::string prg = ippdme_program_text(test::tiny_program());
  const IppdmeSession session = parse_ippdme_session(prg, "t.prg");
  REQUIRE(session.ptmeas.size() == 3);
  const std::vector<Answer> answers = answers_for(session, 1);
  const std::vector<Exchange> ex = exchanges(prg, answers);
  for (const std::string eol : {"\r\n", "\n"})
    for (Layout layout : {Layout::nist_res, Layout::plain, Layout::client_log, Layout::server_log}) {
      CAPTURE(static_cast<int>(layout));
      CAPTURE(eol.size());
      const std::string text = layout_text(ex, layout, eol);
      CHECK(is_ippdme_response_log(text));
      // Plain and .res need the program to know their PtMeas; the logs carry it.
      const bool logs = layout == Layout::client_log || layout == Layout::server_log;
      for (const IppdmeSession* program : {&session, logs ? nullptr : &session}) {
        const MeasurementSet set = read(text, program);
        REQUIRE(set.points.size() == 3);
        CHECK(set.not_measured.empty());
        for (std::size_t k = 0; k < 3; ++k) {
          const MeasuredPoint& p = set.points[k];
          const IppdmePtMeas& m = session.ptmeas[k];
          CHECK(p.id == m.tag);
          // Bit for bit: the numbers as the answer wrote them.
          const Eigen::Vector3d c = *m.target + (1 + 0.001 * (k + 1)) * *m.ijk;
          CHECK(p.xyz == Eigen::Vector3d(std::strtod(num(c.x()).c_str(), nullptr), std::strtod(num(c.y()).c_str(), nullptr),
                                         std::strtod(num(c.z()).c_str(), nullptr)));
          REQUIRE(p.nominal);
          CHECK(*p.nominal == *m.target);
          CHECK(*p.effective_radius == 1);
        }
      }
    }
  // The same through parse_measurements, which detects the layout by content
  // and compensates by ER: centres of a 1 mm ball.
  MeasurementReadOptions o;
  const MeasurementSet set = parse_measurements(layout_text(ex, Layout::client_log, "\r\n"), "s.txt",
                                                measurement_format_from_path("s.txt", layout_text(ex, Layout::client_log, "\r\n")), o);
  CHECK(set.kind == ProbePointKind::probe_centre);
  CHECK(set.probe_radius == 1);
}

TEST_CASE("a PtMeas answered by an error is a point not measured, with the server's text, never a point") {
  const std::string prg = ippdme_program_text(test::tiny_program());
  const IppdmeSession session = parse_ippdme_session(prg, "t.prg");
  const std::string bad = session.ptmeas[1].tag;
  const std::vector<Exchange> ex = exchanges(prg, answers_for(session, 1), bad);
  for (Layout layout : {Layout::nist_res, Layout::plain, Layout::client_log, Layout::server_log}) {
    const MeasurementSet set = read(layout_text(ex, layout, "\r\n"), &session);
    REQUIRE(set.points.size() == 2);
    REQUIRE(set.not_measured.size() == 1);
    CHECK(set.not_measured[0].id == bad);
    CHECK(set.not_measured[0].reason == "Error(2, 1006, \"PtMeas\", \"Surface not found\")");
    CHECK(*set.not_measured[0].nominal == *session.ptmeas[1].target);
  }
  // A PtMeas of the program with no answer at all: not measured too.
  std::vector<Exchange> cut = exchanges(prg, answers_for(session, 1));
  cut.erase(cut.end() - 3, cut.end());  // the last PtMeas, its GoTo up and EndSession unanswered
  const MeasurementSet set = read(layout_text(cut, Layout::plain, "\n"), &session);
  CHECK(set.points.size() == 2);
  REQUIRE(set.not_measured.size() == 1);
  CHECK(set.not_measured[0].id == session.ptmeas[2].tag);
}

TEST_CASE("answers to other commands and events are not points, and a line that is not I++ DME names its line") {
  const std::string log =
      "00001 &\r\n00001 # GetMachineClass(\"CartCMM\")\r\n00001 %\r\n"
      "00002 &\r\n00002 # \"Probe1\"\r\n00002 # \"Probe2\"\r\n00002 %\r\n"
      "00003 &\r\n00003 # Tool.PtMeasPar.Speed(1)\r\n00003 %\r\n"
      "E0001 &\r\nE0001 # X(1), Y(2), Z(3)\r\nE0001 # R(0),X(1),Y(2),Z(3),Tool.A(4)\r\n"
      "00004 &\r\n00004 # X(1), Y(2), Z(3), IJK(0, 0, 2), ER(0.5)\r\n00004 %\r\n";
  const MeasurementSet set = read(log, nullptr);
  REQUIRE(set.points.size() == 1);
  CHECK(set.points[0].id == "00004");
  CHECK(*set.points[0].ijk == Eigen::Vector3d(0, 0, 1));
  MeasurementSet bad;
  try {
    parse_ippdme_response_log("00001 &\nG01 X1 Y2\n", "run.log", nullptr, "", bad);
    FAIL("accepted G-code");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()) == "run.log:2: not an I++ DME response or command: \"G01 X1 Y2\"");
  }
  // A very long line costs linear time and no stack (no std::regex).
  MeasurementSet longer;
  CHECK_THROWS_AS(parse_ippdme_response_log("00001 # X(" + std::string(300000, '(') + "\n", "run.log", nullptr, "", longer),
                  InputError);
}

TEST_CASE("a program from another client: every command passed over, SetCsyTransformation honoured") {
  // A program in MachineCsy, then PartCsy placed 10 mm up and turned 90
  // degrees about z (NIST's Euler angles Theta 0, Psi 90, Phi 0).
  const std::string prg =
      "00001 StartSession()\r\n00002 GetMachineClass()\r\n00003 EnumTools()\r\n00004 Home()\r\n"
      "00005 ChangeTool(\"Probe1\")\r\n00006 OnPtMeasReport(X(), Y(), Z(), IJK(), ER())\r\n"
      "00007 SetCsyTransformation(PartCsy, 0, 0, 10, 0, 90, 0)\r\n00008 PtMeas(X(1), Y(0), Z(0), IJK(1, 0, 0))\r\n"
      "00009 SetCoordSystem(PartCsy)\r\n"
      "00010 PtMeas(X(0), Y(1), Z(0), IJK(0, 1, 0))\r\n00011 EndSession()\r\n";
  const IppdmeSession s = parse_ippdme_session(prg, "other.prg");
  REQUIRE(s.ptmeas.size() == 2);
  const std::string log = "00008 # X(2), Y(0), Z(0), IJK(1, 0, 0), ER(1)\n00010 # X(0), Y(2), Z(0), IJK(0, 1, 0), ER(1)\n";
  const MeasurementSet set = read(log, &s);
  REQUIRE(set.points.size() == 2);
  // The MachineCsy point in PartCsy: R(psi 90) (2, 0, 0) + (0, 0, 10), R from NIST's world model:
  // row 1 (c2 c3 - c1 s2 s3, s2 c3 + c1 c2 s3, s1 s3) = (0, 1, 0): x_part = y_machine.
  const Eigen::Isometry3d t = ippdme_csy_transformation(0, 0, 10, 0, 90, 0);
  CHECK((t.linear() * Eigen::Vector3d(1, 0, 0) - Eigen::Vector3d(0, -1, 0)).norm() < 1e-15);
  CHECK((set.points[0].xyz - Eigen::Vector3d(0, -2, 10)).norm() < 1e-12);
  CHECK((*set.points[0].nominal - Eigen::Vector3d(0, -1, 10)).norm() < 1e-12);
  CHECK((*set.points[0].ijk - Eigen::Vector3d(0, -1, 0)).norm() < 1e-15);
  CHECK(set.points[1].xyz == Eigen::Vector3d(0, 2, 0));  // PartCsy as answered
  // A point in MoveableMachineCsy is refused.
  const IppdmeSession moveable = parse_ippdme_session(
      "00001 StartSession()\n00002 SetCoordSystem(MoveableMachineCsy)\n00003 PtMeas(X(1), Y(0), Z(0))\n", "m.prg");
  MeasurementSet refused;
  CHECK_THROWS_WITH_AS(parse_ippdme_response_log("00003 # X(1), Y(0), Z(0)\n", "run.log", &moveable, "m.prg", refused),
                       doctest::Contains("MoveableMachineCsy"), InputError);
  // A line of another language in a command file names its line.
  CHECK_THROWS_WITH_AS(parse_ippdme_session("00001 StartSession()\nGOTO/1,2,3\n", "x.prg"),
                       "x.prg:2: not an I++ DME command (BAD TAG CHARACTER): \"GOTO/1,2,3\"",
                       InputError);
}

namespace {

// In the CMM's frame (no fit), as `furrow compare --align cmm` evaluates:
// each point's deviation is its compensated distance to the part.
std::vector<double> deviations_cmm(const test::CadPart& part, const MeasurementSet& set) {
  const RegistrationResult r =
      evaluate_at_transform(*part.finder, set, Eigen::Isometry3d::Identity(), RegistrationOptions{}, "cmm");
  std::vector<double> d;
  for (const RegisteredPoint& p : r.points) d.push_back(p.deviation);
  return d;
}

std::string answer_line(int tag, const Eigen::Vector3d& c, const Eigen::Vector3d& n, std::optional<double> er) {
  char t[8];
  std::snprintf(t, sizeof t, "%05d", tag);
  return std::string(t) + " # X(" + num(c.x()) + "), Y(" + num(c.y()) + "), Z(" + num(c.z()) + "), IJK(" + num(n.x()) +
         ", " + num(n.y()) + ", " + num(n.z()) + ")" + (er ? ", ER(" + num(*er) + ")" : std::string()) + "\r\n";
}

}  // namespace

TEST_CASE("ER() compensates the answered ball centres along the surface normal: analytic sphere and bore") {
  constexpr double kSphere = 20, kBore = 8, kEr = 1.4985;  // an effective radius a little under the 1.5 mm ball
  const test::CadPart sphere(BRepPrimAPI_MakeSphere(gp_Pnt(0, 0, 0), kSphere).Shape(), "ipp-er-sphere");
  const TopoDS_Shape block = BRepPrimAPI_MakeBox(gp_Pnt(-30, -30, -20), 60, 60, 20).Shape();
  const TopoDS_Shape hole = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, -25), gp::DZ()), kBore, 30).Shape();
  const test::CadPart bore(BRepAlgoAPI_Cut(block, hole).Shape(), "ipp-er-bore");
  // Deviations planted per point, the centres where a ball of radius ER
  // touching the deviated surface has its centre.
  std::string on_sphere, in_bore, on_sphere_no_er;
  std::vector<double> planted;
  for (int k = 0; k < 8; ++k) {
    const double d = 0.004 * (k - 3);
    planted.push_back(d);
    const double a = 0.7 * k + 0.3, polar = 0.5 + 0.08 * k;
    const Eigen::Vector3d n(std::sin(polar) * std::cos(a), std::sin(polar) * std::sin(a), std::cos(polar));
    on_sphere += answer_line(k + 1, (kSphere + d + kEr) * n, n, kEr);
    on_sphere_no_er += answer_line(k + 1, (kSphere + d + kEr) * n, n, std::nullopt);
    // The bore's material normal points to the axis; material left (d > 0)
    // narrows the bore.
    const Eigen::Vector3d radial(std::cos(a), std::sin(a), 0);
    in_bore += answer_line(k + 1, (kBore - d - kEr) * radial + Eigen::Vector3d(0, 0, -10), -radial, kEr);
  }
  MeasurementReadOptions o;  // no probe diameter: ER gives it
  const MeasurementSet s = parse_measurements(on_sphere, "sphere.res", MeasurementFormat::ippdme_log, o);
  CHECK(s.kind == ProbePointKind::probe_centre);
  CHECK(s.probe_radius == kEr);
  const MeasurementSet b = parse_measurements(in_bore, "bore.res", MeasurementFormat::ippdme_log, o);
  // Without ER the given diameter does the same (as for CSV centres).
  MeasurementReadOptions with_diameter;
  with_diameter.probe_diameter = 2 * kEr;
  const MeasurementSet n = parse_measurements(on_sphere_no_er, "sphere.res", MeasurementFormat::ippdme_log, with_diameter);
  const std::vector<double> ds = deviations_cmm(sphere, s), db = deviations_cmm(bore, b), dn = deviations_cmm(sphere, n);
  REQUIRE(ds.size() == planted.size());
  REQUIRE(db.size() == planted.size());
  for (std::size_t k = 0; k < planted.size(); ++k) {
    CAPTURE(k);
    CHECK(std::abs(ds[k] - planted[k]) < 1e-6);
    CHECK(std::abs(db[k] - planted[k]) < 1e-6);
    CHECK(std::abs(dn[k] - planted[k]) < 1e-6);
  }
  // Answers with different ER cannot share one compensation; ER and a
  // contact-point claim contradict each other.
  CHECK_THROWS_WITH_AS(parse_measurements(answer_line(1, {0, 0, 21}, {0, 0, 1}, 1.0) + answer_line(2, {0, 0, 22}, {0, 0, 1}, 2.0),
                                          "mixed.res", MeasurementFormat::ippdme_log, o),
                       "mixed.res:2: ER(2) differs from ER(1) on line 1: one ball radius per measurement set", InputError);
  MeasurementReadOptions contact;
  contact.kind = ProbePointKind::contact;
  CHECK_THROWS_AS(parse_measurements(on_sphere, "sphere.res", MeasurementFormat::ippdme_log, contact), InputError);
}
