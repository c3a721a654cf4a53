#include "io/cmm/ippdme_session.hpp"

#include <cmath>
#include <cstdlib>
#include <unordered_map>

#include "base/error.hpp"
#include "base/json_fields.hpp"
#include "base/numbers.hpp"
#include "base/text_fields.hpp"
#include "io/cmm/measurement_fields.hpp"

namespace furrow {

namespace mf = measurement_fields;

const char* to_string(IppdmeCsy csy) {
  switch (csy) {
    case IppdmeCsy::machine: return "MachineCsy";
    case IppdmeCsy::moveable_machine: return "MoveableMachineCsy";
    case IppdmeCsy::multiple_arm: return "MultipleArmCsy";
    case IppdmeCsy::part: return "PartCsy";
  }
  return "?";
}

Eigen::Isometry3d ippdme_csy_transformation(double x0, double y0, double z0, double theta, double psi, double phi) {
  const double c1 = std::cos(radians(theta)), s1 = std::sin(radians(theta));
  const double c2 = std::cos(radians(psi)), s2 = std::sin(radians(psi));
  const double c3 = std::cos(radians(phi)), s3 = std::sin(radians(phi));
  Eigen::Matrix3d m;
  m << c2 * c3 - c1 * s2 * s3, s2 * c3 + c1 * c2 * s3, s1 * s3,  //
      -(c2 * s3) - c1 * s2 * c3, -(s2 * s3) + c1 * c2 * c3, s1 * c3,  //
      s1 * s2, -(s1 * c2), c1;
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = m;
  t.translation() = Eigen::Vector3d(x0, y0, z0);
  return t;
}

std::string advance_ippdme_frame(const IppdmeCommand& c, IppdmeFrame& frame) {
  if (c.name == "SetCoordSystem") {
    const std::string& s = c.arguments[0].text;
    if (c.arguments[0].kind != IppdmeItem::Kind::keyword || c.arguments[0].has_arguments)
      return "SetCoordSystem: BAD ARGUMENTS";
    if (s == "MachineCsy") frame.csy = IppdmeCsy::machine;
    else if (s == "MoveableMachineCsy") frame.csy = IppdmeCsy::moveable_machine;
    else if (s == "MultipleArmCsy") frame.csy = IppdmeCsy::multiple_arm;
    else if (s == "PartCsy") frame.csy = IppdmeCsy::part;
    else return "SetCoordSystem: " + quote_field(s) + " is not a coordinate system of the spec";
  } else if (c.name == "SetCsyTransformation") {
    const IppdmeItem& which = c.arguments[0];
    if (which.kind != IppdmeItem::Kind::keyword || which.has_arguments) return "SetCsyTransformation: BAD ARGUMENTS";
    if (which.text == "PartCsy") {
      double v[6];
      for (int k = 0; k < 6; ++k) v[k] = std::strtod(c.arguments[k + 1].text.c_str(), nullptr);
      frame.part = ippdme_csy_transformation(v[0], v[1], v[2], v[3], v[4], v[5]);
    } else if (which.text != "MachineCsy" && which.text != "MoveableMachineCsy" && which.text != "MultipleArmCsy" &&
               which.text != "JogDisplayCsy" && which.text != "JogMoveCsy" && which.text != "SensorCsy") {
      return "SetCsyTransformation: " + quote_field(which.text) + " is not a coordinate system of the spec";
    }
  }
  return "";
}

bool looks_like_ippdme_command(std::string_view line) {
  IppdmeCommand c;
  return line.size() > 6 && parse_ippdme_command(line, c).rfind("BAD COMMAND NAME", 0) != 0 &&
         (line[0] == 'E' || (line[0] >= '0' && line[0] <= '9')) && line[5] == ' ' &&
         line.find('(') != std::string_view::npos;
}

IppdmeSession parse_ippdme_session(std::string_view text, const std::string& name) {
  if (text.size() >= 3 && text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  IppdmeSession session;
  IppdmeFrame frame;
  std::unordered_map<std::string, int> uses;  // per tag, commands so far
  IppdmeCommand c;
  bool ended = false;  // after the first `:` line only `:` and blank lines
  mf::for_each_line(text, [&](int number, std::string_view line) {
    while (!line.empty() && line.back() == '\r') line.remove_suffix(1);  // CR CR LF
    if (line.size() > kMaxIppdmeSessionLine)
      mf::fail(name, number, "line longer than " + std::to_string(kMaxIppdmeSessionLine) + " characters");
    if (mf::trimmed(line).empty() || line == "\\\\") return;
    if (line == ":") {
      ended = true;
      return;
    }
    if (ended) mf::fail(name, number, "text after the closing `:` line");
    const std::string why = parse_ippdme_command(line, c);
    if (!why.empty())
      mf::fail(name, number, "not an I++ DME command (" + why + "): " + quote_field(std::string(line.substr(0, 200))));
    ++session.commands;
    if (c.event) return;  // event commands do not take the tags of the others
    const int use = ++uses[c.tag];
    const std::string frame_error = advance_ippdme_frame(c, frame);
    if (!frame_error.empty()) mf::fail(name, number, frame_error);
    if (c.name != "PtMeas") return;
    IppdmePointItems items;
    const std::string item_error = ippdme_point_items(c.arguments, items);
    if (!item_error.empty()) mf::fail(name, number, "PtMeas: " + item_error);
    IppdmePtMeas p;
    p.tag = c.tag;
    p.use = use;
    p.line = number;
    if (items.has_xyz()) p.target = Eigen::Vector3d(*items.x, *items.y, *items.z);
    if (items.ijk && items.ijk->norm() > 0) p.ijk = items.ijk->normalized();
    p.frame = frame;
    session.ptmeas.push_back(std::move(p));
  });
  if (session.commands == 0) throw InputError(name + ": no I++ DME command in the file");
  return session;
}

IppdmeSession read_ippdme_session(const std::string& path) {
  const std::string text = json_fields::read_text(path);
  return parse_ippdme_session(text, path);
}

}  // namespace furrow
