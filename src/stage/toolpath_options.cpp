#include "stage/toolpath_options.hpp"

namespace furrow {

namespace {

OptionTable<ToolpathGeneration> make_table() {
  using O = ToolpathGeneration;
  OptionTable<O> t;
  t.push_back(number_option<O>("tolerance", "MM", "largest machining error per step",
                               [](auto& o) -> auto& { return o.contacts.forward.tolerance; }));
  t.push_back(number_option<O>("scallop", "MM", "target scallop height between passes",
                               [](auto& o) -> auto& { return o.contacts.scallop; }));
  OptionSpec<O> direction = parsed_option<O>(
      "direction", "D",
      "u or v: iso-parametric passes (v or u fixed); plane:ANGLE: vertical sections at ANGLE degrees from +x",
      [](auto& o) -> auto& { return o.direction; }, parse_pass_direction,
      [](const PassDirectionSpec& d) { return to_string(d); });
  direction.example = "plane:30";
  t.push_back(direction);
  OptionSpec<O> rule = parsed_option<O>(
      "rule", "R",
      "exact: every step's largest error, from the swept cutter, equals the tolerance; chord: the chord "
      "deviation does; circular_arc: an osculating-circle estimate (for comparison; circular-arc is taken too)",
      [](auto& o) -> auto& { return o.contacts.forward.rule; }, parse_step_rule,
      [](StepRule r) { return std::string(to_string(r)); }, {"exact", "chord", "circular_arc"});
  rule.example = "circular-arc";
  t.push_back(rule);
  t.push_back(default_is(number_option<O>("max_step", "MM", "longest step along a pass (chord); 0: no limit",
                                          [](auto& o) -> auto& { return o.contacts.forward.max_step; },
                                          Bound::non_negative),
                         "0, no limit"));
  t.push_back(number_option<O>("clearance", "MM", "rapid height above the highest tip",
                               [](auto& o) -> auto& { return o.write.clearance; }));
  t.push_back(number_option<O>("feed", "MM/MIN", "feed rate written on the first cut",
                               [](auto& o) -> auto& { return o.write.feed; }));
  return t;
}

}  // namespace

const OptionTable<ToolpathGeneration>& toolpath_option_table() {
  static const OptionTable<ToolpathGeneration> table = make_table();
  return table;
}

}  // namespace furrow
