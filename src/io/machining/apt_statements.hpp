#pragma once
// APT CL text cut into statements (docs/formats.md "Tool paths", APT CL
// data): the lexical layer of io/machining/apt_reader.hpp, kept apart so the reader
// deals with meaning only.
//
// A statement is one line, or several when a line ends in `$` (the statement
// continues on the next line; the `$` is dropped). `$$` starts a comment that
// runs to the end of the line. Text statements (PPRINT, PARTNO, INSERT) are
// one line each, taken whole: their text may hold `$`, `/` and commas.
// A statement is then split into its major word (before `/`, upper case,
// blanks collapsed: "TOOL PATH"; "TLON,GOFWD" keeps its comma), and its
// parameters: the text after `/` cut at commas outside parentheses, each
// trimmed and in upper case; a parenthesised group stays one parameter
// ("(CIRCLE/1,2,3,4)").
//
// Failure: InputError "name:line: what" for a `$` continuation on the last
// line and for unbalanced parentheses.
#include <cstddef>
#include <string>
#include <vector>

namespace furrow {

// Where a parameter is written: its bytes [begin, end) in line `line`
// (1-based, counted without a byte-order mark and without the line's
// ending), trimmed as the parameter is. `line` 0: the parameter is empty or
// runs over a continuation, so it has no single place.
struct AptSpan {
  int line = 0;
  std::size_t begin = 0, end = 0;
};

struct AptStatement {
  int line = 0;                     // first line of the statement (1-based)
  int last_line = 0;                // last line (after `$` continuations)
  std::string major;                // "GOTO", "TLON,GOFWD", "PPRINT"; may be empty for a blank statement
  std::vector<std::string> params;  // after '/', upper case; text statements: none
  std::string text;                 // text statements: the words after the major word, as written
  bool has_slash = false;           // whether the statement has a '/'
  std::vector<AptSpan> spans;       // where each of params is written (writers that rewrite values)
};

std::vector<AptStatement> split_apt_statements(const std::string& text, const std::string& name);

// Splits `list` at commas outside parentheses, each part trimmed.
// Throws InputError "name:line: ..." for unbalanced parentheses.
std::vector<std::string> split_apt_params(const std::string& list, const std::string& name, int line);

}  // namespace furrow
