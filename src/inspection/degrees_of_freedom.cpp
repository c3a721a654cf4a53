#include "inspection/degrees_of_freedom.hpp"

#include <sstream>

#include "base/error.hpp"

namespace furrow {

const char* dof_name(int index) {
  static const char* names[6] = {"rx", "ry", "rz", "tx", "ty", "tz"};
  return names[index];
}

bool DegreesOfFreedom::all_free() const { return count() == 6; }

int DegreesOfFreedom::count() const {
  int n = 0;
  for (bool f : free) n += f;
  return n;
}

DegreesOfFreedom DegreesOfFreedom::parse(const std::string& text, const std::string& where) {
  DegreesOfFreedom d;
  if (text == "all") return d;
  if (text == "translation") {
    d.free = {false, false, false, true, true, true};
    return d;
  }
  if (text == "rotation") {
    d.free = {true, true, true, false, false, false};
    return d;
  }
  d.free.fill(false);
  std::istringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    int found = -1;
    for (int k = 0; k < 6; ++k)
      if (item == dof_name(k)) found = k;
    if (found < 0)
      throw InputError(where + ": \"" + item +
                       "\" is not a degree of freedom (all, translation, rotation, or a list "
                       "of rx, ry, rz, tx, ty, tz)");
    if (d.free[found]) throw InputError(where + ": \"" + item + "\" is listed twice");
    d.free[found] = true;
  }
  if (d.count() == 0) throw InputError(where + ": no degree of freedom left to fit");
  return d;
}

std::string DegreesOfFreedom::to_string() const {
  if (all_free()) return "all";
  if (free == std::array<bool, 6>{false, false, false, true, true, true}) return "translation";
  if (free == std::array<bool, 6>{true, true, true, false, false, false}) return "rotation";
  std::string out;
  for (int k = 0; k < 6; ++k)
    if (free[k]) out += (out.empty() ? "" : ",") + std::string(dof_name(k));
  return out;
}

}  // namespace furrow
