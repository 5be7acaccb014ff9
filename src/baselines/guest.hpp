// The user's own program as a guest (audit --command): run through /bin/sh with its output kept
// out of scalecert's, stopped with every process it started when its time is up, in a private
// temporary folder under $TMPDIR.
#pragma once
#include <csignal>
#include <string>

namespace scalecert::internal {

// How a guest run ended.
struct GuestRun {
    // Interrupted: scalecert itself was sent SIGINT, SIGTERM or SIGHUP while the program ran (the
    // program and what it started are stopped; the caller then ends as that signal asks).
    enum End { Exited, Signalled, TimedOut, NotStarted, Interrupted } end = NotStarted;
    int code = 0;  // the exit status (Exited) or the signal (Signalled, Interrupted)
    // The program's standard output and error: how many bytes it wrote to each (read and dropped,
    // never passed on), and the last two lines of its error output (at most kKeptErrorBytes,
    // control characters shown as '?'), for the reason a failure is given.
    long long stdout_bytes = 0, stderr_bytes = 0;
    std::string last_error_line;
    bool ok() const { return end == Exited && code == 0; }
    // "it exited with status 3", "it was killed by signal 9 (Killed)", "it did not finish within 2 s
    // (--command-timeout) and was stopped", "it could not be started", then the end of its error
    // output when there is one. A status past 128 is named as the shell's word for a signal.
    std::string why_failed(double timeout) const;
};
constexpr std::size_t kKeptErrorBytes = 300;

// The text with control characters and bytes that are no UTF-8 shown as '?' (the rest as it is):
// a program's words, fit for one line of stderr and for JSON.
std::string printable(const std::string& text);

// Runs `sh -c command` with standard input from /dev/null and its standard output and error read
// through pipes and dropped. scalecert is made the child subreaper (prctl PR_SET_CHILD_SUBREAPER)
// for the run, so a process the program started stays its descendant even when it leaves the
// process group (setsid, double fork); when the program ends or `timeout` seconds pass, every
// descendant still running is killed (SIGKILL, repeated until none is left) and reaped. So it is
// when scalecert is sent SIGINT, SIGTERM or SIGHUP meanwhile (end = Interrupted).
GuestRun run_guest(const std::string& command, double timeout);

// While it lives, SIGINT, SIGTERM and SIGHUP sent to scalecert are noted, not acted on (those the
// caller ignores stay ignored): a guest's run is then stopped (run_guest) and its folder removed
// before scalecert ends as the signal asks (end_by). It should outlive the folder.
class GuestSignals {
  public:
    GuestSignals();
    ~GuestSignals();
    GuestSignals(const GuestSignals&) = delete;
    GuestSignals& operator=(const GuestSignals&) = delete;
    int pending() const;  // the signal noted, or 0
    // Removes the folder and ends scalecert by `sig`.
    [[noreturn]] static void end_by(int sig, const std::string& folder);

  private:
    struct sigaction before_[3];
};

// A private folder (mode 0700) for a guest's files, under $TMPDIR when that is set to an existing
// folder where one can be made, else /tmp, removed with everything in it when this goes out of scope. InputError when
// none can be made.
class GuestFolder {
  public:
    GuestFolder();
    ~GuestFolder();
    GuestFolder(const GuestFolder&) = delete;
    GuestFolder& operator=(const GuestFolder&) = delete;
    const std::string& path() const { return path_; }

  private:
    std::string path_;
};

}  // namespace scalecert::internal
