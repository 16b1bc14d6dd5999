#include "validation/compare/published_reference.h"
#include "core/io/input_file.h"
#include "core/scene/toml_fields.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <toml++/toml.h>

namespace collide::validation {
namespace {

[[noreturn]] void fail(const std::string& file, const toml::node* node, const std::string& what) {
    std::ostringstream msg;
    msg << file;
    if (node && node->source().begin.line) msg << ":" << node->source().begin.line;
    msg << ": " << what;
    throw std::runtime_error(msg.str());
}

std::string required_string(const toml::table& t, const std::string& file, const char* key) {
    const toml::node* n = t.get(key);
    if (!n || !n->is_string()) fail(file, n ? n : nullptr, std::string(key) + ": expected a string");
    return *n->value<std::string>();
}

double finite_number(const toml::node& n, const std::string& file, const std::string& key) {
    const auto v = n.value<double>();
    if (!v || !std::isfinite(*v)) fail(file, &n, key + ": expected a finite number");
    return *v;
}

int small_power(const toml::table& t, const std::string& file, const char* key) {
    const toml::node* n = t.get(key);
    const auto v = n ? n->value<std::int64_t>() : std::nullopt;
    if (!v || *v < 0 || *v > 200) fail(file, n, std::string(key) + ": expected an integer in [0, 200]");
    return int(*v);
}

void read_terms(const toml::array& terms, const std::string& file, PublishedReference& ref) {
    for (const auto& node : terms) {
        const toml::table* t = node.as_table();
        if (!t) fail(file, &node, "terms: expected tables { coefficient, eta_power, one_minus_eta_power }");
        const toml::node* c = t->get("coefficient");
        if (!c) fail(file, &node, "terms: a term has no coefficient");
        ref.terms.push_back({finite_number(*c, file, "coefficient"), small_power(*t, file, "eta_power"),
                             small_power(*t, file, "one_minus_eta_power")});
    }
}

void read_points(const toml::array& points, const std::string& file, PublishedReference& ref) {
    for (const auto& node : points) {
        const toml::table* t = node.as_table();
        const toml::node* ratio = t ? t->get("mass_ratio") : nullptr;
        const toml::node* count = t ? t->get("collisions") : nullptr;
        if (!ratio || !count || !count->is_integer())
            fail(file, &node, "points: expected tables { mass_ratio = NUMBER, collisions = INTEGER }");
        ref.counts[finite_number(*ratio, file, "mass_ratio")] = *count->value<std::int64_t>();
    }
}

// One [[rows]] table of a beta_pressure_d2 file, read by the scene files' strict reader
// (TomlFields): every key required (method optional), each of its type and range, no other key;
// errors name the file, the line and rows[K].key.
FiniteNPoint read_finite_n_point(const toml::table& table, const std::string& file, std::size_t k) {
    const TomlFields t(table, "rows[" + std::to_string(k) + "]", file);
    t.allow_only({"id", "method", "disks", "box", "aspect_ratio", "boundary", "eta", "beta_pressure_d2", "standard_error"});
    auto text = [&](const char* key) {
        const std::string v = t.string(key);
        t.require(!v.empty(), key, "a non-empty string");
        return v;
    };
    auto positive = [&](const char* key) {
        const double v = t.number(key);
        t.require(v > 0, key, "a positive number");
        return v;
    };
    FiniteNPoint p;
    p.id = text("id");
    if (t.has("method")) p.method = text("method");
    p.disks = t.integer("disks");
    t.require(p.disks >= 1, "disks", "an integer N >= 1");
    p.box = text("box");
    p.aspect_ratio = positive("aspect_ratio");
    p.boundary = t.choice("boundary", {"periodic", "reflect"}, "");  // required: no fallback
    p.eta = positive("eta");
    // Above close packing no configuration exists.
    t.require(p.eta < M_PI / (2 * std::sqrt(3.0)), "eta", "an area fraction below close packing pi / (2 sqrt 3)");
    p.beta_pressure_d2 = positive("beta_pressure_d2");
    p.standard_error = positive("standard_error");
    p.line = t.line();
    return p;
}

void read_finite_n_rows(const toml::array& rows, const std::string& file, PublishedReference& ref) {
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const toml::table* t = rows[k].as_table();
        if (!t) fail(file, &rows[k], "rows[" + std::to_string(k) + "]: expected a [[rows]] table");
        FiniteNPoint p = read_finite_n_point(*t, file, k);
        for (const FiniteNPoint& q : ref.finite_n)
            if (q.id == p.id) fail(file, t, "rows[" + std::to_string(k) + "].id: \"" + p.id + "\" is also the id of the row at line " + std::to_string(q.line));
        ref.finite_n.push_back(std::move(p));
    }
}

}  // namespace

const FiniteNPoint& PublishedReference::finite_n_point(const std::string& id) const {
    std::string ids;
    for (const FiniteNPoint& p : finite_n) {
        if (p.id == id) return p;
        ids += (ids.empty() ? "" : ", ") + p.id;
    }
    throw std::runtime_error(source_path + ": no row with id \"" + id + "\" (the rows: " + (ids.empty() ? "none" : ids) + ")");
}

double PublishedReference::number(const std::string& n) const {
    const auto it = numbers.find(n);
    if (it == numbers.end()) throw std::runtime_error(source_path + ": " + n + ": expected a number");
    return it->second;
}

std::string PublishedReference::text(const std::string& n) const {
    const auto it = texts.find(n);
    if (it == texts.end()) throw std::runtime_error(source_path + ": " + n + ": expected a string");
    return it->second;
}

PublishedReference load_reference(const std::string& directory, const std::string& key) {
    const std::string file = (std::filesystem::path(directory) / (key + ".toml")).string();
    std::string text;
    try {  // the input guard (core/io/input_file.h)
        text = read_input_file(file, 1u << 20);
    } catch (const InputFileError& e) {
        throw std::runtime_error(file + ": cannot open the published reference '" + key + "': " + e.cause());
    }
    toml::table root;
    try {
        root = toml::parse(text, file);
    } catch (const toml::parse_error& e) {
        throw std::runtime_error(file + ":" + std::to_string(e.source().begin.line) + ": not valid TOML: " +
                                 std::string(e.description()));
    }
    PublishedReference ref;
    ref.key = key;
    ref.source_path = file;
    ref.name = required_string(root, file, "name");
    ref.citation = required_string(root, file, "citation");
    ref.quantity = required_string(root, file, "quantity");
    for (const auto& [k, node] : root) {
        const std::string name(k.str());
        if (name == "terms" && node.is_array()) read_terms(*node.as_array(), file, ref);
        else if (name == "points" && node.is_array()) read_points(*node.as_array(), file, ref);
        else if (name == "rows" && node.is_array()) read_finite_n_rows(*node.as_array(), file, ref);
        else if (node.is_number()) ref.numbers[name] = finite_number(node, file, name);
        else if (node.is_string()) ref.texts[name] = *node.value<std::string>();
        else fail(file, &node, name + ": expected a number, a string, `terms`, `points` or `[[rows]]`");
    }
    if (ref.numbers.count("valid_below")) ref.valid_below = ref.numbers.at("valid_below");
    if (ref.quantity == "compressibility_factor" && ref.terms.empty()) fail(file, nullptr, "terms: expected at least one term");
    if (ref.quantity == "collision_count" && ref.counts.empty()) fail(file, nullptr, "points: expected at least one point");
    if (ref.quantity == "beta_pressure_d2" && ref.finite_n.empty()) fail(file, nullptr, "rows: expected at least one [[rows]] table");
    return ref;
}

double compressibility_factor(const PublishedReference& eos, double eta) {
    if (!(eta >= 0 && eta <= eos.valid_below))
        throw std::runtime_error(eos.source_path + ": area fraction " + std::to_string(eta) +
                                 " is outside the range of " + eos.name + " (0 to " + std::to_string(eos.valid_below) + ")");
    double z = 0;
    for (const EquationOfStateTerm& t : eos.terms)
        z += t.coefficient * std::pow(eta, t.eta_power) / std::pow(1 - eta, t.one_minus_eta_power);
    return z;
}

double contact_value(double compressibility, double eta) { return (compressibility - 1) / (2 * eta); }

double enskog_collision_rate(double number_density, double sigma, double contact, double kt_over_m) {
    return 2 * number_density * sigma * contact * std::sqrt(M_PI * kt_over_m);
}

}  // namespace collide::validation
