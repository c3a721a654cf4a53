#pragma once
// All the outputs of one command, published together or not at all, and never
// over one of its inputs.
//
// Why one mechanism: a command that writes several files (a prediction and its
// map, a G-code file and its contacts, a plan folder) used to write them one
// by one, so a failure or a kill between two left a partial set, and each
// command checked its inputs its own way (one of them replaced the folder
// holding its own part). Here a command declares what it reads, stages what
// it writes, and publishes at the end:
//
//   OutputSet outputs;
//   outputs.add_input(part_path, "part");        // before any output
//   outputs.file(json_path, json_text);           // staged: a hidden sibling
//   outputs.file(map_path, png_bytes);
//   outputs.publish(json_path);                   // main file renamed last
//
// Contract:
// - An output that is an input, or a folder output that holds an input
//   (after resolving symbolic links and `..`, parents included), is refused
//   with an InputError naming both, before anything is written.
// - Staged content goes to a temporary sibling of its destination
//   (`.NAME.tmp-PID-N`, same folder, so publishing is a rename on one file
//   system). Nothing is visible under a destination's name before publish().
// - publish() renames the files in the order they were staged, with `main`
//   (when given) last, so a reader that waits for the main file sees the
//   whole set. A folder output replaces an older folder of that name.
// - Destroying an unpublished set (an exception, an early return) removes
//   everything it staged. SIGINT, SIGTERM and SIGHUP remove the staged
//   temporaries of every live set and then end the process as the signal
//   would. A SIGKILL cannot be caught: temporaries of processes that no
//   longer run are removed the next time any command stages an output next
//   to the same destination.
#include <string>
#include <vector>

namespace furrow {

// Throws InputError when writing `output` would overwrite the input at
// `input` or replace a folder holding it. `role` names the input in the
// message ("part", "measurements", ...). Paths that do not exist yet are
// compared after resolving their existing parents.
void check_output_spares_input(const std::string& output, const std::string& input,
                               const std::string& role);

class OutputSet {
 public:
  OutputSet();
  ~OutputSet();
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  // Declares a file or folder the command reads. Outputs staged before or
  // after are checked against it.
  void add_input(const std::string& path, const std::string& role);

  // Checks now, before the work, that `path` may be written: it spares every
  // input declared so far and is not already an output of this set.
  void will_write(const std::string& path);

  // Stages a file with its whole content. Creates missing parent folders.
  // Throws InputError naming the path when it cannot be written.
  void file(const std::string& path, const std::string& content);

  // Stages a folder output and returns the (empty) staging folder to fill.
  // The folder replaces `path` as a whole when published.
  std::string folder(const std::string& path);

  // Publishes every staged output; `main` (a staged path) goes last.
  void publish(const std::string& main = "");

  // Staged destinations, in staging order (for messages such as "wrote ...").
  std::vector<std::string> destinations() const;

 private:
  struct Staged {
    std::string destination;
    std::string temporary;
    bool folder = false;
  };
  struct Input {
    std::string path;
    std::string role;
  };
  void check_against_inputs(const std::string& destination) const;
  void discard() noexcept;

  std::vector<Input> inputs_;
  std::vector<Staged> staged_;
  std::vector<std::string> intended_;
  bool published_ = false;
};

}  // namespace furrow
