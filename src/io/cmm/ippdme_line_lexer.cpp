#include "io/cmm/ippdme_line_lexer.hpp"

#include <omp.h>

#include <exception>
#include <system_error>
#include <thread>

#include "io/cmm/measurement_fields.hpp"

namespace furrow {

namespace mf = measurement_fields;

namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

bool starts_with_word(std::string_view s, std::string_view word) {
  if (s.size() < word.size()) return false;
  for (std::size_t k = 0; k < word.size(); ++k) {
    const char c = s[k] >= 'A' && s[k] <= 'Z' ? static_cast<char>(s[k] - 'A' + 'a') : s[k];  // ASCII, no locale
    if (c != word[k]) return false;
  }
  return true;
}

}  // namespace

bool is_ippdme_response_mark(char c) { return c == '#' || c == '%' || c == '&' || c == '!'; }

std::string_view ippdme_line_part(std::string_view line, bool& directed) {
  directed = false;
  line = mf::trimmed(line);
  if (line.empty() || line == "\\\\" || line == ":") return {};
  const std::size_t space = line.find(' ');
  const std::string_view first = line.substr(0, space);
  bool stamp = first.find(':') != std::string_view::npos;
  for (char c : first)
    if (!is_digit(c) && c != ':' && c != '_' && c != '.' && c != '/' && c != '-') stamp = false;
  if (stamp) line = space == std::string_view::npos ? std::string_view() : mf::trimmed(line.substr(space + 1));
  for (std::string_view word : {std::string_view("sent:"), std::string_view("received:")})
    if (starts_with_word(line, word)) {
      directed = true;
      return mf::trimmed(line.substr(word.size()));
    }
  return stamp ? std::string_view() : line;  // a time-stamped note
}

int ippdme_tag_of(std::string_view ipp) {
  if (ipp.size() < 7 || ipp[5] != ' ') return -1;
  const bool event = ipp[0] == 'E';
  int tag = 0;
  for (int k = event ? 1 : 0; k < 5; ++k) {
    if (!is_digit(ipp[k])) return -1;
    tag = 10 * tag + (ipp[k] - '0');
  }
  return event ? -2 : tag;
}

bool lex_ippdme_line(int number, std::string_view line, IppdmeLexedLine& out, IppdmePointItems& items, bool& fast) {
  bool directed = false;
  const std::string_view ipp = ippdme_line_part(line, directed);
  if (ipp.empty()) return false;
  out.number = number;
  out.ipp = ipp;
  out.directed = directed;
  out.tag = ippdme_tag_of(ipp);
  out.mark = 0;
  fast = false;
  if (out.tag == -1) return true;
  if (is_ippdme_response_mark(ipp[6])) {
    out.mark = ipp[6];
    // The usual answer of a PtMeas.
    if (out.mark == '#') fast = ippdme_point_items_fast(mf::trimmed(ipp.substr(7)), kIppdmeAnswerDigits, items);
  } else {
    // A PtMeas of point items only.
    fast = ipp.size() > 14 && ipp.substr(6, 7) == "PtMeas(" && ipp.back() == ')' &&
           ippdme_point_items_fast(ipp.substr(13, ipp.size() - 14), kIppdmeDigits, items);
  }
  return true;
}

namespace ippdme_lexer_detail {

void lex_chunk(std::string_view part, Chunk& chunk) {
  chunk.lines.clear();
  chunk.item_index.clear();
  chunk.items.clear();
  chunk.line_count = 0;
  IppdmeLexedLine line;
  IppdmePointItems items;
  bool fast = false;
  mf::for_each_line(part, [&](int number, std::string_view raw) {
    chunk.line_count = number;
    if (!lex_ippdme_line(number, raw, line, items, fast)) return;
    chunk.lines.push_back(line);
    chunk.item_index.push_back(fast ? static_cast<int>(chunk.items.size()) : -1);
    if (fast) chunk.items.push_back(items);
  });
}

std::string_view next_part(std::string_view text, std::size_t start, std::size_t chunk_bytes) {
  if (text.size() - start <= chunk_bytes) return text.substr(start);
  const std::size_t end = text.find('\n', start + chunk_bytes - 1);
  return text.substr(start, end == std::string_view::npos ? std::string_view::npos : end + 1 - start);
}

bool second_thread_allowed() { return omp_get_max_threads() >= 2; }

struct ChunkInFlight::State {
  std::thread thread;
  std::exception_ptr error;
};

ChunkInFlight::ChunkInFlight(std::string_view part, Chunk& chunk) : state_(std::make_unique<State>()) {
  State* s = state_.get();
  auto work = [s, part, &chunk] {
    try {
      lex_chunk(part, chunk);
    } catch (...) {
      s->error = std::current_exception();
    }
  };
  try {
    s->thread = std::thread(work);
  } catch (const std::system_error&) {
    work();  // no thread to be had: the same work on this one
  }
}

ChunkInFlight::~ChunkInFlight() {
  if (state_->thread.joinable()) state_->thread.join();
}

void ChunkInFlight::wait() {
  if (state_->thread.joinable()) state_->thread.join();
  if (state_->error) std::rethrow_exception(state_->error);
}

}  // namespace ippdme_lexer_detail

}  // namespace furrow
