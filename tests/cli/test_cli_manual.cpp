// The man page and the bash completion are written from the command table
// (`furrow help --man`, `furrow help --completion`); the oracle here is what
// each command's own --help prints, read back through the CLI.
#include <doctest/doctest.h>

#include <regex>
#include <set>
#include <string>
#include <vector>

#include "support/run_cli.hpp"

using namespace furrow::test;

namespace {

std::vector<std::string> command_names() {
  const CliResult help = run_furrow({"help"});
  REQUIRE(help.status == 0);
  std::vector<std::string> names;
  static const std::regex line("\n  ([a-z][a-z-]*) ");
  for (auto it = std::sregex_iterator(help.out.begin(), help.out.end(), line); it != std::sregex_iterator(); ++it)
    names.push_back((*it)[1]);
  return names;
}

std::set<std::string> options_of(const std::string& text) {
  std::set<std::string> out;
  static const std::regex option("--[a-z][a-z0-9-]*");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), option); it != std::sregex_iterator(); ++it)
    out.insert(it->str());
  return out;
}

}  // namespace

TEST_CASE("the man page and the completion carry every command and every option its --help shows") {
  const std::vector<std::string> names = command_names();
  REQUIRE(names.size() >= 10);
  const CliResult man = run_furrow({"help", "--man"});
  const CliResult completion = run_furrow({"help", "--completion"});
  REQUIRE(man.status == 0);
  REQUIRE(completion.status == 0);
  std::size_t checked = 0;
  for (const std::string& name : names) {
    CAPTURE(name);
    CHECK(man.out.find(".SS " + name + "\n") != std::string::npos);
    const CliResult help = run_furrow({name, "--help"});
    REQUIRE(help.status == 0);
    const std::set<std::string> options = options_of(help.out);
    checked += options.size();
    // troff escapes every '-' of the page's text as "\-".
    for (const std::string& option : options) {
      CAPTURE(option);
      std::string troff;
      for (char c : option) troff += c == '-' ? std::string("\\-") : std::string(1, c);
      CHECK(man.out.find(troff) != std::string::npos);
      // A whole word of a compgen -W "..." list: --out must not pass by --output.
      const std::regex word("[\" ]" + option + "[\" ]");
      CHECK(std::regex_search(completion.out, word));
    }
  }
  CHECK(checked > 50);  // the commands' options were really read
  // The environment the program reads is documented.
  CHECK(man.out.find(".SH ENVIRONMENT") != std::string::npos);
  CHECK(man.out.find("FURROW_CAD_MODULE") != std::string::npos);
}
