#pragma once
// The installed manual and shell completion, written from the same command
// table and usage texts that `furrow help COMMAND` prints, so that they
// cannot drift apart: `furrow help --man` (troff for man(1)) and
// `furrow help --completion` (a bash completion script). The build runs
// both and installs their output.
#include <ostream>
#include <string>
#include <vector>

#include "cli/commands.hpp"

namespace furrow::cli {

// Every option a usage text names ("--name"), in order of first mention.
std::vector<std::string> options_in_usage(const std::string& usage);

void write_man_page(std::ostream& out, const std::vector<const Command*>& commands);
// docs/options.md: every stage's options as Markdown tables
// (`furrow help --options`).
void write_options_reference(std::ostream& out);
void write_bash_completion(std::ostream& out, const std::vector<const Command*>& commands);

}  // namespace furrow::cli
