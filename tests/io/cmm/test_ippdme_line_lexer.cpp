// The I++ DME session lexer's chunked pipeline (io/cmm/ippdme_line_lexer.hpp)
// against the plain line-by-line lexing it stands in for (the oracle: each
// line of the file lexed in turn): with chunks from one byte to the whole
// file, on NIST's session logs and response files and on a made-up log of
// every layout, every line with content is given in file order with the
// same number, text, tag, mark and point items bit for bit. Then the reader
// through the pipeline: a log larger than one chunk reads back the points
// written, bit for bit, and an error in a later chunk names its own line.
#include <doctest/doctest.h>
#include <omp.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "base/error.hpp"
#include "io/cmm/ippdme_line_lexer.hpp"
#include "io/cmm/ippdme_response_log.hpp"
#include "io/cmm/measurement_fields.hpp"
#include "io/cmm/measurement_file.hpp"
#include "support/shared_standards.hpp"

using namespace furrow;

namespace {

std::uint64_t bits(double v) {
  std::uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

// One lexed line as text: everything the pipeline hands on, numbers by bits.
std::string describe(const IppdmeLexedLine& line, const IppdmePointItems* items) {
  std::ostringstream out;
  out << line.number << '|' << line.ipp << '|' << line.directed << '|' << line.tag << '|' << int(line.mark) << '|';
  if (!items) return out.str() + "slow";
  for (const std::optional<double>* v : {&items->x, &items->y, &items->z, &items->er, &items->tool_a, &items->tool_b,
                                         &items->tool_c})
    out << (*v ? std::to_string(bits(**v)) : std::string("-")) << ',';
  if (items->ijk)
    for (int a = 0; a < 3; ++a) out << bits((*items->ijk)[a]) << ',';
  return out.str();
}

std::vector<std::string> line_by_line(std::string_view text) {
  std::vector<std::string> out;
  IppdmeLexedLine line;
  IppdmePointItems items;
  bool fast = false;
  measurement_fields::for_each_line(text, [&](int number, std::string_view raw) {
    if (lex_ippdme_line(number, raw, line, items, fast)) out.push_back(describe(line, fast ? &items : nullptr));
  });
  return out;
}

std::vector<std::string> pipelined(std::string_view text, std::size_t chunk_bytes) {
  std::vector<std::string> out;
  for_each_lexed_ippdme_line(text, chunk_bytes, [&](const IppdmeLexedLine& line, const IppdmePointItems* items) {
    out.push_back(describe(line, items));
  });
  return out;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A client log of `n` PtMeas, as NIST's clients write them (time stamps,
// Sent/Received, blank lines, CR LF), with an event answer and a note.
std::string client_log(int n) {
  std::string out = "04:08:18_00:00:00 *********** Starting DME file: t.prg **********\r\n\r\n";
  for (int k = 1; k <= n; ++k) {
    char tag[8];
    std::snprintf(tag, sizeof tag, "%05d", k);
    const double x = 10.0 + k / 7.0, y = -3.0 - k / 13.0, z = 0.25 * k;
    char cmd[200], data[200];
    std::snprintf(cmd, sizeof cmd, "PtMeas(X(%.6f), Y(%.6f), Z(%.6f), IJK(0, 0, 1))", x, y, z);
    std::snprintf(data, sizeof data, "X(%.5f), Y(%.5f), Z(%.5f), IJK(0, 0, 1), ER(1.4985)", x + 1e-3, y, z + 1.5);
    out += std::string("04:08:18_00:00:01 Sent: ") + tag + " " + cmd + "\r\n\r\n";
    out += std::string("04:08:18_00:00:01 Received: ") + tag + " &\r\n\r\n";
    if (k % 97 == 0) out += "04:08:18_00:00:01 Received: E0001 # X(1), Y(2), Z(3)\r\n\r\n";
    out += std::string("04:08:18_00:00:01 Received: ") + tag + " # " + data + "\r\n\r\n";
    out += std::string("04:08:18_00:00:01 Received: ") + tag + " %\r\n\r\n";
  }
  return out + "04:08:18_00:00:09 Final Tag: 09999\r\n";
}

}  // namespace

TEST_CASE("I++ DME lexer: chunks of any size give the lines one by one in file order, as lexed line by line") {
  const std::string nist = furrow::test::standards_path("standards/ipp-dme-1.4/nist-test-files");
  std::vector<std::string> texts{client_log(300), "", "\n\n", "00001 &", "\\\\\r\n00001 %\r\n\\\\"};
  for (const char* name : {"/ClientServerLogs/AlignPart_Client.log", "/ClientServerLogs/AlignPart_Server.log",
                           "/AlignPart.res", "/AlignPart.prg", "/scan.res"})
    texts.push_back(read_file(nist + name));
  // With OpenMP's thread limit at 1 the chunks are lexed on this thread alone.
  const int threads = omp_get_max_threads();
  for (const int limit : {threads, 1}) {
    omp_set_num_threads(limit);
    CAPTURE(limit);
    for (const std::string& text : texts) {
      const std::vector<std::string> oracle = line_by_line(text);
      for (const std::size_t chunk : {std::size_t{0}, std::size_t{1}, std::size_t{2}, std::size_t{7}, std::size_t{64},
                                      std::size_t{1000}, text.size(), text.size() + 1}) {
        CAPTURE(chunk);
        CAPTURE(text.size());
        CHECK(pipelined(text, chunk) == oracle);
      }
    }
  }
  omp_set_num_threads(threads);
}

TEST_CASE("I++ DME lexer: an exception from the reader ends the read with a chunk in flight") {
  const std::string text = client_log(2000);
  int seen = 0;
  CHECK_THROWS_AS(for_each_lexed_ippdme_line(text, 4096,
                                             [&](const IppdmeLexedLine& line, const IppdmePointItems*) {
                                               ++seen;
                                               if (line.number >= 3001) throw InputError("stop");
                                             }),
                  InputError);
  CHECK(seen > 0);
}

TEST_CASE("I++ DME lexer: a session log of several chunks reads back its points bit for bit, errors on their own line") {
  // 20,000 points of the plain layout Furrow writes: about 2.7 MB, more
  // than one chunk of the reader, so the second thread takes part.
  MeasurementSet written;
  for (int k = 0; k < 20000; ++k) {
    MeasuredPoint p;
    p.xyz = Eigen::Vector3d(100.0 + k / 3.0, -50.0 + k / 7.0, 1.0 / (k + 1));
    p.ijk = Eigen::Vector3d(0, 0.6, 0.8);
    p.line = 0;
    written.points.push_back(p);
  }
  const std::string text = ippdme_response_log_text(written);
  REQUIRE(text.size() > (std::size_t{1} << 21));
  MeasurementReadOptions options;
  options.probe_diameter = 2;
  const MeasurementSet read = parse_measurements(text, "big.res", MeasurementFormat::ippdme_log, options);
  REQUIRE(read.points.size() == written.points.size());
  bool identical = true;
  for (std::size_t k = 0; k < read.points.size(); ++k)
    for (int a = 0; a < 3; ++a) {
      identical = identical && bits(read.points[k].xyz[a]) == bits(written.points[k].xyz[a]);
      identical = identical && read.points[k].ijk && bits((*read.points[k].ijk)[a]) == bits((*written.points[k].ijk)[a]);
    }
  CHECK(identical);
  // Each point is 3 lines: a bad number planted in point 15,000's data is on
  // line 3 * 14,999 + 2 = 44,999, in the file's second megabytes.
  std::string broken = text;
  const std::size_t at = broken.find("15000 # X(");
  REQUIRE(at != std::string::npos);
  broken.replace(at + 10, 1, "?");
  CHECK_THROWS_WITH_AS(parse_measurements(broken, "big.res", MeasurementFormat::ippdme_log, options),
                       doctest::Contains("big.res:44999:"), InputError);
}
