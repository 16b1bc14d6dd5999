// The extension module collide._collide: the scene reader, the backend registry, the run
// driver and the suite runner of the C++ code, bound for Python (docs/python.md). Nothing here
// computes physics; python/collide/__init__.py adds the few conveniences written in Python.
#include <unistd.h>

#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>
#include <tuple>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "core/io/progress_line.h"
#include "core/io/output_file.h"
#include "core/io/provenance.h"
#include "core/io/run_export.h"
#include "core/io/run_reader.h"
#include "core/run_driver.h"
#include "core/scene/scene_loader.h"
#include "core/scene/scene_overrides.h"
#include "core/scene/toml_fields.h"
#include "core/numerics/state_hash.h"
#include "path_argument.h"
#include "scene_from_dict.h"
#include "simulation.h"
#include "statistics.h"
#include "structure.h"
#include "validation/record/case_result.h"
#include "validation/plan/external_solvers.h"
#include "validation/suite_runner.h"

namespace py = pybind11;

namespace collide::python {
namespace {

// Thrown out of run_scene's output callback when Ctrl-C was pressed: unwinds the run (the
// RunWriter is destroyed uncommitted, so no half-written file is left) back to Python.
struct Interrupted {};

py::dict run(const Scene& given, const std::string& backend_name, const PathArgument& out, bool frames,
             bool progress, const py::kwargs& options) {
    Scene scene = given;  // with the keyword options in its [backend.NAME] table
    const BackendOptions backend_settings = backend_options(options, backend_name, scene);
    const BackendInfo& backend = backend_for(scene, backend_name);
    const ParticleState<double> initial = generate_initial_state(scene);
    auto solver = backend.create(backend_settings);
    std::unique_ptr<RunWriter> writer;
    if (!out.text.empty()) writer = std::make_unique<RunWriter>(out, frames);

    std::unique_ptr<ProgressLine> line;
    if (progress) line = std::make_unique<ProgressLine>(stderr);
    RunOptions run_options;
    run_options.writer = writer.get();
    run_options.on_output = [&line](double time, double duration) {
        if (line) line->update_time(time, duration);
        py::gil_scoped_acquire gil;
        if (PyErr_CheckSignals() != 0) throw Interrupted{};
    };
    RunResult result;
    try {
        py::gil_scoped_release release;
        result = run_scene(scene, *solver, initial, run_options);
        if (line) line->finish();
        if (writer) {
            writer->write_attributes(run_provenance(scene, backend.name, *solver));
            writer->commit();
        }
    } catch (const Interrupted&) {
        throw py::error_already_set();  // the KeyboardInterrupt PyErr_CheckSignals set
    }

    const py::dict metrics = metric_series_dict(result.series);

    const ParticleState<double>& s = result.final_state;
    py::dict d;
    d["metrics"] = metrics;
    d["positions"] = read_only_pairs(s.x, s.y);
    d["velocities"] = read_only_pairs(s.vx, s.vy);
    d["state_hash"] = state_hash(s);
    d["stats"] = stats_dict(result.stats);
    d["wall_seconds"] = result.wall_seconds;
    d["backend"] = backend.name;
    return d;
}

// One outside solver of validate(solvers=...), as python/collide/__init__.py's _solver_entry
// builds it: (name, command, "module:Class", rule, exact, precision, long_lived), the fields
// of external::ExternalSolverSpec that a suite's [solver.NAME] table and the CLI's options set.
using SolverEntry = std::tuple<std::string, std::string, std::string, std::string, bool, std::string, bool>;

// Runs the suite as `collide validate` does (progress on stderr); the caller reads summary.json.
// `solvers`: outside solvers, run by `runner` for a class; a class's own attributes are read
// with the suite's (class_declarations.h).
py::dict validate(const PathArgument& suite_path, const PathArgument& out, int jobs, bool resume,
                  const std::vector<SolverEntry>& solvers,
                  const validation::PythonRunner& runner) {
    if (jobs <= 0) jobs = validation::default_jobs();
    validation::Suite suite = validation::load_suite(suite_path);
    std::vector<external::ExternalSolverSpec> specs;
    for (const auto& [name, command, python_class, rule, exact, precision, long_lived] : solvers) {
        external::ExternalSolverSpec spec;
        spec.name = name;
        spec.command = command;
        spec.python_class = python_class;
        spec.rule = rule;
        spec.exact = exact;
        spec.precision = precision;
        spec.long_lived = long_lived;
        spec.origin = "solvers[\"" + name + "\"]";
        if (std::string problem = external::spec_problem(spec); !problem.empty())
            throw validation::SuiteError(spec.origin + ": " + problem);
        specs.push_back(spec);
    }
    validation::add_solvers(suite, specs);
    const auto backends = validation::backends_with_solvers(suite, all_backends(), runner);
    validation::RunnerOptions options;
    options.output_dir = out;
    options.jobs = jobs;
    options.resume = resume;
    options.progress = stderr;
    options.progress_is_terminal = ::isatty(STDERR_FILENO) != 0;
    validation::SuiteOutcome outcome;
    {
        py::gil_scoped_release release;  // the cases run in forked children that never touch Python
        outcome = validation::run_suite(suite, backends, options);
    }
    py::dict d;
    d["suite"] = suite.name;
    d["cases"] = outcome.cases.size();
    d["cases_run"] = outcome.cases_run;
    d["cases_resumed"] = outcome.cases_resumed;
    d["wall_seconds"] = outcome.wall_seconds;
    d["jobs"] = outcome.jobs;
    d["passed"] = outcome.count(validation::CheckStatus::pass);
    d["failed"] = outcome.count(validation::CheckStatus::fail);
    d["left_out"] = outcome.count(validation::CheckStatus::left_out);
    return d;
}

// "FILE:LINE: DETAIL" (split at the first ":DIGITS: ") or else "FILE: DETAIL" (at the first
// ": "): core/scene/toml_fields.h's location(). Read by hand, not by std::regex: libstdc++'s
// matcher recurses once per character, and a message quoting a 60,000-character path
// overflowed the stack.
struct LocatedMessage {
    std::optional<std::string> source;
    std::optional<int> line;
    std::string detail;
};

LocatedMessage split_located(const std::string& message) {
    for (std::size_t colon = message.find(':'); colon != std::string::npos; colon = message.find(':', colon + 1)) {
        const std::size_t end = message.find_first_not_of("0123456789", colon + 1);
        const std::size_t digits = end == std::string::npos ? 0 : end - colon - 1;
        if (digits > 0 && digits <= 9 && message.compare(end, 2, ": ") == 0)
            return {message.substr(0, colon), std::stoi(message.substr(colon + 1, digits)), message.substr(end + 2)};
    }
    const std::size_t separator = message.find(": ");
    if (separator == std::string::npos) return {std::nullopt, std::nullopt, message};
    return {message.substr(0, separator), std::nullopt, message.substr(separator + 2)};
}

// Raises `type` with the message and its parts as attributes: source, line (None without one)
// and detail (the key and what was expected).
void raise_located(const py::object& type, const std::string& message) {
    const LocatedMessage part = split_located(message);
    py::object error = type(message);
    error.attr("source") = part.source ? py::cast(*part.source) : py::none();
    error.attr("line") = part.line ? py::cast(*part.line) : py::none();
    error.attr("detail") = part.detail;
    PyErr_SetObject(type.ptr(), error.ptr());
}

// A Python value as TOML value text, for Scene.with_overrides: what `--set PATH=VALUE` would
// carry after the '='. A str is always a string (never parsed as TOML).
std::string toml_value(const py::handle& v) {
    if (py::isinstance<py::bool_>(v)) return v.cast<bool>() ? "true" : "false";
    if (py::isinstance<py::int_>(v)) return py::str(v).cast<std::string>();
    if (py::isinstance<py::float_>(v)) return py::repr(py::float_(py::reinterpret_borrow<py::object>(v))).cast<std::string>();
    if (py::isinstance<py::str>(v)) {
        std::string quoted = "\"";
        for (char c : v.cast<std::string>()) quoted += c == '"' || c == '\\' ? std::string("\\") + c : std::string(1, c);
        return quoted + "\"";
    }
    std::string text;
    if (py::isinstance<py::dict>(v)) {
        for (const auto& [key, value] : v.cast<py::dict>())
            text += (text.empty() ? "" : ", ") + py::str(key).cast<std::string>() + " = " + toml_value(value);
        return "{ " + text + " }";
    }
    if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) {
        for (const auto& item : v) text += (text.empty() ? "" : ", ") + toml_value(item);
        return "[" + text + "]";
    }
    throw py::type_error("with_overrides: " + py::repr(v).cast<std::string>() +
                         " is no TOML value (expected bool, int, float, str, list or dict)");
}

// Each value is first read under Scene.from_dict's rules (scene_from_dict.h), which bound its
// depth and refuse a container that holds itself, naming the key: toml_value recurses, and a
// dict 10^5 deep overflowed the stack.
Scene with_overrides(const Scene& scene, const py::dict& changes) {
    std::vector<SceneOverride> overrides;
    for (const auto& [key, value] : changes) {
        const std::string path = py::str(key).cast<std::string>();
        if (value.is_none()) throw py::type_error("with_overrides: " + shortened(path) + " = None: expected a TOML value");
        toml_value_from_python(value, shortened(path));
        overrides.push_back({path, toml_value(value)});
    }
    return scene_with_overrides(scene, overrides);
}

// XDMF and XYZ, written as `collide export` writes them; GSD is written in Python.
void export_run(const PathArgument& run, const PathArgument& out, const std::string& format) {
    const ExportFormat f = export_format(format, out);
    if (f == ExportFormat::gsd) throw std::invalid_argument("_export: gsd is written by collide.gsd_export");
    check_output_is_not_input(out, run);  // the program's command line does this by remembering its inputs
    if (f == ExportFormat::xdmf) {
        check_output_is_not_input(xdmf_frames_path(out), run);
        write_xdmf(run, out);
    } else {
        write_file_atomically(out, xyz_text(run));
    }
}

// What `collide export` checks before it writes: the output path (core/io/output_file.h) and the
// run file, every frame read through the checked reader (core/io/run_reader.h). Python's GSD
// writer calls it first, as the program does.
void check_export(const PathArgument& run, const PathArgument& out) {
    check_output_path(out);
    check_output_is_not_input(out, run);
    require_frames(run);
}

// A run file read back through the checked reader (core/io/run_reader.h): every check `collide
// render` and `collide report` make, then the columns of the run schema as NumPy arrays and the
// solver's statistics (/stats, as Simulation.stats() gives them). With
// `frames`, every frame as (T, N, 2) arrays (each checked as it is read).
py::dict read_run(const PathArgument& path, bool frames) {
    const RunFile run(path);
    py::dict attributes;
    for (const auto& [name, value] : run.root_attributes()) attributes[py::str(name)] = value;
    std::vector<Metrics> series;
    for (std::size_t k = 0; k < run.output_count(); ++k) series.push_back(run.metrics_at(k));
    const ParticleState<double>& constants = run.constants();
    py::dict particles;
    particles["radius"] = read_only_array(constants.radius);
    particles["mass"] = read_only_array(constants.mass);
    particles["inv_mass"] = read_only_array(constants.inv_mass);
    py::dict d;
    d["attributes"] = attributes;
    d["metrics"] = metric_series_dict(series);
    d["particles"] = particles;
    d["stats"] = stats_dict(run.stats());
    d["has_frames"] = run.has_frames();
    if (frames && !run.has_frames())
        throw std::invalid_argument(path.text + ": written without frames: rerun with frames=True (`collide run --frames`)");
    if (frames) {
        const auto t = py::ssize_t(run.output_count()), n = py::ssize_t(run.disk_count());
        py::array_t<double> position({t, n, py::ssize_t(2)}), velocity({t, n, py::ssize_t(2)});
        auto p = position.mutable_unchecked<3>();
        auto v = velocity.mutable_unchecked<3>();
        ParticleState<double> state;
        for (py::ssize_t k = 0; k < t; ++k) {
            run.read_frame(std::size_t(k), state);
            for (py::ssize_t i = 0; i < n; ++i) {
                const auto j = std::size_t(i);
                p(k, i, 0) = state.x[j], p(k, i, 1) = state.y[j];
                v(k, i, 0) = state.vx[j], v(k, i, 1) = state.vy[j];
            }
        }
        position.attr("flags").attr("writeable") = false;
        velocity.attr("flags").attr("writeable") = false;
        d["frame_times"] = read_only_array(run.frame_times());
        d["positions"] = position;
        d["velocities"] = velocity;
    }
    return d;
}

// None where the backend can run the scene, else its reason (BackendInfo::supports): lets a
// caller choose the backends for a scene without building a solver.
std::optional<std::string> refusal(const std::string& backend, const Scene& scene) {
    return find_backend(backend).supports(scene);
}

py::list backends() {
    py::list list;
    for (const BackendInfo& b : all_backends()) {
        py::dict d;
        d["name"] = b.name;
        d["precision"] = b.precision;
        d["description"] = b.description;
        list.append(d);
    }
    return list;
}

}  // namespace
}  // namespace collide::python

PYBIND11_MODULE(_collide, m) {
    using namespace collide;
    using namespace collide::python;
    m.doc() = "collide: 2D hard-disk collisions (the C++ solvers, scene reader and suite runner)";

    // Bad scene and suite files: ValueError subclasses whose text is the CLI's message, which
    // names the file, the line, the key and what was expected; the parts are attributes too.
    static py::exception<SceneError> scene_error(m, "SceneError", PyExc_ValueError);
    static py::exception<validation::SuiteError> suite_error(m, "SuiteError", PyExc_ValueError);
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const SceneError& e) {
            raise_located(scene_error, e.what());
        } catch (const validation::SuiteError& e) {
            raise_located(suite_error, e.what());
        }
    });

    // Provenance of the HDF5 files written from Python: the interpreter's command line.
    {
        static std::vector<std::string> args;
        static std::vector<char*> argv;
        args.push_back(py::module_::import("sys").attr("executable").cast<std::string>());
        for (const auto& a : py::module_::import("sys").attr("argv")) args.push_back(py::str(a).cast<std::string>());
        for (auto& a : args) argv.push_back(a.data());
        set_command_line(int(argv.size()), argv.data());
    }

    py::class_<Scene>(m, "Scene", "A scene (docs/scenes.md): read from a file, TOML text or a dict")
        .def_static("from_file", [](const PathArgument& path) { return load_scene(path); }, py::arg("path"),
                    "Reads a scene file, as `collide run` does")
        .def_static("from_toml", &parse_scene, py::arg("text"), py::arg("name") = "scene",
                    "Reads scene TOML text; `name` stands for the file name in messages")
        .def_static(
            "from_dict",
            [](const py::dict& d, const std::string& name) { return parse_scene(toml_text_from_dict(d), name); },
            py::arg("d"), py::arg("name") = "scene",
            "Reads a dict with the keys of a scene file (tables as dicts, [[particles]] as a list of dicts); a "
            "value with no TOML form raises TypeError or ValueError naming its key (docs/refusals.md)")
        .def_readonly("name", &Scene::name)
        .def_readonly("description", &Scene::description)
        .def_readonly("seed", &Scene::seed)
        .def_readonly("source_path", &Scene::source_path)
        .def_readonly("source_text", &Scene::source_text, "The scene's TOML text (for a dict: the text made from it)")
        .def_readonly("overrides", &Scene::overrides, "The with_overrides changes made to the file, \"PATH=VALUE; ...\"")
        .def("with_overrides", &with_overrides, py::arg("changes"),
             "This scene with keys of its file changed, as `collide run --set` does: {\"run.dt\": 2.5e-4, "
             "\"world.boundary\": \"periodic\"}; bad paths and values raise SceneError")
        .def_property_readonly("box", [](const Scene& s) {
            return py::make_tuple(s.world.xmin, s.world.ymin, s.world.xmax, s.world.ymax);
        })
        .def_property_readonly("periodic", &Scene::periodic)
        .def_property_readonly("duration", [](const Scene& s) { return s.run.duration; })
        .def_property_readonly("output_interval", [](const Scene& s) { return s.run.output_interval; })
        .def_property_readonly("dt", [](const Scene& s) { return s.run.dt; })
        .def("initial_state_hash", [](const Scene& s) { return state_hash(generate_initial_state(s)); },
             "The 64-bit FNV-1a hash of the generated initial state's bits (core/numerics/state_hash.h)")
        .def("__repr__", [](const Scene& s) { return "<collide.Scene '" + s.name + "'>"; });

    py::class_<Simulation>(m, "Simulation", "One scene on one backend; state read back as NumPy arrays (copies)")
        .def(py::init([](const Scene& given, const std::string& backend, const py::kwargs& options) {
                 Scene scene = given;  // with the keyword options in its [backend.NAME] table
                 const BackendOptions settings = backend_options(options, backend, scene);
                 return std::make_unique<Simulation>(scene, backend, settings);
             }),
             py::arg("scene"), py::arg("backend") = "event")
        .def("advance_to", &Simulation::advance_to, py::arg("t"),
             "Advances to absolute time t (stepped backends: to the nearest whole step). Refuses a t that is "
             "not finite, in the past or beyond 1e12 steps of dt (ValueError), and a state that became NaN/Inf "
             "(RuntimeError, with the CLI's words)")
        .def_property_readonly("time", &Simulation::time)
        .def_property_readonly("backend", &Simulation::backend)
        .def_property_readonly("scene", &Simulation::scene)
        .def("__len__", &Simulation::size)
        .def_property_readonly("positions", [](Simulation& s) { return read_only_pairs(s.state().x, s.state().y); })
        .def_property_readonly("velocities", [](Simulation& s) { return read_only_pairs(s.state().vx, s.state().vy); })
        .def_property_readonly("radii", [](Simulation& s) { return read_only_array(s.state().radius); })
        .def_property_readonly("masses", [](Simulation& s) { return read_only_array(s.state().mass); })
        .def("state_hash", [](Simulation& s) { return state_hash(s.state()); },
             "The hash of the current state's bits (core/numerics/state_hash.h)")
        .def("metrics", &Simulation::metrics)
        .def("stats", &Simulation::stats)
        .def("provenance", &Simulation::provenance)
        .def("__repr__", [](const Simulation& s) {
            return "<collide.Simulation '" + s.scene().name + "' on " + s.backend() + " at t = " + std::to_string(s.time()) + ">";
        });

    m.def("_run", &run, py::arg("scene"), py::arg("backend"), py::arg("out"), py::arg("frames"), py::arg("progress"));
    m.def("_read_run", &read_run, py::arg("path"), py::arg("frames"));
    m.def("_export", &export_run, py::arg("run"), py::arg("out"), py::arg("format"));
    m.def("_validate", [](const PathArgument& suite, const PathArgument& out, int jobs, bool resume,
                          const std::vector<SolverEntry>& solvers,
                          const PathArgument& python, const PathArgument& runner) {
        return validate(suite, out, jobs, resume, solvers, validation::PythonRunner{python, runner});
    }, py::arg("suite"), py::arg("out"), py::arg("jobs"), py::arg("resume"), py::arg("solvers"), py::arg("python"),
          py::arg("runner"));
    m.def("toml_from_dict", &toml_text_from_dict, py::arg("d"),
          "The TOML text Scene.from_dict reads (the lines its error messages name)");
    m.def("_check_export", &check_export, py::arg("run"), py::arg("out"));
    m.def("backends", &backends, "The backends compiled into this build: name, precision, description");
    m.def("refusal", &refusal, py::arg("backend"), py::arg("scene"),
          "None if `backend` can run `scene`, else why not (the reason Simulation would give)");
    m.def("build_provenance", &build_provenance, "Commit, compiler, flags and library versions of this build");
    bind_structure(m);
    bind_statistics(m);
}
