// An outside solver as a backend: any program, spoken to through the file protocol of
// docs/your-solver.md, behind the same Solver interface as the built-in backends. The suites,
// checks, comparisons with `event`, work-precision lines and report then treat it like any
// other backend row (validation/plan/external_solvers.h puts it into a suite's backend list).
//
// Per program call, collide writes a request directory (request.txt, initial.npy, scene.toml),
// runs `COMMAND DIR` (or, for a long-lived program, sends DIR to its running copy:
// solver_server.h), and reads DIR/result.txt and DIR/states.npy back. Everything that comes
// back is checked (exit status, time limit, shapes, dtype, count, finite numbers, times); a
// fault throws with a message that names the solver, the scene and what was wrong.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/backend_registry.h"

namespace collide::external {

// The protocol version written into every request (request.txt: "protocol 2"). Version 2 adds,
// all optional and so backward compatible: `option KEY VALUE` request lines (a suite variant's
// settings), `seconds` in result.txt (the solver's own stepping time, its cost), and the
// declarations `handles` (capabilities), `files` (package files in its provenance) and
// `long_lived` (one program start serves many calls, solver_server.h).
inline constexpr int protocol_version = 2;

// The scene features a solver may declare it handles (`handles = [...]` in its [solver] table),
// in the order they are named: "walls" (reflecting boundaries), "periodic", "restitution" (e or
// the wall restitution below 1), "friction", "gravity", "damping", "stones".
const std::vector<std::string>& solver_capabilities();
std::string capabilities_text();  // "walls, periodic, ...", for messages

// The capabilities `scene` needs (a subset of solver_capabilities()).
std::vector<std::string> scene_needs(const Scene& scene);

struct ExternalSolverSpec {
    std::string name;         // its backend name in every output: lower-case letters, digits, _ or -
    std::string command;      // a /bin/sh command line; the request directory is appended as "$1"
    std::string directory;    // where the command runs ("" = the current directory)
    std::string python_class; // "module:Class" or "file.py:Class" when given as a Python class (else "")
    // "" or the stepping rule it implements ("collide-first", "integrate-first"): such a solver is
    // judged as the built-in stepped backends are (the statistics against the predicted bias).
    std::string rule;
    // Declared exact (event-driven: no time step, every contact resolved at its time): held to
    // what exact dynamics allows in its precision (docs/validation.md, "What a solver claims").
    // Exact with a rule is a contradiction, refused.
    bool exact = false;
    std::string precision;  // "double", "float", or "" (not declared: double)
    std::string computed_precision() const { return precision.empty() ? "double" : precision; }
    // The capabilities it declares (protocol 2); unset: it may get any scene and refuse one when
    // called ("refuse REASON"). Set: a scene that needs another is left out without a call.
    std::optional<std::vector<std::string>> handles;
    // Files beyond the command's words whose hashes go into every case's provenance (its lock
    // file, the engine's library), relative to its directory.
    std::vector<std::string> files;
    // Declared long-lived (`long_lived = true`): started once per process that runs cases, as
    // `COMMAND --serve`, it answers request after request over a pipe (solver_server.h), so its
    // start-up is paid once; a call that it fails (dies, hangs, answers garbage) fails that case
    // only, and the next call starts it again. A Python class runs through its one-shot runner.
    bool long_lived = false;
    double call_time_limit = 60;  // seconds per program call
    std::string origin;       // where it was named, for messages ("--solver", "suite.toml:12")
};

// "" when request directories can be made where they go ($TMPDIR, else /tmp), else why not,
// naming TMPDIR: it is relative (the solver runs in its own directory, where a relative path
// names another place), missing, not a directory, or not writable. Checked once, before any
// case, wherever outside solvers join a suite (validation/plan/external_solvers.h).
std::string request_root_problem();

// "" when `name` can be a solver's name, else what is wrong with it.
std::string solver_name_problem(const std::string& name);

// "" or what is wrong with a rule name.
std::string rule_problem(const std::string& rule);

// "" or what is wrong with a precision name ("" is not declared: double).
std::string precision_problem(const std::string& precision);

// "" or what is wrong with a declared capability list (an unknown name, named twice).
std::string handles_problem(const std::vector<std::string>& handles);

// "" when a solver declaring `handles` can run `scene`, else why not (what it needs that the
// solver does not declare).
std::string unhandled_need(const ExternalSolverSpec& spec, const Scene& scene);

// "" or why `spec` cannot be long-lived (a Python class: its runner answers one call per start).
std::string long_lived_problem(const ExternalSolverSpec& spec);

// "" or the contradiction between the declarations: exact (no time step) with a stepping rule.
std::string claims_problem(bool exact, const std::string& rule);

// "" when `spec` is complete and valid (name, exactly one of command and python_class, a class
// as "module:Class", the rule, the precision, no contradiction), else what is wrong, e.g.
// "rule: expected ...". Every way a
// solver is named (a suite's [solver.NAME], --solver, Python's solvers=) is checked by it;
// the suite file also names the key's line.
std::string spec_problem(const ExternalSolverSpec& spec);

// The spec of NAME=COMMAND (`--solver`); throws std::invalid_argument naming the fault.
ExternalSolverSpec parse_solver_option(const std::string& text);

// The registry entry of an outside solver: what it declares (exact, rule, precision; an exact
// solver conserves momentum and energy, a stepping rule momentum), supports() accepts every
// scene (the program may refuse one at run time by answering "refuse REASON": the case is then
// left out), create() makes an ExternalSolver.
BackendInfo external_backend(const ExternalSolverSpec& spec);

// The Solver behind external_backend(); public for the tests.
std::unique_ptr<Solver> make_external_solver(const ExternalSolverSpec& spec);

}  // namespace collide::external
