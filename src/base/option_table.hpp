#pragma once
// OptionTable: the options of one stage, each described once (its job-file
// member, its command-line flag, the kind and bounds of its value, its help
// sentence), so that the command-line reader, the job-file reader and
// writer, `--help`, the man page and docs/options.md are all made from the
// same description and cannot drift apart (docs/architecture.md "Options").
//
// A value travels as JSON whichever way it came: the command line turns
// `--probe-diameter 2.5` into the number 2.5 (by the option's kind) and a
// job file holds it as written, so one read function checks both, and its
// error names where the value came from ("furrow plan: --probe-diameter: must
// be positive, got -1" or "job.json: plan.probe_diameter: must be positive,
// got -1"). Every read throws InputError; nothing is clamped silently.
//
// The default shown in help is what `write` gives for a default-constructed
// options struct, so help text never states a default the code does not use.
//
// This header exposes nlohmann::json; include it only from .cpp files.
#include <functional>
#include <initializer_list>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "base/json_fields.hpp"

namespace furrow {

enum class OptionKind {
  number,   // a finite number
  integer,  // a whole number
  text,     // a word (a name, a choice, a list such as "rx,ry,tz")
  toggle,   // true/false; on the command line a flag that sets the non-default
  numbers,  // a fixed count of numbers: "a,b,c" on the command line, [a, b, c] in a job
};

// What a number may be; checked by both readers.
enum class Bound { any, positive, non_negative, fraction /* [0, 1] */ };

template <class Options>
struct OptionSpec {
  std::string key;            // job-file member; the flag is "--" + key, '_' -> '-'
  OptionKind kind = OptionKind::number;
  std::string value_name;     // in help: "MM", "N", "DEG" (empty for a toggle)
  std::string help;           // one or two sentences, without the default; for a
                              // toggle, what its command-line flag does
  std::string default_text;   // set when the default is a rule ("probe radius + 1");
                              // empty: the written default of Options{}
  std::vector<std::string> choices;  // the words a choice takes, for help and tests
  std::string example;        // a valid non-default value (command-line text) for
                              // the tests; empty: made from the default
  std::size_t count = 0;      // how many numbers (OptionKind::numbers)
  std::string former_flag;    // an older command-line name still taken ("--outliers")
  nlohmann::json schema;      // the value's JSON Schema (without null, which every
                              // option takes for "the default")
  std::function<void(const nlohmann::json& value, const std::string& where, Options&)> read;
  std::function<nlohmann::json(const Options&)> write;
};

template <class Options>
using OptionTable = std::vector<OptionSpec<Options>>;

// The command-line flag of a job-file member: "max_tilt" -> "max-tilt".
std::string option_flag(const std::string& key);

// One option as help and docs show it, without its Options type.
struct OptionDoc {
  std::string flag;        // "--max-tilt", or "--no-outlier-rejection" for a toggle on by default
  std::string key;         // "max_tilt"
  OptionKind kind = OptionKind::number;
  std::string value_name;
  std::string help;
  std::string default_text;  // "75", "none", "probe radius + 1"
  std::size_t count = 0;     // numbers in a list option
  std::string former_flag;   // older command-line name still taken, or empty
  nlohmann::json schema;     // JSON Schema of the job-file member, null allowed
};

// `schema` with null allowed (an absent or null member keeps the default)
// and `help` as its description.
nlohmann::json nullable_schema(const nlohmann::json& schema, const std::string& help);
// The JSON Schema of a number within `bound`.
nlohmann::json number_schema(Bound bound);
// The JSON Schema (draft 2020-12) of a section holding the members of
// `docs` and `extra` (name -> schema), refusing any other member.
nlohmann::json section_schema(const std::vector<OptionDoc>& docs, const nlohmann::json& extra = nlohmann::json::object());

// A default as help states it: numbers in their shortest text ("2", not "2.0").
std::string default_value_text(const nlohmann::json& value);

template <class Options>
std::vector<OptionDoc> describe(const OptionTable<Options>& table) {
  const Options defaults{};
  std::vector<OptionDoc> docs;
  for (const OptionSpec<Options>& s : table) {
    const nlohmann::json d = s.write(defaults);
    OptionDoc doc{option_flag(s.key), s.key,   s.kind,        s.value_name,
                  s.help,              s.default_text, s.count, s.former_flag,
                  nullable_schema(s.schema, s.help)};
    if (s.kind == OptionKind::toggle && d.is_boolean() && d.get<bool>()) doc.flag = "--no-" + doc.flag.substr(2);
    if (doc.default_text.empty()) {
      if (d.is_null())
        doc.default_text = "none";
      else if (d.is_string())
        doc.default_text = d.get<std::string>().empty() ? "none" : d.get<std::string>();
      else
        doc.default_text = default_value_text(d);
    }
    docs.push_back(std::move(doc));
  }
  return docs;
}

// The options' lines of a usage text: "  --max-tilt DEG       largest angle
// ... (default 75)", the help wrapped at 80 columns under column 23.
std::string option_help_lines(const std::vector<OptionDoc>& docs);
// A Markdown table of the options of one stage (docs/options.md).
std::string option_markdown_table(const std::vector<OptionDoc>& docs);

// Reads each member of `table` that `find(key)` yields into `options`;
// `path(key)` names it in errors. Used with a JsonCursor by the job reader.
template <class Options, class Cursor>
void read_option_members(const Cursor& cursor, const OptionTable<Options>& table, Options& options) {
  for (const OptionSpec<Options>& s : table)
    if (const nlohmann::json* v = cursor.find(s.key)) s.read(*v, cursor.path(s.key), options);
}

// Every option of `table` as a JSON object (the job-file writer).
template <class Options>
nlohmann::json option_members(const OptionTable<Options>& table, const Options& options) {
  nlohmann::json out = nlohmann::json::object();
  for (const OptionSpec<Options>& s : table) out[s.key] = s.write(options);
  return out;
}

// A table built from a list of others (a command taking several stages' options).
template <class Options>
OptionTable<Options> only_options(const OptionTable<Options>& table, const std::vector<std::string>& keys) {
  OptionTable<Options> out;
  for (const std::string& k : keys)
    for (const OptionSpec<Options>& s : table)
      if (s.key == k) out.push_back(s);
  return out;
}

namespace option_detail {
double checked_number(const nlohmann::json& v, const std::string& where, Bound bound);
long checked_integer(const nlohmann::json& v, const std::string& where, long min_value);
std::string checked_text(const nlohmann::json& v, const std::string& where);
std::vector<double> checked_numbers(const nlohmann::json& v, const std::string& where, std::size_t count);
template <class T>
struct is_optional : std::false_type {};
template <class T>
struct is_optional<std::optional<T>> : std::true_type {};
}  // namespace option_detail

// The words of a choice, in the order given: `choice_names({A::x, A::y})`
// with the enum's to_string.
template <class E>
std::vector<std::string> choice_names(std::initializer_list<E> values) {
  std::vector<std::string> out;
  for (E v : values) out.push_back(to_string(v));
  return out;
}

// Builders. `get` is a generic lambda returning the member, e.g.
// `[](auto& o) -> auto& { return o.motion.move_speed; }`, so the same
// accessor serves the reader (Options&) and the writer (const Options&).

// A number into double or std::optional<double> (null when absent).
template <class Options, class Get>
OptionSpec<Options> number_option(std::string key, std::string value_name, std::string help, Get get,
                                  Bound bound = Bound::positive) {
  OptionSpec<Options> s;
  s.key = std::move(key);
  s.kind = OptionKind::number;
  s.value_name = std::move(value_name);
  s.help = std::move(help);
  s.schema = number_schema(bound);
  s.read = [get, bound](const nlohmann::json& v, const std::string& where, Options& o) {
    get(o) = option_detail::checked_number(v, where, bound);
  };
  s.write = [get](const Options& o) -> nlohmann::json {
    const auto& x = get(o);
    if constexpr (option_detail::is_optional<std::decay_t<decltype(x)>>::value)
      return x ? json_fields::finite(*x, "option") : nlohmann::json(nullptr);
    else
      return json_fields::finite(x, "option");
  };
  return s;
}

// A whole number >= min_value into an integer or std::optional of one.
template <class Options, class Get>
OptionSpec<Options> integer_option(std::string key, std::string value_name, std::string help, Get get,
                                   long min_value) {
  OptionSpec<Options> s;
  s.key = std::move(key);
  s.kind = OptionKind::integer;
  s.value_name = std::move(value_name);
  s.help = std::move(help);
  s.schema = {{"type", "integer"}, {"minimum", min_value}};
  s.read = [get, min_value](const nlohmann::json& v, const std::string& where, Options& o) {
    auto& target = get(o);
    using T = std::decay_t<decltype(target)>;
    const long x = option_detail::checked_integer(v, where, min_value);
    if constexpr (option_detail::is_optional<T>::value)
      target = static_cast<typename T::value_type>(x);
    else
      target = static_cast<T>(x);
  };
  s.write = [get](const Options& o) -> nlohmann::json {
    const auto& x = get(o);
    if constexpr (option_detail::is_optional<std::decay_t<decltype(x)>>::value)
      return x ? nlohmann::json(*x) : nlohmann::json(nullptr);
    else
      return nlohmann::json(x);
  };
  return s;
}

// Free text into a std::string.
template <class Options, class Get>
OptionSpec<Options> text_option(std::string key, std::string value_name, std::string help, Get get) {
  OptionSpec<Options> s;
  s.key = std::move(key);
  s.kind = OptionKind::text;
  s.value_name = std::move(value_name);
  s.help = std::move(help);
  s.schema = {{"type", "string"}};
  s.read = [get](const nlohmann::json& v, const std::string& where, Options& o) {
    get(o) = option_detail::checked_text(v, where);
  };
  s.write = [get](const Options& o) -> nlohmann::json { return nlohmann::json(get(o)); };
  return s;
}

// A word parsed into a value: `parse(text, where)` throws InputError naming
// `where` for a word it does not take; `print(value)` writes it back.
template <class Options, class Get, class Parse, class Print>
OptionSpec<Options> parsed_option(std::string key, std::string value_name, std::string help, Get get, Parse parse,
                                  Print print, std::vector<std::string> choices = {}) {
  OptionSpec<Options> s;
  s.key = std::move(key);
  s.kind = OptionKind::text;
  s.value_name = std::move(value_name);
  s.help = std::move(help);
  s.choices = std::move(choices);
  s.schema = {{"type", "string"}};  // the parser may take more spellings than `choices`
  s.read = [get, parse](const nlohmann::json& v, const std::string& where, Options& o) {
    get(o) = parse(option_detail::checked_text(v, where), where);
  };
  s.write = [get, print](const Options& o) -> nlohmann::json { return nlohmann::json(print(get(o))); };
  return s;
}

// true/false into a bool; on the command line `--KEY` (or `--no-KEY` when
// the default is true) sets the other value.
template <class Options, class Get>
OptionSpec<Options> toggle_option(std::string key, std::string help, Get get) {
  OptionSpec<Options> s;
  s.key = std::move(key);
  s.kind = OptionKind::toggle;
  s.help = std::move(help);
  s.schema = {{"type", "boolean"}};
  s.read = [get](const nlohmann::json& v, const std::string& where, Options& o) {
    get(o) = json_fields::boolean(v, where);
  };
  s.write = [get](const Options& o) -> nlohmann::json { return nlohmann::json(static_cast<bool>(get(o))); };
  return s;
}

// `count` numbers, each finite, into whatever `set(values, where, options)`
// makes of them (it checks how they relate, e.g. a box's min below its
// max, and throws InputError naming `where`); `get(options)` gives them
// back for the writer, or none (written null).
template <class Options, class Set, class Get>
OptionSpec<Options> numbers_option(std::string key, std::string value_name, std::string help, std::size_t count,
                                   Set set, Get get) {
  OptionSpec<Options> s;
  s.key = std::move(key);
  s.kind = OptionKind::numbers;
  s.value_name = std::move(value_name);
  s.help = std::move(help);
  s.count = count;
  s.schema = {{"type", "array"}, {"items", {{"type", "number"}}}, {"minItems", count}, {"maxItems", count}};
  s.read = [set, count](const nlohmann::json& v, const std::string& where, Options& o) {
    set(option_detail::checked_numbers(v, where, count), where, o);
  };
  s.write = [get](const Options& o) -> nlohmann::json {
    const std::optional<std::vector<double>> values = get(o);
    if (!values) return nullptr;
    nlohmann::json out = nlohmann::json::array();
    for (double x : *values) out.push_back(json_fields::finite(x, "option"));
    return out;
  };
  return s;
}

// An older command-line name of the option, still taken on the command line
// (scripts written for it keep working) and named in help.
template <class Options>
OptionSpec<Options> formerly(OptionSpec<Options> s, std::string former_flag) {
  s.former_flag = std::move(former_flag);
  return s;
}

// States the default in words, where it is a rule rather than a value
// ("per face, from its curvature").
template <class Options>
OptionSpec<Options> default_is(OptionSpec<Options> s, std::string text) {
  s.default_text = std::move(text);
  return s;
}

// Replaces what the writer records (a resolved default such as the border
// the planner uses when none is given) and how help states the default.
template <class Options, class Write>
OptionSpec<Options> written_as(OptionSpec<Options> s, Write write, std::string default_text) {
  s.write = [write](const Options& o) -> nlohmann::json { return write(o); };
  s.default_text = std::move(default_text);
  return s;
}

}  // namespace furrow
