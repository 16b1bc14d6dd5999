#include "external_solver.h"

#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/io/fd_io.h"
#include "core/io/output_file.h"
#include "core/io/path_causes.h"
#include "core/io/temporary_directory.h"
#include "core/numerics/number_text.h"
#include "core/numerics/target_time.h"
#include "core/text/printable.h"
#include "npy.h"
#include "program_call.h"
#include "solver_files.h"
#include "solver_server.h"

namespace collide::external {
namespace fs = std::filesystem;
namespace {

// How much of a program's output a fault message quotes (the whole output goes to the case log).
constexpr std::size_t quoted_output_chars = 600;
// result.txt is a few lines; more than this is not a result.
constexpr std::uintmax_t max_result_bytes = 64u << 20;

// Where request directories go: $TMPDIR, else /tmp (POSIX).
std::string request_root() {
    const char* tmpdir = std::getenv("TMPDIR");
    return tmpdir && *tmpdir ? tmpdir : "/tmp";
}

// A request directory of its own under request_root(), removed with it.
TemporaryDirectory request_directory() {
    if (const std::string problem = request_root_problem(); !problem.empty()) throw std::runtime_error(problem);
    return TemporaryDirectory(request_root(), "collide-solver", "a request directory");
}

// At most `limit` bytes of the file: a solver's output may be large, and only its head is read.
std::string read_text(const std::string& path, std::uintmax_t limit) {
    std::error_code ec;
    const auto size = fs::file_size(path, ec);
    if (ec) return {};
    std::ifstream in(path, std::ios::binary);
    std::string text(std::size_t(std::min<std::uintmax_t>(size, limit)), '\0');
    in.read(text.data(), std::streamsize(text.size()));
    text.resize(std::size_t(in.gcount()));
    return text;
}

// "" when the program left `name` as a regular file (or a link to one), else what it left:
// "wrote no states.npy", "wrote states.npy as a FIFO, not a regular file" (reading a FIFO would
// wait for a writer for good; a directory is no answer either).
std::string answer_file_problem(const std::string& path, const std::string& name) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        struct stat link {};
        if (::lstat(path.c_str(), &link) == 0) return "wrote " + name + " as a symbolic link to nothing";
        return "wrote no " + name;
    }
    if (!S_ISREG(st.st_mode)) return "wrote " + name + " as " + path_causes::kind_of(st.st_mode) + ", not a regular file";
    return "";
}

// A request file in the call's private directory, deleted after the call: no atomic rename or
// fsync is needed (nothing else can see it), only a complete write.
void write_request_file(const std::string& path, const std::string& bytes) {
    const int fd = open_output_stream(path);  // the output guard (core/io/output_file.h)
    const bool written = write_fully(fd, bytes.data(), bytes.size());
    if (::close(fd) != 0 || !written) throw std::runtime_error(path + ": could not write the request (disk full?)");
}

std::string times_text(const std::vector<double>& times) {
    std::string out;
    for (double t : times) {
        out += ' ';
        out += round_trip_text(t);
    }
    return out;
}

// request.txt: one "key value" line each, the numbers as round-trip text (strtod gives the
// same double back). The scene file's own text is beside it; these values are the case's.
std::string request_text(const ExternalSolverSpec& spec, const Scene& scene, std::size_t disks, double start,
                         const std::vector<double>& times) {
    std::ostringstream out;
    const auto number = [&out](const char* key, double v) { out << key << ' ' << round_trip_text(v) << '\n'; };
    out << "protocol " << protocol_version << '\n';
    out << "solver " << spec.name << '\n';
    out << "scene " << scene.name << '\n';
    out << "seed " << scene.seed << '\n';
    out << "disks " << disks << '\n';
    number("start_time", start);
    out << "output_times" << times_text(times) << '\n';
    number("dt", scene.run.dt);
    out << "substeps " << scene.run.substeps << '\n';
    out << "order " << to_string(scene.run.order) << '\n';
    out << "boundary " << to_string(scene.world.boundary) << '\n';
    number("xmin", scene.world.xmin);
    number("ymin", scene.world.ymin);
    number("xmax", scene.world.xmax);
    number("ymax", scene.world.ymax);
    number("restitution", scene.physics.restitution);
    number("wall_restitution", scene.physics.wall_restitution);
    number("friction", scene.physics.friction);
    number("gravity_x", scene.physics.gravity_x);
    number("gravity_y", scene.physics.gravity_y);
    number("damping", scene.physics.damping);
    number("duration", scene.run.duration);
    // A suite variant's settings ([variant."NAME[...]"]) arrive as the scene's [backend.NAME] table.
    if (const auto options = scene.backend_options.find(spec.name); options != scene.backend_options.end())
        for (const auto& [key, value] : options->second) out << "option " << key << ' ' << value << '\n';
    return out.str();
}

// initial.npy: (N, 7) float64, columns x, y, vx, vy, radius, mass, stone (1 for a kinematic stone).
std::string state_npy(const ParticleState<double>& s) {
    std::vector<double> rows;
    rows.reserve(s.size() * 7);
    for (std::size_t i = 0; i < s.size(); ++i)
        for (double v : {s.x[i], s.y[i], s.vx[i], s.vy[i], s.radius[i], s.mass[i], s.is_stone(i) ? 1.0 : 0.0})
            rows.push_back(v);
    return npy_bytes(rows, {s.size(), 7});
}

std::string join_words(const std::vector<std::string>& words) {
    std::string out;
    for (const auto& w : words) out += (out.empty() ? "" : ", ") + w;
    return out;
}

// What result.txt says.
struct Answer {
    std::vector<double> times;
    bool has_times = false;
    std::int64_t steps = 0, contacts = 0;
    bool has_contacts = false;
    std::optional<double> seconds;  // its own stepping time (protocol 2)
    std::string version, refusal;
    std::string precision;  // "" when result.txt does not say
};

bool whole_number(const std::string& word, std::int64_t& value) {
    if (word.empty() || word.size() > 18 || word.find_first_not_of("0123456789") != std::string::npos) return false;
    value = std::stoll(word);
    return true;
}

bool real_number(const std::string& word, double& value) {
    if (word.empty()) return false;
    char* end = nullptr;
    value = std::strtod(word.c_str(), &end);
    return end == word.c_str() + word.size();
}

std::string rest_of_line(std::istringstream& in) {
    std::string rest;
    std::getline(in, rest);
    const auto first = rest.find_first_not_of(" \t");
    rest = first == std::string::npos ? "" : rest.substr(first);
    while (!rest.empty() && (rest.back() == '\r' || rest.back() == ' ')) rest.pop_back();
    return printable_tail(rest, 300);
}

Answer parse_answer(const std::string& text) {
    Answer a;
    std::istringstream lines(text);
    std::string line;
    int number = 0;
    while (std::getline(lines, line)) {
        ++number;
        std::istringstream in(line);
        std::string key;
        if (!(in >> key) || key[0] == '#') continue;
        const std::string where = "result.txt line " + std::to_string(number) + ": ";
        if (key == "times") {
            std::string word;
            while (in >> word) {
                double t = 0;
                if (!real_number(word, t))
                    throw std::runtime_error(where + "times: '" + printable_tail(word, 40) + "' is not a number");
                a.times.push_back(t);
            }
            a.has_times = true;
        } else if (key == "steps" || key == "contacts") {
            std::string word;
            in >> word;
            std::int64_t v = 0;
            if (!whole_number(word, v)) throw std::runtime_error(where + key + ": expected a whole number >= 0");
            (key == "steps" ? a.steps : a.contacts) = v;
            if (key == "contacts") a.has_contacts = true;
        } else if (key == "seconds") {
            std::string word;
            in >> word;
            double v = 0;
            if (!real_number(word, v) || !(v >= 0) || !std::isfinite(v))
                throw std::runtime_error(where + "seconds: expected a number of seconds >= 0");
            a.seconds = v;
        } else if (key == "precision") {
            a.precision = rest_of_line(in);
            if (const std::string why = precision_problem(a.precision); !why.empty())
                throw std::runtime_error(where + "precision: expected " + why);
        } else if (key == "version") {
            a.version = rest_of_line(in);
        } else if (key == "refuse") {
            a.refusal = rest_of_line(in);
            if (a.refusal.empty()) throw std::runtime_error(where + "refuse: expected the reason after the word");
        } else {
            throw std::runtime_error(where + "unknown key '" + printable_tail(key, 40) +
                                     "' (expected times, steps, contacts, seconds, precision, version or refuse)");
        }
    }
    return a;
}

class ExternalSolver : public Solver {
public:
    explicit ExternalSolver(ExternalSolverSpec spec) : spec_(std::move(spec)), files_sha256_(solver_files_digest(spec_)) {}

    std::string name() const override { return spec_.name; }

    void load(const Scene& scene, const ParticleState<double>& initial) override {
        if (initial.size() == 0) throw std::invalid_argument(spec_.name + ": the scene has no disks");
        scene_ = scene;
        state_ = initial;
        time_ = 0;
        planned_.clear();
        computed_.clear();
        stats_ = SolverStats{};
        calls_ = 0;
    }

    void plan_outputs(const std::vector<double>& times) override { planned_ = times; }

    void advance_to(double t) override {
        check_target_time(spec_.name, t, time_, scene_.run.dt, false);
        if (t == time_) return;
        if (!computed_.count(t)) call(times_for(t));
        const std::vector<double>& row = computed_.at(t);
        for (std::size_t i = 0; i < state_.size(); ++i) {
            state_.x[i] = row[4 * i];
            state_.y[i] = row[4 * i + 1];
            state_.vx[i] = row[4 * i + 2];
            state_.vy[i] = row[4 * i + 3];
        }
        time_ = t;
        // The states before t are no longer needed (times never decrease).
        computed_.erase(computed_.begin(), computed_.upper_bound(t));
    }

    void read_state(ParticleState<double>& out) const override { out = state_; }
    double time() const override { return time_; }
    SolverStats stats() const override { return stats_; }

    std::map<std::string, std::string> provenance() const override {
        std::map<std::string, std::string> p;
        p["solver_command"] = spec_.command;
        p["solver_protocol"] = std::to_string(protocol_version);
        if (!spec_.directory.empty()) p["solver_directory"] = spec_.directory;
        if (!spec_.python_class.empty()) p["solver_python_class"] = spec_.python_class;
        if (!spec_.rule.empty()) p["solver_rule"] = spec_.rule;
        if (spec_.exact) p["solver_exact"] = "true";
        p["solver_precision"] = spec_.computed_precision();
        if (!version_.empty()) p["solver_version"] = version_;
        if (!files_sha256_.empty()) p["solver_files_sha256"] = files_sha256_;
        if (spec_.handles) p["solver_handles"] = join_words(*spec_.handles);
        if (spec_.long_lived) p["solver_long_lived"] = "true";
        return p;
    }

private:
    // One call covers every planned time from t on when t is planned (one program run per
    // case), else t alone (a warm-up run, a replay step).
    std::vector<double> times_for(double t) const {
        if (std::find(planned_.begin(), planned_.end(), t) == planned_.end()) return {t};
        std::vector<double> times;
        for (double p : planned_)
            if (p >= t) times.push_back(p);
        return times;
    }

    [[noreturn]] void fault(const std::string& what) const {
        std::ostringstream msg;
        msg << "solver '" << spec_.name << "', scene " << scene_.name << " (seed " << scene_.seed << ", dt "
            << round_trip_text(scene_.run.dt) << "), call " << calls_ << " from t = "
            << round_trip_text(time_) << ": " << what;
        throw std::runtime_error(msg.str());
    }

    // How a program call ended: its wall time, what it printed, and "" or the fault.
    struct CallEnd {
        double seconds = 0;
        std::string output;
        std::string problem;
    };

    // A one-shot call: the program started for this request alone, its exit status the reply.
    CallEnd call_once(const TemporaryDirectory& dir) const {
        const ProgramOutcome outcome = call_program(spec_.command, dir.path(), program_directory(), dir.file("output.txt"),
                                                    spec_.call_time_limit);
        CallEnd end{outcome.seconds, read_text(dir.file("output.txt"), max_result_bytes), ""};
        if (!outcome.succeeded()) end.problem = outcome.describe(spec_.call_time_limit);
        return end;
    }

    // A long-lived solver's call: this process's idle server of the command, started when there
    // is none (or the last one ended); given back for the next call while it lives.
    CallEnd call_server(const TemporaryDirectory& dir) {
        std::unique_ptr<SolverServer> server = take_idle_server(spec_.command, program_directory());
        if (!server) server = std::make_unique<SolverServer>(spec_.command, program_directory());
        const ServedCall served = server->call(dir.path(), spec_.call_time_limit);
        if (served.started) stats_.counters["server_starts"] += 1;
        if (server->alive()) give_back_server(spec_.command, program_directory(), std::move(server));
        return {served.process.seconds, served.output, served.problem(spec_.call_time_limit)};
    }

    std::string program_directory() const { return spec_.directory.empty() ? "." : spec_.directory; }

    void call(const std::vector<double>& times) {
        const TemporaryDirectory dir = request_directory();
        write_request_file(dir.file("request.txt"), request_text(spec_, scene_, state_.size(), time_, times));
        write_request_file(dir.file("initial.npy"), state_npy(state_));
        write_request_file(dir.file("scene.toml"), scene_.source_text);
        const CallEnd end = spec_.long_lived ? call_server(dir) : call_once(dir);
        ++calls_;
        stats_.counters["program_calls"] += 1;
        stats_.counters["program_seconds"] += end.seconds;
        forward_to_log(end.output);
        if (!end.problem.empty()) fault(end.problem + quoted(end.output));
        if (const std::string problem = answer_file_problem(dir.file("result.txt"), "result.txt"); !problem.empty())
            fault((spec_.long_lived ? "it answered done but " : "it exited with status 0 but ") + problem + quoted(end.output));
        Answer answer;
        try {
            answer = parse_answer(read_text(dir.file("result.txt"), max_result_bytes));
        } catch (const std::exception& e) {
            fault(e.what());
        }
        if (!answer.version.empty()) version_ = answer.version;
        // The limits it is judged by follow from the precision it declared: an answer computed
        // in another one would be judged by the wrong limits.
        if (!answer.precision.empty() && answer.precision != spec_.computed_precision())
            fault("result.txt says precision " + answer.precision + ", but the solver is declared " + spec_.computed_precision() +
                  " (declare it: precision = \"" + answer.precision + "\" in its [solver] table, --solver-precision " +
                  spec_.name + "=" + answer.precision + ", or the class's `precision` attribute)");
        if (!answer.refusal.empty()) throw SceneRefused(spec_.name + " refuses this scene: " + answer.refusal);
        check_times(answer, times);
        store(dir.file("states.npy"), times);
        stats_.steps += answer.steps;
        stats_.contacts += answer.contacts;
        // Whether every call so far counted its contacts: without them the collision rate of the
        // case is unknown, and left out (docs/your-solver.md, "contacts").
        stats_.counters["contacts_reported"] = (calls_ == 1 || stats_.counters["contacts_reported"] > 0) && answer.has_contacts;
        if (answer.seconds) stats_.counters["solver_seconds"] += *answer.seconds;
        else stats_.counters["solver_seconds_missing"] = 1;
    }

    std::string quoted(const std::string& output) const {
        if (output.empty()) return "; it printed nothing";
        return "; the end of its output: " + printable_tail(output, quoted_output_chars);
    }

    // The program's own words go to the case's log as they are (never into the report).
    void forward_to_log(const std::string& output) const {
        if (output.empty()) return;
        std::fprintf(stderr, "--- output of solver '%s' (call %d) ---\n", spec_.name.c_str(), calls_);
        std::fwrite(output.data(), 1, output.size(), stderr);
        std::fprintf(stderr, "\n--- end of output ---\n");
    }

    void check_times(const Answer& answer, const std::vector<double>& times) const {
        if (!answer.has_times) fault("result.txt has no 'times' line (the output times it computed)");
        if (answer.times.size() != times.size())
            fault("result.txt lists " + std::to_string(answer.times.size()) + " output times, expected " +
                  std::to_string(times.size()) + ":" + times_text(times));
        // Equal up to rounding: a stepper that sums t += dt reaches 0.30000000000000004.
        const double tolerance = 1e-9 * std::max(scene_.run.duration, std::fabs(times.back()));
        for (std::size_t k = 0; k < times.size(); ++k)
            if (!(std::fabs(answer.times[k] - times[k]) <= tolerance))
                fault("result.txt: output time " + std::to_string(k) + " is " + round_trip_text(answer.times[k]) +
                      ", expected " + round_trip_text(times[k]) + " (the state for the wrong time)");
    }

    void store(const std::string& path, const std::vector<double>& times) {
        if (const std::string problem = answer_file_problem(path, "states.npy"); !problem.empty()) fault(problem);
        NpyArray states;
        // The request fixes the answer's shape, and so its size: (output times, disks, [x, y, vx, vy]).
        const std::vector<std::size_t> expected = {times.size(), state_.size(), 4};
        try {
            states = read_npy(path, expected);
        } catch (const NpyError& e) {
            std::string what = e.what();  // without the request directory's path: it is gone after the call
            if (what.rfind(path + ": ", 0) == 0) what.erase(0, path.size() + 2);
            fault("states.npy: " + what + (what.rfind("shape", 0) == 0 ? " (output times, disks, [x, y, vx, vy])" : ""));
        }
        const std::size_t row = 4 * state_.size();
        for (std::size_t k = 0; k < times.size(); ++k) {
            const auto begin = states.data.begin() + std::ptrdiff_t(k * row);
            const auto bad = std::find_if(begin, begin + std::ptrdiff_t(row), [](double v) { return !std::isfinite(v); });
            if (bad != begin + std::ptrdiff_t(row)) {
                const std::size_t at = std::size_t(bad - begin);
                static const char* const column[] = {"x", "y", "vx", "vy"};
                fault("states.npy holds " + round_trip_text(*bad) + " (NaN/Inf) at t = " + round_trip_text(times[k]) +
                      ", disk " + std::to_string(at / 4) + ", " + column[at % 4]);
            }
            computed_[times[k]].assign(begin, begin + std::ptrdiff_t(row));
        }
    }

    ExternalSolverSpec spec_;
    std::string files_sha256_;  // the files a run's provenance names (solver_files.h)
    Scene scene_;
    ParticleState<double> state_;
    double time_ = 0;
    std::vector<double> planned_;
    std::map<double, std::vector<double>> computed_;  // output time -> x, y, vx, vy of every disk
    SolverStats stats_;
    std::string version_;
    int calls_ = 0;
};

}  // namespace

const std::vector<std::string>& solver_capabilities() {
    static const std::vector<std::string> all = {"walls", "periodic", "restitution", "friction", "gravity", "damping", "stones"};
    return all;
}

std::string capabilities_text() { return join_words(solver_capabilities()); }

std::vector<std::string> scene_needs(const Scene& scene) {
    std::vector<std::string> needs = {scene.periodic() ? "periodic" : "walls"};
    if (scene.physics.restitution != 1 || scene.physics.wall_restitution != 1) needs.push_back("restitution");
    if (scene.has_friction()) needs.push_back("friction");
    if (scene.has_gravity()) needs.push_back("gravity");
    if (scene.has_damping()) needs.push_back("damping");
    const bool stones = std::any_of(scene.generators.begin(), scene.generators.end(), [](const ParticleGenerator& g) {
        return g.stone || std::any_of(g.disks.begin(), g.disks.end(), [](const auto& d) { return d.stone; });
    });
    if (stones) needs.push_back("stones");
    return needs;
}

std::string handles_problem(const std::vector<std::string>& handles) {
    const auto& known = solver_capabilities();
    for (std::size_t i = 0; i < handles.size(); ++i) {
        if (std::find(known.begin(), known.end(), handles[i]) == known.end())
            return "capabilities from " + capabilities_text() + ", not \"" + printable_tail(handles[i], 40) + "\"";
        if (std::find(handles.begin(), handles.begin() + std::ptrdiff_t(i), handles[i]) != handles.begin() + std::ptrdiff_t(i))
            return "each capability once (\"" + handles[i] + "\" is named twice)";
    }
    return "";
}

std::string unhandled_need(const ExternalSolverSpec& spec, const Scene& scene) {
    if (!spec.handles) return "";
    std::vector<std::string> missing;
    for (const std::string& need : scene_needs(scene))
        if (std::find(spec.handles->begin(), spec.handles->end(), need) == spec.handles->end()) missing.push_back(need);
    if (missing.empty()) return "";
    return spec.name + " declares that it handles " + (spec.handles->empty() ? "nothing" : join_words(*spec.handles)) +
           "; the scene needs " + join_words(missing) + " too (handles = [...] in its [solver] table)";
}

std::string request_root_problem() {
    const std::string root = request_root();
    const std::string named = std::getenv("TMPDIR") && *std::getenv("TMPDIR") ? "TMPDIR=" + root : root;
    const std::string advice = "; set TMPDIR to an absolute path of a writable directory, or unset it for /tmp";
    if (fs::path(root).is_relative())
        return named + ": outside solvers get their request directories there, and a relative path would name "
                       "another place in the solver's own directory" + advice;
    struct stat st {};
    if (::stat(root.c_str(), &st) != 0)
        return named + ": outside solvers get their request directories there, and it " +
               (errno == ENOENT ? std::string("does not exist") : std::string(std::strerror(errno))) + advice;
    if (!S_ISDIR(st.st_mode))
        return named + ": outside solvers get their request directories there, and it is " + path_causes::kind_of(st.st_mode) +
               ", not a directory" + advice;
    if (::access(root.c_str(), W_OK | X_OK) != 0)
        return named + ": outside solvers get their request directories there, and it cannot be written (" +
               std::strerror(errno) + ")" + advice;
    return "";
}

std::string solver_name_problem(const std::string& name) {
    if (name.empty() || name.size() > 40 || name.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_-") != std::string::npos ||
        name[0] == '-')
        return "a solver name of 1 to 40 lower-case letters, digits, _ or - (it becomes part of file names), not '" +
               printable_tail(name, 60) + "'";
    return "";
}

std::string rule_problem(const std::string& rule) {
    if (rule.empty() || rule == "collide-first" || rule == "integrate-first") return "";
    return "\"collide-first\" or \"integrate-first\" (the stepping rule it implements), not \"" + rule + "\"";
}

std::string precision_problem(const std::string& precision) {
    if (precision.empty() || precision == "double" || precision == "float") return "";
    return "\"double\" or \"float\" (the precision it computes in), not \"" + printable_tail(precision, 40) + "\"";
}

std::string long_lived_problem(const ExternalSolverSpec& spec) {
    if (spec.long_lived && !spec.python_class.empty())
        return "a program (command = \"...\"): a Python class runs through its runner, which is started once per call";
    return "";
}

std::string claims_problem(bool exact, const std::string& rule) {
    if (exact && !rule.empty())
        return "exact together with rule \"" + rule + "\": an exact solver has no time step, a stepping rule has one; "
               "declare one of them";
    return "";
}

std::string spec_problem(const ExternalSolverSpec& spec) {
    if (std::string why = solver_name_problem(spec.name); !why.empty()) return "expected " + why;
    if (spec.command.empty() == spec.python_class.empty())
        return "expected either a command (a program) or a Python class (\"module:Class\"), not both or neither";
    if (!spec.python_class.empty() && spec.python_class.find(':') == std::string::npos)
        return "python: expected \"module:Class\" or \"file.py:Class\", not \"" + spec.python_class + "\"";
    if (std::string why = rule_problem(spec.rule); !why.empty()) return "rule: expected " + why;
    if (std::string why = precision_problem(spec.precision); !why.empty()) return "precision: expected " + why;
    if (spec.handles)
        if (std::string why = handles_problem(*spec.handles); !why.empty()) return "handles: expected " + why;
    if (std::string why = long_lived_problem(spec); !why.empty()) return "long_lived: expected " + why;
    return claims_problem(spec.exact, spec.rule);
}

ExternalSolverSpec parse_solver_option(const std::string& text) {
    const auto eq = text.find('=');
    if (eq == std::string::npos)
        throw std::invalid_argument("--solver " + text + ": expected NAME=COMMAND, e.g. mine='python3 my_solver.py'");
    ExternalSolverSpec spec;
    spec.name = text.substr(0, eq);
    spec.command = text.substr(eq + 1);
    spec.origin = "--solver " + text;
    if (const std::string why = solver_name_problem(spec.name); !why.empty())
        throw std::invalid_argument("--solver " + text + ": expected " + why);
    if (spec.command.find_first_not_of(" \t") == std::string::npos)
        throw std::invalid_argument("--solver " + text + ": expected a command after '='");
    return spec;
}

std::unique_ptr<Solver> make_external_solver(const ExternalSolverSpec& spec) {
    return std::make_unique<ExternalSolver>(spec);
}

BackendInfo external_backend(const ExternalSolverSpec& spec) {
    BackendInfo info;
    info.name = spec.name;
    info.precision = spec.computed_precision();
    info.exact = spec.exact;
    info.rule = spec.rule;
    if (spec.exact) info.conserves = {"momentum", "energy"};
    else if (!spec.rule.empty()) info.conserves = {"momentum"};
    info.description = "outside solver: " + (spec.python_class.empty() ? spec.command : spec.python_class);
    // Declared capabilities leave a scene out before any program call; without them, every scene
    // goes to the program, which may refuse it.
    info.supports = [spec](const Scene& scene) -> std::optional<std::string> {
        if (std::string why = unhandled_need(spec, scene); !why.empty()) return why;
        return std::nullopt;
    };
    info.create = [spec](const BackendOptions&) { return make_external_solver(spec); };
    return info;
}

}  // namespace collide::external
