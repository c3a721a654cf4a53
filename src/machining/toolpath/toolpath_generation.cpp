#include "machining/toolpath/toolpath_generation.hpp"

#include "geometry/part.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <sstream>

#include "base/error.hpp"

namespace furrow {

Toolpath plan_tips(const ContactPlan& plan) {
  Toolpath path;
  path.kind = ToolpathKind::tool_tips;
  for (const PlannedPass& p : plan.passes) {
    ToolpathPass pass;
    for (const PlannedContact& q : p.points) {
      ToolpathPoint t;
      t.position = q.tip;
      pass.points.push_back(t);
    }
    path.passes.push_back(pass);
  }
  return path;
}

std::string plan_gcode(const ContactPlan& plan, const Cutter& cutter, const std::string& header,
                       const ToolpathWriteOptions& options) {
  double top = -std::numeric_limits<double>::infinity();
  for (const PlannedPass& p : plan.passes)
    for (const PlannedContact& q : p.points) top = std::max(top, q.tip.z());
  std::ostringstream h;
  h << header << "\ntool " << cutter.name() << " " << to_string(cutter.type()) << " diameter " << cutter.diameter()
    << " corner radius " << cutter.corner_radius() << " mm; positions are tool tips";
  return toolpath_to_gcode(plan_tips(plan), top + options.clearance, options.feed, h.str());
}

std::string plan_contact_csv(const Part& part, const ContactPlan& plan) {
  for (const Face& f : part.faces)
    if (f.name().find_first_of(",#\r\n") != std::string::npos || f.name().empty() ||
        f.name().find_first_not_of(" \t") != 0 || f.name().back() == ' ' || f.name().back() == '\t')
      throw InputError("toolpath: face name \"" + f.name() +
                       "\" cannot be written to the contact-point CSV (no commas, '#', line breaks or "
                       "surrounding blanks)");
  std::ostringstream out;
  out << "# contact points of a furrow tool path: pass, point [mm], unit outward normal, face, (u, v)\n";
  out << "pass,x,y,z,nx,ny,nz,face,u,v\n";
  char buf[320];
  for (std::size_t k = 0; k < plan.passes.size(); ++k)
    for (const PlannedContact& q : plan.passes[k].points) {
      const Eigen::Vector3d& p = q.at.point;
      const Eigen::Vector3d& n = q.at.normal;
      std::snprintf(buf, sizeof buf, "%zu,%.7f,%.7f,%.7f,%.12f,%.12f,%.12f,%s,%.15g,%.15g\n", k, p.x(), p.y(), p.z(),
                    n.x(), n.y(), n.z(), part.faces[q.at.face].name().c_str(), q.at.uv.x(), q.at.uv.y());
      out << buf;
    }
  return out.str();
}

}  // namespace furrow
