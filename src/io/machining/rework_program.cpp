#include "io/machining/rework_program.hpp"

#include <algorithm>
#include <cctype>
#include <climits>
#include <cstdio>
#include <sstream>

namespace furrow {

namespace {

std::string number(double v, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
  std::string s = buffer;
  if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);  // no "-0.0000"
  return s;
}

// "1000.0000" -> "1000", "12.5000" -> "12.5".
std::string trimmed(std::string s) {
  s.erase(s.find_last_not_of('0') + 1);
  if (s.back() == '.') s.pop_back();
  return s;
}

bool is_rapid_statement(const std::string& line) {
  std::string word;
  for (char c : line)
    if (c != ' ' && c != '\t') word += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return word == "RAPID";
}

// The original's lines, each without its line ending.
std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> out;
  std::size_t at = 0;
  while (at < text.size()) {
    std::size_t end = text.find('\n', at);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(at, end - at);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    out.push_back(std::move(line));
    at = end + 1;
  }
  return out;
}

class Writer {
 public:
  Writer(ReworkFormat format, int decimals, std::string eol)
      : apt_(format == ReworkFormat::apt), decimals_(decimals), eol_(std::move(eol)) {}

  void raw(const std::string& line) { out_ += line + eol_; }

  // G-code only: straight up from wherever the header left the machine.
  void rapid_z(double z) { raw("G0 Z" + number(z, decimals_)); }
  void rapid_to(const Eigen::Vector3d& p) {
    if (apt_) {
      raw("RAPID");
      raw("GOTO/" + number(p.x(), decimals_) + "," + number(p.y(), decimals_) + "," + number(p.z(), decimals_));
    } else {
      raw("G0 X" + number(p.x(), decimals_) + " Y" + number(p.y(), decimals_) + " Z" + number(p.z(), decimals_));
    }
  }
  void cut_to(const Eigen::Vector3d& p, double feed) {
    const bool new_feed = feed > 0 && feed != feed_;
    if (apt_) {
      if (new_feed) raw("FEDRAT/MMPM," + number(feed, 4));
      raw("GOTO/" + number(p.x(), decimals_) + "," + number(p.y(), decimals_) + "," + number(p.z(), decimals_));
    } else {
      std::string line =
          "G1 X" + number(p.x(), decimals_) + " Y" + number(p.y(), decimals_) + " Z" + number(p.z(), decimals_);
      if (new_feed) line += " F" + trimmed(number(feed, 4));
      raw(line);
    }
    if (new_feed) feed_ = feed;
  }
  std::string take() { return std::move(out_); }

 private:
  bool apt_;
  int decimals_;
  std::string eol_;
  std::string out_;
  double feed_ = -1;
};

}  // namespace

std::string write_rework_program(const std::string& original_text, const Toolpath& original,
                                 const std::vector<ReworkStretch>& stretches, double clearance, int decimals,
                                 ReworkFormat format) {
  // The header ends before the first motion line, the end begins after the last.
  int first = INT_MAX, last = 0;
  for (const RapidMove& r : original.rapids) first = std::min(first, r.line), last = std::max(last, r.line);
  for (const ToolpathPass& p : original.passes)
    for (const ToolpathPoint& q : p.points) first = std::min(first, q.line), last = std::max(last, q.line);
  const std::vector<std::string> lines = split_lines(original_text);
  const std::string eol = original_text.find("\r\n") != std::string::npos ? "\r\n" : "\n";
  Writer w(format, decimals, eol);
  int header_end = std::min(first, static_cast<int>(lines.size()) + 1);
  // APT: a RAPID just before the first motion is that motion's modifier,
  // not header: the rework writes its own.
  while (format == ReworkFormat::apt && header_end > 1 &&
         is_rapid_statement(lines[static_cast<std::size_t>(header_end - 2)]))
    --header_end;
  for (int i = 1; i < header_end; ++i) w.raw(lines[static_cast<std::size_t>(i - 1)]);
  bool up = false;  // at the clearance height over a known position
  for (const ReworkStretch& s : stretches) {
    const Eigen::Vector3d& start = s.tips.front();
    // The first: G-code rises from wherever the header left the machine;
    // APT's first RAPID GOTO/ is from an unknown position anyway.
    if (!up && format == ReworkFormat::gcode) w.rapid_z(clearance);
    w.rapid_to({start.x(), start.y(), clearance});
    w.cut_to(start, s.feeds.front());  // the plunge, at the stretch's feed
    for (std::size_t k = 1; k < s.tips.size(); ++k) w.cut_to(s.tips[k], s.feeds[k]);
    w.rapid_to({s.tips.back().x(), s.tips.back().y(), clearance});
    up = true;
  }
  for (std::size_t i = static_cast<std::size_t>(last); i < lines.size(); ++i) w.raw(lines[i]);
  return w.take();
}

}  // namespace furrow
