// The lines of an I++ DME session, lexed: what each line says without the
// session's state (docs/formats.md "Reading any I++ DME session").
//
// Why a stage of its own: in a million-point session log about two thirds of
// the reading is finding each line's I++ DME part and converting its
// numbers, work that depends on the line alone. Lexed in chunks, two at a
// time on two threads, and applied in file order, a log reads faster on two
// cores; the reader's decisions, its
// errors and their line numbers are those of a line-by-line read, because
// everything that depends on earlier lines stays in the sequential part.
#pragma once

#include <cstddef>
#include <memory>
#include <string_view>
#include <vector>

#include "io/cmm/ippdme_command.hpp"

namespace furrow {

// One line with I++ DME content.
struct IppdmeLexedLine {
  int number = 0;        // in the file, from 1
  std::string_view ipp;  // the I++ DME part: no time stamp, "Sent:"/"Received:" or blanks
  bool directed = false;  // the line had "Sent:" or "Received:"
  int tag = -1;           // 0..99999; -2 an event tag (E and four digits); -1 none
  char mark = 0;          // '&', '%', '#', '!' for a response, 0 for a command or untagged
};

bool is_ippdme_response_mark(char c);

// The I++ DME part of a line of any layout (empty for a line with none:
// blank, `\\`, `:`, a log's time-stamped note such as "Final Tag: 09999");
// `directed` tells whether it was logged as sent or received.
std::string_view ippdme_line_part(std::string_view line, bool& directed);

// The tag's number (0..99999) when `ipp` starts with five digits and a
// space; -1 otherwise. Event tags (E and four digits) give -2.
int ippdme_tag_of(std::string_view ipp);

// Lexes one line; false for a line without I++ DME content. `items` gets
// the point items read in place - the data of a '#' answer, or the
// arguments of a PtMeas command - and `fast` tells whether they were (false:
// the line needs the general parser, and `items` is unspecified).
bool lex_ippdme_line(int number, std::string_view line, IppdmeLexedLine& out, IppdmePointItems& items, bool& fast);

// The lines of `text` with content, in file order, given to `apply(line,
// items)` one by one, `items` null when the line's point items were not read
// in place. Chunks of about `chunk_bytes` (cut after a line end) are lexed in
// pairs, one on the calling thread and one on a second thread; a text within
// one chunk, or with OMP_NUM_THREADS=1, is lexed on the calling thread alone. An exception from `apply`
// ends the read once the chunk in flight is lexed. The lines' string views
// point into `text`.
template <class Apply>
void for_each_lexed_ippdme_line(std::string_view text, std::size_t chunk_bytes, Apply&& apply);

// Below: the chunked pipeline.
namespace ippdme_lexer_detail {
struct Chunk {
  std::vector<IppdmeLexedLine> lines;  // numbered from 1 within the chunk
  std::vector<int> item_index;         // per line: into `items`, -1 none
  std::vector<IppdmePointItems> items;
  int line_count = 0;  // every line, with content or not
};
// Fills `chunk` (its buffers reused) with the lines of `part`.
void lex_chunk(std::string_view part, Chunk& chunk);
// The chunk from `start`: about `chunk_bytes`, ending after a line end (or
// at the text's end).
std::string_view next_part(std::string_view text, std::size_t start, std::size_t chunk_bytes);
// Whether a second thread may be used: OpenMP's thread limit
// (OMP_NUM_THREADS), which bounds every parallel stage of Furrow, is 2 or more.
bool second_thread_allowed();
// Runs `lex_chunk(part, chunk)` on a second thread; `wait` returns when it
// is done (rethrowing what it threw). Joins in its destructor.
class ChunkInFlight {
 public:
  ChunkInFlight(std::string_view part, Chunk& chunk);
  ~ChunkInFlight();
  ChunkInFlight(const ChunkInFlight&) = delete;
  ChunkInFlight& operator=(const ChunkInFlight&) = delete;
  void wait();

 private:
  struct State;
  std::unique_ptr<State> state_;
};
}  // namespace ippdme_lexer_detail

template <class Apply>
void for_each_lexed_ippdme_line(std::string_view text, std::size_t chunk_bytes, Apply&& apply) {
  namespace d = ippdme_lexer_detail;
  if (chunk_bytes == 0) chunk_bytes = 1;
  int first_line = 0;  // lines before the chunk being applied
  auto apply_chunk = [&](d::Chunk& chunk) {
    for (std::size_t k = 0; k < chunk.lines.size(); ++k) {
      IppdmeLexedLine& line = chunk.lines[k];
      line.number += first_line;
      const int i = chunk.item_index[k];
      apply(static_cast<const IppdmeLexedLine&>(line), i < 0 ? nullptr : &chunk.items[static_cast<std::size_t>(i)]);
    }
    first_line += chunk.line_count;
  };
  // Chunks in pairs: the second lexed on another thread while this one lexes
  // and applies the first; the lexing dominates, so both cores share it. The
  // two chunks' buffers are kept from pair to pair.
  d::Chunk first_chunk, second_chunk;
  const bool two_threads = text.size() > chunk_bytes && d::second_thread_allowed();
  std::size_t start = 0;
  while (start < text.size()) {
    const std::string_view first = d::next_part(text, start, chunk_bytes);
    start += first.size();
    if (!two_threads) {
      d::lex_chunk(first, first_chunk);
      apply_chunk(first_chunk);
      continue;
    }
    std::unique_ptr<d::ChunkInFlight> second;
    if (start < text.size()) {
      const std::string_view part = d::next_part(text, start, chunk_bytes);
      start += part.size();
      second = std::make_unique<d::ChunkInFlight>(part, second_chunk);
    }
    d::lex_chunk(first, first_chunk);
    apply_chunk(first_chunk);
    if (second) {
      second->wait();
      second.reset();
      apply_chunk(second_chunk);
    }
  }
}

}  // namespace furrow
