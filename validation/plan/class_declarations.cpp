#include "validation/plan/class_declarations.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/text/printable.h"
#include "core/io/shell_quote.h"
#include "core/io/temporary_directory.h"
#include "external/program_call.h"

namespace collide::validation {
namespace fs = std::filesystem;
namespace {

// Loading a class imports its module (and NumPy): seconds at most.
constexpr double load_time_limit = 60;

// A directory of its own for the runner's answer, removed with it.
TemporaryDirectory answer_directory() {
    try {
        return TemporaryDirectory(fs::temp_directory_path(), "collide-declarations", "a directory");
    } catch (const std::runtime_error& e) {
        throw SuiteError(e.what());
    }
}

std::string file_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// Takes the class's value of one declaration: the suite's or command line's, where given, must agree.
void merge(std::string& declared, const std::string& by_class, const std::string& key, const std::string& where) {
    if (by_class.empty()) return;
    if (!declared.empty() && declared != by_class)
        throw SuiteError(where + ": " + key + " \"" + declared + "\" is declared for it, but the class declares " + key +
                         " = \"" + by_class + "\"; declare it once");
    declared = by_class;
}

}  // namespace

void add_class_declarations(external::ExternalSolverSpec& spec, const PythonRunner& python) {
    if (spec.python_class.empty()) return;
    const std::string where = spec.origin + ": class " + spec.python_class;
    const TemporaryDirectory dir = answer_directory();
    const std::string command =
        shell_quote(python.python) + " " + shell_quote(python.runner) + " --declarations " + shell_quote(spec.python_class);
    const external::ProgramOutcome outcome = external::call_program(
        command, dir.file("declarations.txt"), spec.directory.empty() ? "." : spec.directory, dir.file("output.txt"),
        load_time_limit);
    if (!outcome.succeeded())
        throw SuiteError(where + ": could not load it to read its declarations (" + outcome.describe(load_time_limit) +
                         "): " + printable_tail(file_text(dir.file("output.txt")), 600));
    std::istringstream lines(file_text(dir.file("declarations.txt")));
    std::string key, value, exact;
    std::string rule, precision;
    while (lines >> key && std::getline(lines >> std::ws, value)) {
        if (key == "exact") exact = value;
        else if (key == "rule") rule = value;
        else if (key == "precision") precision = value;
    }
    if (!exact.empty() && exact != "true" && exact != "false")
        throw SuiteError(where + ": its attribute exact: expected True or False, not " + exact);
    if (const std::string why = external::rule_problem(rule); !why.empty())
        throw SuiteError(where + ": its attribute rule: expected " + why);
    if (const std::string why = external::precision_problem(precision); !why.empty())
        throw SuiteError(where + ": its attribute precision: expected " + why);
    merge(spec.rule, rule, "rule", where);
    merge(spec.precision, precision, "precision", where);
    if (exact == "false" && spec.exact)
        throw SuiteError(where + ": it is declared exact, but the class declares exact = False; declare it once");
    spec.exact = spec.exact || exact == "true";
    if (const std::string why = external::claims_problem(spec.exact, spec.rule); !why.empty())
        throw SuiteError(where + ": " + why);
}

}  // namespace collide::validation
