#pragma once
// What the QIF 3.0 schema cannot check (qif_schema.hpp validates the rest):
// every list's `n` equals its number of children, every id lies in
// 1..idMax and idMax is the largest, every *Id reference names an element
// of the document (the XSD's keyrefs cover only some of them), and a
// MeasuredPointSet's count matches its Points.
#include <doctest/doctest.h>

#include <cstdlib>
#include <map>
#include <pugixml.hpp>
#include <sstream>
#include <string>
#include <vector>

namespace furrow::test {

inline std::vector<pugi::xml_node> element_children(pugi::xml_node n) {
  std::vector<pugi::xml_node> out;
  for (pugi::xml_node c = n.first_child(); c; c = c.next_sibling())
    if (c.type() == pugi::node_element) out.push_back(c);
  return out;
}

// References whose value is a QIF id (not a QPId, a UUID).
inline bool is_reference(const std::string& name) {
  if (name == "Id") return true;
  if (name.size() < 3 || name.compare(name.size() - 2, 2, "Id") != 0) return false;
  return name.find("QPId") == std::string::npos;
}

// Every departure, one line each (empty: none).
struct QifIdsAndCounts {
  std::vector<std::string> problems;
  std::size_t references = 0;  // references resolved
};

inline QifIdsAndCounts qif_ids_and_counts(const std::string& text) {
  QifIdsAndCounts out;
  auto& problems = out.problems;
  pugi::xml_document doc;
  const pugi::xml_parse_result parsed = doc.load_string(text.c_str());
  if (!parsed) return {{std::string("not XML: ") + parsed.description()}, 0};
  const pugi::xml_node root = doc.document_element();
  const unsigned long id_max = std::strtoul(root.attribute("idMax").value(), nullptr, 10);
  std::map<unsigned long, std::string> ids;  // id -> element name
  std::vector<pugi::xml_node> references;
  std::vector<pugi::xml_node> stack = {root};
  while (!stack.empty()) {
    const pugi::xml_node n = stack.back();
    stack.pop_back();
    const std::string name = n.name();
    const std::vector<pugi::xml_node> kids = element_children(n);
    if (const pugi::xml_attribute id = n.attribute("id")) {
      const unsigned long v = std::strtoul(id.value(), nullptr, 10);
      if (v < 1 || v > id_max) problems.push_back(name + ": id " + id.value() + " outside 1..idMax");
      if (!ids.emplace(v, name).second) problems.push_back(name + ": duplicate id " + id.value());
    }
    if (const pugi::xml_attribute count = n.attribute("n"))
      if (std::strtoul(count.value(), nullptr, 10) != kids.size())
        problems.push_back(name + ": n=" + count.value() + " but " + std::to_string(kids.size()) + " children");
    if (is_reference(name) && kids.empty()) references.push_back(n);
    if (name == "MeasuredPointSet") {
      std::istringstream points(n.child("Points").child_value());
      double v;
      int values = 0;
      while (points >> v) ++values;
      if (values != 3 * n.attribute("count").as_int()) problems.push_back("MeasuredPointSet: count differs");
    }
    for (auto k = kids.rbegin(); k != kids.rend(); ++k) stack.push_back(*k);
  }
  if (ids.empty() || ids.rbegin()->first != id_max) problems.push_back("idMax is not the largest id");
  for (const pugi::xml_node r : references)
    if (ids.count(std::strtoul(r.child_value(), nullptr, 10)) != 1)
      problems.push_back(std::string(r.name()) + " " + r.child_value() + " names no element");
    else
      ++out.references;
  return out;
}

// For tests: CHECKs that there is no problem (printing them) and returns the
// number of references resolved, so that a test can require that the
// document had some to check.
inline std::size_t check_qif_ids_and_counts(const std::string& text) {
  const QifIdsAndCounts s = qif_ids_and_counts(text);
  std::string all;
  for (const std::string& p : s.problems) all += p + "\n";
  CHECK_MESSAGE(s.problems.empty(), all);
  return s.references;
}

}  // namespace furrow::test
