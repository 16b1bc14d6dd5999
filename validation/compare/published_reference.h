// Published physics the report holds the reference solver against: equations of state, exact
// collision counts, the constants of a kinetic-theory law, each with its citation. The values
// live in data/references/NAME.toml (one file per reference, format in docs/validation.md,
// "Reference against physics"), never in code, so a reader can check every number against
// the paper it came from.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace collide::validation {

// One term c eta^a / (1 - eta)^b of an equation of state Z(eta). Henderson's form and Kolafa
// & Rottner's series in x = eta / (1 - eta) are both sums of such terms.
struct EquationOfStateTerm {
    double coefficient = 0;
    int eta_power = 0;
    int one_minus_eta_power = 0;
};

// One published pressure at finite N (quantity "beta_pressure_d2": li_2022.toml, engel_2013.toml):
// at this N, in this box, the pressure beta P d^2 (d the diameter) and its standard error. The
// box matters at 1e-5: the same N and eta in another box shape is another number.
struct FiniteNPoint {
    std::string id;             // what a suite's `published = "KEY:ID"` names
    std::string method;         // the row's own method where the file mixes them ("" otherwise)
    long long disks = 0;        // N
    std::string box;            // width : height as the paper writes it, "9 : 8 sqrt(3)/2"
    double aspect_ratio = 0;    // height / width
    std::string boundary;       // "periodic"
    double eta = 0;             // area fraction N pi r^2 / A
    double beta_pressure_d2 = 0, standard_error = 0;
    int line = 0;               // in the reference file
};

struct PublishedReference {
    std::string key;       // the file's stem, e.g. "kolafa_rottner_2006"
    std::string name;      // "Kolafa & Rottner (2006)"
    std::string citation;
    std::string quantity;  // "compressibility_factor", "collision_count", ...
    std::string source_path;
    std::vector<EquationOfStateTerm> terms;            // compressibility_factor
    double valid_below = 1;                            // compressibility_factor: largest eta
    std::map<double, long long> counts;                // collision_count: parameter -> count
    std::map<std::string, double> numbers;             // other constants (bins, uncertainties)
    std::map<std::string, std::string> texts;          // other strings (equation_of_state)
    std::vector<FiniteNPoint> finite_n;                // beta_pressure_d2: the [[rows]]

    double number(const std::string& name) const;      // throws naming the file when missing
    std::string text(const std::string& name) const;
    // The [[rows]] entry with this id; throws naming the file, the id and the ids there are.
    const FiniteNPoint& finite_n_point(const std::string& id) const;
};

// Reads data/references/KEY.toml from `directory`; throws std::runtime_error naming the file,
// the line and what was expected.
PublishedReference load_reference(const std::string& directory, const std::string& key);

// Z(eta) of an equation-of-state reference: the sum of its terms. Throws for eta outside
// [0, valid_below].
double compressibility_factor(const PublishedReference& eos, double eta);

// The contact value of the pair distribution from Z by the 2-D contact theorem
// Z = 1 + 2 eta g(sigma) (eta the area fraction).
double contact_value(double compressibility, double eta);

// Enskog's collision rate per disk, nu = 2 rho sigma g(sigma) sqrt(pi kT / m) (2-D).
double enskog_collision_rate(double number_density, double sigma, double contact_value, double kt_over_m);

}  // namespace collide::validation
