// A long-lived outside solver (`long_lived = true`, docs/your-solver.md "A solver that serves
// many calls"): the program is started once, as `COMMAND --serve`, and then answers one request
// directory after another over a pipe, so what it pays once (Node's start, a WebAssembly
// engine's compile: about 1.8 s for Rapier) is paid once per process that runs cases (a
// suite's worker), not once per call.
//
// The wire format, one line each way per call:
//   collide -> program (its stdin):   the request directory's absolute path, then "\n"
//   program -> collide (its stdout):  "done\n" when result.txt and states.npy are written, or
//                                     "failed REASON\n" when it could not answer this request
// Its stderr goes to the case's log, as a one-shot program's output does. End of file on its
// stdin means "no more requests": it should exit.
//
// Whatever the program does, the call ends: a server that dies, runs past the call's limit or
// writes a line that is neither reply is ended (its process group killed, its orphans ended,
// every process reaped) and the next call starts a new one.
#pragma once

#include <sys/types.h>

#include <memory>
#include <string>

#include "program_call.h"

namespace collide::external {

// How one request to a server went.
struct ServedCall {
    enum class Reply { done, failed, garbage, ended };
    Reply reply = Reply::ended;
    std::string text;         // failed: its reason; garbage: the line it wrote (printable)
    ProgramOutcome process;   // ended: how the server ended (exit, signal, the limit); seconds: the call's wall time
    bool started = false;     // this call started the server: its start-up is in `seconds`
    std::string output;       // what it wrote on stderr during the call (and its start-up)
    // "" when the answer files are there to be read, else the fault, e.g. "the server exited
    // with status 3 before answering" or "answered 'hello' instead of 'done' or 'failed REASON'".
    std::string problem(double limit_seconds) const;
};

class SolverServer {
public:
    // Starts `COMMAND --serve` in `directory`; throws std::runtime_error when it cannot be
    // started at all (fork, pipe or its log file failed).
    SolverServer(const std::string& command, const std::string& directory);
    ~SolverServer();  // close(): end of file on its stdin, then it is waited for and reaped
    SolverServer(const SolverServer&) = delete;
    SolverServer& operator=(const SolverServer&) = delete;

    // Sends `request_dir` and waits for the reply, at most `limit_seconds`; a server that did not
    // reply "done" or "failed" is ended by the call (alive() is then false).
    ServedCall call(const std::string& request_dir, double limit_seconds);
    bool alive() const { return pid_ > 0; }
    // False when it has exited, or wrote a line while idle (it is then ended and reaped).
    bool still_running();
    // Sends end of file (closes its stdin) without waiting; close() then waits.
    void send_end();
    // Waits up to `grace_seconds` after send_end() for it to exit, then kills what is left.
    void close(double grace_seconds = 5);
    // A copy of this object made by fork() in a child process: forget the server there, closing
    // only the descriptors (the parent that started it ends it).
    void forget();

private:
    ProgramOutcome end(bool kill_now, double grace_seconds);
    std::string take_output();
    bool take_pending_line(std::string& line);
    void drain_replies();
    bool read_line(std::string& line, double limit_seconds, ProgramOutcome& ended);

    pid_t pid_ = 0;
    int requests_ = -1;   // its stdin (our write end)
    int replies_ = -1;    // its stdout (our read end)
    int log_ = -1;        // its stderr: an unlinked file, read and emptied after each call
    std::string pending_; // what it wrote after the last line taken
    bool fresh_ = false;  // started and not yet called
    bool reaped_ = false; // waited for already (status_ holds how it ended)
    int status_ = 0;
};

// The process's idle servers, by command and directory (one per thread that runs calls at the
// same time: a call takes one out and gives it back). Servers started before a fork belong to
// the parent: a child process sees none of them.
std::unique_ptr<SolverServer> take_idle_server(const std::string& command, const std::string& directory);
void give_back_server(const std::string& command, const std::string& directory, std::unique_ptr<SolverServer> server);

// Closes every idle server of this process (end of file on each one's stdin, all at once; each
// is waited for up to 5 s, then killed) and reaps them. A process that runs cases calls it
// before it exits with _exit (a suite's worker); a normal exit closes them too.
void close_solver_servers();

}  // namespace collide::external
