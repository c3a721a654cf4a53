// Every file of NIST's I++ DME 1.4 test suite (shared/standards/ipp-dme-1.4/
// nist-test-files) through the readers of any session (ippdme_session.hpp,
// ippdme_response_log.hpp): command files parse, or are refused at the
// first error NIST's own parser reports (the *Errors* files carry planted
// errors); response files and the client/server logs read, with as many
// points as PtMeas commands answered with X, Y and Z - counted here by a plain
// scan of the text, not by the readers' code.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "base/error.hpp"
#include "io/cmm/ippdme_response_log.hpp"
#include "io/cmm/ippdme_session.hpp"
#include "support/shared_standards.hpp"

using namespace furrow;
namespace fs = std::filesystem;

namespace {

std::string nist_dir() { return test::standards_path("standards/ipp-dme-1.4/nist-test-files"); }

std::string slurp_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Lines split at any of CR and LF (empty ones dropped).
std::vector<std::string> raw_lines(const std::string& text) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : text) {
    if (c == '\r' || c == '\n') {
      if (!cur.empty()) out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) out.push_back(cur);
  return out;
}

// The text after "Sent: " / "Received: " (either case), or the line itself.
std::string after_direction(const std::string& line) {
  for (const char* word : {"Sent: ", "Received: ", "received: ", "sent: "}) {
    const std::size_t at = line.find(word);
    if (at != std::string::npos) return line.substr(at + std::string(word).size());
  }
  return line;
}

bool has_tag(const std::string& l) {
  return l.size() > 6 && l[5] == ' ' && std::all_of(l.begin(), l.begin() + 5, [](char c) { return c >= '0' && c <= '9'; });
}

// The oracle: tags of PtMeas commands in `commands`, then the data lines
// of `responses` on those tags holding X(, Y( and Z( (NIST's files give each
// PtMeas its own tag, checked here); without commands, every data line with
// the three.
std::size_t answered_ptmeas(const std::string& commands, const std::string& responses, bool have_commands) {
  std::set<std::string> ptmeas;
  std::multiset<std::string> all;
  for (const std::string& raw : raw_lines(commands)) {
    const std::string l = after_direction(raw);
    if (!has_tag(l) || l[6] == '#' || l[6] == '&' || l[6] == '%' || l[6] == '!') continue;
    all.insert(l.substr(0, 5));
    if (l.compare(6, 7, "PtMeas(") == 0) ptmeas.insert(l.substr(0, 5));
  }
  for (const std::string& t : ptmeas) REQUIRE(all.count(t) == 1);
  std::size_t n = 0;
  for (const std::string& raw : raw_lines(responses)) {
    const std::string l = after_direction(raw);
    if (!has_tag(l) || l[6] != '#') continue;
    if (have_commands && !ptmeas.count(l.substr(0, 5))) continue;
    if (l.find("X(") != std::string::npos && l.find("Y(") != std::string::npos && l.find("Z(") != std::string::npos)
      ++n;
  }
  return n;
}

std::vector<std::string> files_with(const std::string& dir, const std::string& ext) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ext) out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

std::string error_of_session(const std::string& path) {
  try {
    parse_ippdme_session(slurp_bytes(path), path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

MeasurementSet read_session_log(const std::string& path, const IppdmeSession* program) {
  MeasurementSet set;
  parse_ippdme_response_log(slurp_bytes(path), path, program, "", set);
  return set;
}

}  // namespace

TEST_CASE("NIST I++ DME command files: all parse, the planted errors are refused where NIST's parser refuses") {
  const std::vector<std::string> prgs = files_with(nist_dir(), ".prg");
  REQUIRE(prgs.size() >= 50);
  for (const std::string& path : prgs) {
    CAPTURE(path);
    const std::string stem = fs::path(path).stem().string();
    const std::string error = error_of_session(path);
    if (stem == "parserCmdErrors") {
      // parserCmdErrors.txt: the first command after StartSession is
      // "E0101 AbortE(3)": AbortE MUST HAVE NO ARGUMENTS.
      CHECK(error == path + ":3: not an I++ DME command (AbortE: MUST HAVE NO ARGUMENTS): \"E0101 AbortE(3)\"");
    } else if (stem == "numbersErrorCmd") {
      // numbersErrorCmd.txt: 00010 GoTo(X(12345678901234567)): BAD NUMBER MORE THAN 16 DIGITS.
      CHECK(error.rfind(path + ":5: not an I++ DME command (GoTo: BAD NUMBER MORE THAN 16 DIGITS)", 0) == 0);
    } else {
      CHECK(error == "");
    }
  }
}

TEST_CASE("NIST I++ DME parser errors: each command of parserCmdErrors.prg NIST refuses for syntax or arguments is refused") {
  // One command at a time, as NIST's parser reads them: the lines that
  // parserCmdErrors.txt answers with MUST HAVE..., ARGUMENT MUST BE ...,
  // BAD NUMBER..., ILLEGAL SPACE, EVENT COMMAND ... or TAG NUMBER OUT OF
  // RANGE are refused here too.
  const std::string txt = slurp_bytes(nist_dir() + "/parserCmdErrors.txt");
  const std::vector<std::string> lines = raw_lines(txt);
  std::size_t checked = 0;
  for (std::size_t k = 0; k + 1 < lines.size(); ++k) {
    const std::string& command = lines[k];
    const std::string& message = lines[k + 1];
    if (command.size() < 7 || command[5] != ' ' || command.find('(') == std::string::npos) continue;
    const bool ours = message.find("MUST HAVE") != std::string::npos ||
                      message.find("ARGUMENT MUST BE STRING") != std::string::npos ||
                      message.find("ARGUMENT MUST BE INTEGER") != std::string::npos ||
                      message.find("BAD NUMBER") != std::string::npos || message.find("ILLEGAL SPACE") != std::string::npos ||
                      message.find("EVENT TAG") != std::string::npos || message.find("BAD E NUMBER") != std::string::npos ||
                      message.find("TAG NUMBER OUT OF RANGE") != std::string::npos;
    if (!ours) continue;
    CAPTURE(command);
    CAPTURE(message);
    IppdmeCommand c;
    CHECK(parse_ippdme_command(command, c) != "");
    ++checked;
  }
  CHECK(checked >= 40);
}

TEST_CASE("NIST I++ DME response files: every .res reads with its program, points = PtMeas answered with data") {
  const std::string dir = nist_dir();
  const std::vector<std::string> files = files_with(dir, ".res");
  REQUIRE(files.size() >= 50);
  std::size_t total = 0;
  for (const std::string& path : files) {
    CAPTURE(path);
    const std::string stem = fs::path(path).stem().string();
    const std::string prg = dir + "/" + stem + ".prg";
    const std::string text = slurp_bytes(path);
    if (stem == "parserResErrors" || stem == "numbersErrorRes") {
      // Planted errors in the responses (parserResErrors.txt, numbersErrorRes.txt).
      CHECK_THROWS_AS(read_session_log(path, nullptr), InputError);
      continue;
    }
    const bool have_program = fs::exists(prg) && stem != "parserCmdErrors" && stem != "numbersErrorCmd";
    std::optional<IppdmeSession> program;
    if (have_program) program = parse_ippdme_session(slurp_bytes(prg), prg);
    MeasurementSet set;
    try {
      set = read_session_log(path, program ? &*program : nullptr);
    } catch (const InputError& e) {
      FAIL_CHECK(e.what());
      continue;
    }
    const std::size_t expected = answered_ptmeas(have_program ? slurp_bytes(prg) : "", text, have_program);
    CHECK(set.points.size() == expected);
    MESSAGE(stem << ".res: " << set.points.size() << " points, " << set.not_measured.size() << " not measured");
    total += set.points.size();
  }
  CHECK(total > 0);
}

TEST_CASE("NIST I++ DME client and server logs: every log reads on its own, points = PtMeas answered with data") {
  const std::string dir = nist_dir() + "/ClientServerLogs";
  const std::vector<std::string> files = files_with(dir, ".log");
  REQUIRE(files.size() >= 100);
  std::size_t total = 0;
  for (const std::string& path : files) {
    CAPTURE(path);
    const std::string text = slurp_bytes(path);
    CHECK(is_ippdme_response_log(text));
    MeasurementSet set;
    try {
      set = read_session_log(path, nullptr);
    } catch (const InputError& e) {
      FAIL_CHECK(e.what());
      continue;
    }
    CHECK(set.points.size() == answered_ptmeas(text, text, true));
    MESSAGE(fs::path(path).filename().string() << ": " << set.points.size() << " points, " << set.not_measured.size()
                                               << " not measured");
    total += set.points.size();
  }
  CHECK(total > 0);
}
