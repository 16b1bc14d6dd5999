#include "validation/explain/energy_jump.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <set>
#include <stdexcept>

#include "core/metrics.h"

namespace collide::validation {
namespace {

constexpr double contact_slack = 1e-6;  // relative: a pair at (r_i + r_j)(1 + slack) touches
constexpr double float_slack = 1e-6;    // of the box size: float positions read back in double
constexpr double rounding = 1e-9;       // of the rms speed: a smaller velocity change is no contact
constexpr double force_slack = 1e-3;    // of the forces' own change: how exactly a rule integrates them

double kinetic(const ParticleState<double>& p, std::size_t i) {
    if (p.is_stone(i)) return 0;  // a kinematic stone moves as prescribed and exchanges no energy
    return disk_kinetic_energy(p.mass[i], p.vx[i], p.vy[i]);
}

// Kinetic plus gravitational potential energy, m |v|^2 / 2 - m g.x.
double energy(const Scene& scene, const ParticleState<double>& p, std::size_t i) {
    if (p.is_stone(i)) return 0;
    return kinetic(p, i) - p.mass[i] * (scene.physics.gravity_x * p.x[i] + scene.physics.gravity_y * p.y[i]);
}

double total(const ParticleState<double>& p, double (*per_disk)(const ParticleState<double>&, std::size_t)) {
    double sum = 0;
    for (std::size_t i = 0; i < p.size(); ++i) sum += per_disk(p, i);
    return sum;
}

double total_energy(const Scene& scene, const ParticleState<double>& p) {
    double sum = 0;
    for (std::size_t i = 0; i < p.size(); ++i) sum += energy(scene, p, i);
    return sum;
}

// Component of a separation along one axis, the nearest image where the box is periodic.
double separation(double d, double length, bool periodic) {
    if (periodic) d -= length * std::round(d / length);
    return d;
}

double speed(const ParticleState<double>& p, std::size_t i) { return std::hypot(p.vx[i], p.vy[i]); }

// How far beyond touching a contact of disk i (and j) can have been seen in the step: what
// they travel in one dt, before or after it, plus the rounding of float positions.
double reach(const Scene& scene, const ParticleState<double>& before, const ParticleState<double>& after,
             std::size_t i) {
    const double travel = std::max(speed(before, i), speed(after, i)) * scene.run.dt;
    return travel + float_slack * std::max(scene.world.width(), scene.world.height());
}

bool within(const Scene& scene, const ParticleState<double>& p, std::size_t i, std::size_t j, double extra) {
    const bool periodic = scene.periodic();
    const double dx = separation(p.x[i] - p.x[j], scene.world.width(), periodic);
    const double dy = separation(p.y[i] - p.y[j], scene.world.height(), periodic);
    const double limit = (p.radius[i] + p.radius[j]) * (1 + contact_slack) + extra;
    return dx * dx + dy * dy <= limit * limit;
}

bool touching(const Scene& scene, const ParticleState<double>& before, const ParticleState<double>& after,
              std::size_t i, std::size_t j) {
    const double extra = reach(scene, before, after, i) + reach(scene, before, after, j);
    return within(scene, before, i, j, extra) || within(scene, after, i, j, extra);
}

// The reflecting walls disk i reaches in state p, allowing `extra` beyond touching.
void add_walls(const Scene& scene, const ParticleState<double>& p, std::size_t i, double extra,
               std::set<std::string>& out) {
    if (scene.periodic()) return;
    const double r = p.radius[i] * (1 + contact_slack) + extra;
    const World& w = scene.world;
    if (p.x[i] - r <= w.xmin) out.insert("left");
    if (p.x[i] + r >= w.xmax) out.insert("right");
    if (p.y[i] - r <= w.ymin) out.insert("bottom");
    if (p.y[i] + r >= w.ymax) out.insert("top");
}

// Whether a contact changed disk i's velocity in the step: the change beyond what gravity and
// damping alone give (dv = (g - gamma v) dt, to force_slack of itself), above rounding.
bool contact_changed(const Scene& scene, const ParticleState<double>& before, const ParticleState<double>& after,
                     std::size_t i, double speed_scale) {
    if (before.is_stone(i)) return false;
    const double dt = scene.run.dt, gamma = scene.physics.damping;
    const double fx = (scene.physics.gravity_x - gamma * before.vx[i]) * dt;
    const double fy = (scene.physics.gravity_y - gamma * before.vy[i]) * dt;
    const double rx = after.vx[i] - before.vx[i] - fx, ry = after.vy[i] - before.vy[i] - fy;
    const double allowed = rounding * speed_scale + force_slack * std::hypot(fx, fy);
    return rx * rx + ry * ry > allowed * allowed;
}

std::vector<std::size_t> changed_disks(const Scene& scene, const ParticleState<double>& before,
                                       const ParticleState<double>& after) {
    double mean_square = 0;
    for (std::size_t i = 0; i < before.size(); ++i) mean_square += before.vx[i] * before.vx[i] + before.vy[i] * before.vy[i];
    const double speed_scale = std::sqrt(mean_square / double(std::max<std::size_t>(before.size(), 1)));
    std::vector<std::size_t> changed;
    for (std::size_t i = 0; i < before.size(); ++i)
        if (contact_changed(scene, before, after, i, speed_scale)) changed.push_back(i);
    return changed;
}

// Union-find root with path halving.
std::size_t root(std::vector<std::size_t>& parent, std::size_t a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
}

// "a wall", "2 walls", "a stone", "a wall and 2 stones", or "" for neither.
std::string obstacle_words(std::size_t walls, std::size_t stones) {
    auto count = [](std::size_t n, const char* what) {
        return n == 0 ? std::string() : n == 1 ? std::string("a ") + what : std::to_string(n) + " " + what + "s";
    };
    const std::string w = count(walls, "wall"), s = count(stones, "stone");
    return w.empty() ? s : s.empty() ? w : w + " and " + s;
}

std::string join_indices(const std::vector<std::string>& v) {
    std::string s;
    for (std::size_t k = 0; k < v.size(); ++k) s += (k == 0 ? "" : k + 1 == v.size() ? " and " : ", ") + v[k];
    return s;
}

// What disk i touched that is not yet named: other disks (taking those pairs off `open`), its
// walls and stones.
std::vector<std::string> partners_of(const ContactGroup& g, std::size_t i,
                                     std::vector<std::pair<std::size_t, std::size_t>>& open) {
    std::vector<std::string> names;
    for (auto it = open.begin(); it != open.end();) {
        if (it->first != i && it->second != i) {
            ++it;
            continue;
        }
        names.push_back(std::to_string(it->first == i ? it->second : it->first));
        it = open.erase(it);
    }
    for (const auto& [disk, wall] : g.walls)
        if (disk == i) names.push_back("the " + wall + " wall");
    for (const auto& [disk, stone] : g.stones)
        if (disk == i) names.push_back("stone " + std::to_string(stone));
    return names;
}

// "disk 72 touches 545 and 839; disk 12 touches the left wall": the disk with the most
// contacts not yet named first, each contact named once.
std::string contacts_text(const ContactGroup& g) {
    std::vector<std::pair<std::size_t, std::size_t>> open = g.pairs;
    std::set<std::size_t> done;
    std::string out;
    while (true) {
        std::size_t best = 0, best_count = 0;
        for (const JumpDisk& d : g.disks) {
            if (done.count(d.index)) continue;
            std::vector<std::pair<std::size_t, std::size_t>> probe = open;
            const std::size_t n = partners_of(g, d.index, probe).size();
            if (n > best_count) best = d.index, best_count = n;
        }
        if (best_count == 0) return out;
        done.insert(best);
        out += (out.empty() ? "" : "; ") + ("disk " + std::to_string(best) + " touches ") +
               join_indices(partners_of(g, best, open));
    }
}

}  // namespace

std::string contact_kind(std::size_t disks, std::size_t pairs, std::size_t walls, std::size_t stones) {
    const std::string obstacles = obstacle_words(walls, stones);
    if (pairs == 0 && obstacles.empty()) return "no contact found";
    if (obstacles.empty()) return disks == 2 ? "an isolated pair" : std::to_string(disks) + " disks in contact at once";
    if (pairs == 0) return (disks == 1 ? "a disk at " : std::to_string(disks) + " disks at ") + obstacles;
    if (disks == 2) return "a disk touching " + obstacles + " and a disk";
    return std::to_string(disks) + " disks in contact at once, with " + obstacles;
}

std::vector<ContactGroup> attribute_change(const Scene& scene, const ParticleState<double>& before,
                                           const ParticleState<double>& after) {
    if (before.size() != after.size()) throw std::invalid_argument("attribute_change: states of different sizes");
    const std::vector<std::size_t> changed = changed_disks(scene, before, after);
    std::vector<std::size_t> stones;
    for (std::size_t i = 0; i < before.size(); ++i)
        if (before.is_stone(i)) stones.push_back(i);

    // Contacts among the changed disks (a step's impulse changes both disks of a pair), joined
    // into groups; stones and walls take impulses without changing, so they join no groups.
    std::vector<std::size_t> parent(changed.size());
    std::iota(parent.begin(), parent.end(), std::size_t{0});
    std::vector<std::pair<std::size_t, std::size_t>> pairs;  // positions in `changed`
    for (std::size_t a = 0; a < changed.size(); ++a)
        for (std::size_t b = a + 1; b < changed.size(); ++b)
            if (touching(scene, before, after, changed[a], changed[b])) {
                pairs.emplace_back(a, b);
                parent[root(parent, a)] = root(parent, b);
            }

    std::vector<ContactGroup> groups;
    std::vector<std::size_t> group_of(changed.size()), slot(changed.size(), SIZE_MAX);
    std::vector<std::set<std::string>> group_walls;
    for (std::size_t a = 0; a < changed.size(); ++a) {
        const std::size_t r = root(parent, a), i = changed[a];
        if (slot[r] == SIZE_MAX) {
            slot[r] = groups.size();
            groups.emplace_back();
            group_walls.emplace_back();
        }
        ContactGroup& g = groups[group_of[a] = slot[r]];
        g.disks.push_back({i, energy(scene, before, i), energy(scene, after, i)});
        g.energy_change += energy(scene, after, i) - energy(scene, before, i);
        std::set<std::string> walls;
        add_walls(scene, before, i, reach(scene, before, after, i), walls);
        add_walls(scene, after, i, reach(scene, before, after, i), walls);
        for (const std::string& w : walls) g.walls.emplace_back(i, w);
        group_walls[group_of[a]].insert(walls.begin(), walls.end());
        for (std::size_t s : stones)
            if (touching(scene, before, after, i, s)) g.stones.emplace_back(i, s);
    }
    for (const auto& [a, b] : pairs) groups[group_of[a]].pairs.emplace_back(changed[a], changed[b]);
    for (std::size_t k = 0; k < groups.size(); ++k) {
        ContactGroup& g = groups[k];
        std::set<std::size_t> stones_touched;
        for (const auto& st : g.stones) stones_touched.insert(st.second);
        g.kind = contact_kind(g.disks.size(), g.pairs.size(), group_walls[k].size(), stones_touched.size());
    }
    std::stable_sort(groups.begin(), groups.end(), [](const ContactGroup& x, const ContactGroup& y) {
        return std::fabs(x.energy_change) > std::fabs(y.energy_change);
    });
    return groups;
}

std::vector<double> step_times(double from, double dt, double t_end) {
    std::vector<double> times;
    const std::int64_t first = std::int64_t(std::llround(from / dt)), last = std::int64_t(std::floor(t_end / dt + 1e-9));
    for (std::int64_t k = first; k < last; ++k) times.push_back(double(k + 1) * dt);
    return times;
}

EnergyJump largest_energy_change(Solver& solver, const Scene& scene, double t_end,
                                 const std::function<void(double, double)>& on_step) {
    const double dt = scene.run.dt;
    const std::vector<double> times = step_times(solver.time(), dt, t_end);
    if (times.empty()) {
        char text[200];
        std::snprintf(text, sizeof text, "no whole step of dt = %g lies between t = %g and t = %g", dt, solver.time(),
                      t_end);
        throw std::runtime_error(text);
    }
    ParticleState<double> before, after, worst_before, worst_after;
    EnergyJump jump;
    bool found = false;
    solver.read_state(before);
    std::int64_t k = std::int64_t(std::llround(solver.time() / dt));
    for (const double t : times) {
        solver.advance_to(t);
        if (on_step) on_step(t, t_end);
        solver.read_state(after);
        const double change = total_energy(scene, after) - total_energy(scene, before);
        const bool nonfinite = !std::isfinite(change);
        if (!found || nonfinite || std::fabs(change) > std::fabs(jump.energy_change)) {
            found = true;
            jump = {k, double(k) * dt, double(k + 1) * dt, total(before, kinetic), change, nonfinite, {}};
            worst_before = before;
            worst_after = after;
        }
        if (nonfinite) break;  // later steps only carry the NaN on
        std::swap(before, after);
        ++k;
    }
    if (!jump.nonfinite) jump.groups = attribute_change(scene, worst_before, worst_after);
    return jump;
}

std::string describe(const EnergyJump& jump) {
    char head[256];
    if (jump.nonfinite) {
        std::snprintf(head, sizeof head, "the state became non-finite (NaN or infinite) in the step ending at t = %.6g",
                      jump.time_after);
        return head;
    }
    std::snprintf(head, sizeof head, "the step ending at t = %.6g changes the energy by %+.4g", jump.time_after,
                  jump.energy_change);
    std::string text = head;
    if (jump.kinetic_before > 0) {
        std::snprintf(head, sizeof head, " (%+.3g %% of K)", 100 * jump.energy_change / jump.kinetic_before);
        text += head;
    }
    if (jump.groups.empty()) return text + "; no contact changed a velocity (the forces' integration alone)";
    const ContactGroup& g = jump.groups.front();
    double held = 0;
    for (const JumpDisk& d : g.disks) held += d.energy_before;
    const std::string contacts = contacts_text(g);
    text += "; " + g.kind + (contacts.empty() ? "" : " (" + contacts + ")");
    char share[160];
    std::snprintf(share, sizeof share, ": %.4g before, %.4g after", held, held + g.energy_change);
    text += share;
    if (held > 0) {
        std::snprintf(share, sizeof share, " (%+.3g %%)", 100 * g.energy_change / held);
        text += share;
    }
    if (jump.groups.size() > 1)
        text += "; " + std::to_string(jump.groups.size() - 1) + " other group" + (jump.groups.size() > 2 ? "s" : "") +
                " changed less";
    return text;
}

}  // namespace collide::validation
