// Every file scalecert reads or writes goes through here: regular files only, opened without
// blocking, read up to a limit; outputs written beside their target and renamed into place.
#pragma once
#include "numeric/exact.hpp"

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace scalecert::internal {

// Every file scalecert reads is opened here. open_regular_file opens `path` with O_RDONLY |
// O_NONBLOCK | O_CLOEXEC (and O_NOFOLLOW when no_follow): the open never blocks (a FIFO with no
// writer, a terminal) and the descriptor is not inherited. Anything but a regular file (a FIFO,
// socket, device or directory; with no_follow, a symbolic link) is refused, before it is opened
// when its name already says so. Throws InputError "PATH: problem" (one line; `what` names the
// file's role, "scene file"). Returns the descriptor, blocking again, and its size in *size.
int open_regular_file(const std::string& path, const std::string& what, bool no_follow = false, size_t* size = nullptr);
// The whole of a regular file (open_regular_file), at most max_bytes, else InputError naming the limit.
std::string read_regular_file(const std::string& path, const std::string& what, size_t max_bytes,
                              bool no_follow = false);
// A word as /bin/sh reads it: as it is when it holds only letters, digits and _./-, else in single
// quotes, each ' inside written '\''.
std::string shell_word(const std::string& text);
// read_regular_file, or standard input for "-" (where a command documents it).
std::string read_input(const std::string& path, const std::string& what, size_t max_bytes);

// While an InputObserver lives, every file read_input and read_regular_file read on this thread
// is passed to it, with the path as given: campaigns hash the bytes an audit actually read.
class InputObserver {
  public:
    using Fn = std::function<void(const std::string& path, const std::string& bytes)>;
    explicit InputObserver(Fn f);
    ~InputObserver();
    InputObserver(const InputObserver&) = delete;
    InputObserver& operator=(const InputObserver&) = delete;

  private:
    Fn f_;
    const Fn* prev_;
};

// Writes text to path through a temporary file created exclusively beside it, synced to disk,
// then renamed into place, so a failed run never leaves a half-written file. Refuses a target
// that exists and is not a regular file. Throws InputError naming the path.
void write_file_atomically(const std::string& path, const std::string& text);
// Notes on stderr, "scalecert: note: TEXT": what a user may want to know about a run (how numbers
// were read, a step that did not run), never the answer. `scalecert --quiet` silences them and the
// progress lines (quiet()); errors are always said.
void set_quiet(bool quiet);
bool quiet();
void say_note(const std::string& text);
// That refusal alone, for a command that checks its outputs' names before it writes any.
void refuse_non_regular_output(const std::string& path);
// The same for several files: every text is written and synced before any rename, so a failure
// while writing leaves none of them.
void write_files_atomically(const std::vector<std::pair<std::string, std::string>>& files);
// The output journal of a command (the scalecert command opens it): from begin_output_journal on,
// every file write_file(s)_atomically puts in place is recorded, with a hard link to what it
// replaced, and every folder make_output_dir creates. undo_outputs, on failure, removes what was
// created and puts back what was replaced, so that a command that exits 2 leaves no output;
// commit_outputs, on success, drops the kept copies.
void begin_output_journal();
void undo_outputs();
void commit_outputs();
void journal_dir(const std::string& dir);  // a folder created for outputs (removed on undo when empty)
// Refuses (InputError) an output that is one of the inputs (the same file, by device and inode):
// certify-fp --certificate CLAIMS replaced the claims it read.
void refuse_outputs_over_inputs(const std::vector<std::string>& outputs, const std::vector<std::string>& inputs);
// Notes files a command read (its scene, the meshes the scene names): every later
// write_file(s)_atomically of this process refuses to replace one of them with other bytes
// (`region SCENE --out MESH` would replace a mesh the scene names, `audit S --out S` its scene).
void note_inputs(const std::vector<std::string>& paths);

}  // namespace scalecert::internal
