#include "energy_jump.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <stdexcept>

namespace collide::validation {
namespace {

constexpr double contact_slack = 1e-6;  // relative: a pair at (r_i + r_j)(1 + slack) touches
constexpr double rounding = 1e-9;       // of the rms speed: a smaller velocity change is no contact
constexpr double force_slack = 1e-3;    // of the forces' own change: how exactly a rule integrates them

// m |v|^2 / 2 of a free disk; a kinematic stone moves as prescribed and exchanges no energy.
double kinetic(const ParticleState<double>& p, std::size_t i) {
    if (p.is_stone(i)) return 0;
    return 0.5 * p.mass[i] * (p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i]);
}

double total_kinetic(const ParticleState<double>& p) {
    double k = 0;
    for (std::size_t i = 0; i < p.size(); ++i) k += kinetic(p, i);
    return k;
}

// Component of a separation along one axis, the nearest image where the box is periodic.
double separation(double d, double length, bool periodic) {
    if (periodic) d -= length * std::round(d / length);
    return d;
}

bool touching(const Scene& scene, const ParticleState<double>& p, std::size_t i, std::size_t j) {
    const bool periodic = scene.periodic();
    const double dx = separation(p.x[i] - p.x[j], scene.world.width(), periodic);
    const double dy = separation(p.y[i] - p.y[j], scene.world.height(), periodic);
    const double reach = (p.radius[i] + p.radius[j]) * (1 + contact_slack);
    return dx * dx + dy * dy <= reach * reach;
}

// The reflecting walls disk i reaches in state p.
std::vector<std::string> walls_touched(const Scene& scene, const ParticleState<double>& p, std::size_t i) {
    std::vector<std::string> out;
    if (scene.periodic()) return out;
    const double r = p.radius[i] * (1 + contact_slack);
    const World& w = scene.world;
    if (p.x[i] - r <= w.xmin) out.push_back("left");
    if (p.x[i] + r >= w.xmax) out.push_back("right");
    if (p.y[i] - r <= w.ymin) out.push_back("bottom");
    if (p.y[i] + r >= w.ymax) out.push_back("top");
    return out;
}

// Union-find root with path halving.
std::size_t root(std::vector<std::size_t>& parent, std::size_t a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
}

std::string join_indices(const std::vector<std::size_t>& v) {
    std::string s;
    for (std::size_t k = 0; k < v.size(); ++k) {
        if (k) s += k + 1 == v.size() ? " and " : ", ";
        s += std::to_string(v[k]);
    }
    return s;
}

// The walls disk i touched, in words ("the left wall").
std::vector<std::string> wall_names(const ContactGroup& g, std::size_t i) {
    std::vector<std::string> out;
    for (const auto& [disk, name] : g.walls)
        if (disk == i) out.push_back("the " + name + " wall");
    return out;
}

// "disk 72 touches 545 and 839; disk 12 touches the left wall": the disk with the most
// contacts not yet named first, each contact named once.
std::string contacts_text(const ContactGroup& g) {
    std::vector<std::pair<std::size_t, std::size_t>> open = g.pairs;
    std::vector<std::size_t> walls_named;
    std::string out;
    auto degree = [&](std::size_t i) {
        return std::count_if(open.begin(), open.end(), [i](const auto& p) { return p.first == i || p.second == i; });
    };
    while (true) {
        std::size_t best = SIZE_MAX;
        long best_degree = 0;
        for (const JumpDisk& d : g.disks) {
            const bool walls_left = !wall_names(g, d.index).empty() &&
                                    std::find(walls_named.begin(), walls_named.end(), d.index) == walls_named.end();
            const long n = long(degree(d.index)) + (walls_left ? 1 : 0);
            if (n > best_degree) best = d.index, best_degree = n;
        }
        if (best == SIZE_MAX) return out;
        std::vector<std::size_t> partners;
        for (auto it = open.begin(); it != open.end();) {
            if (it->first == best || it->second == best) {
                partners.push_back(it->first == best ? it->second : it->first);
                it = open.erase(it);
            } else {
                ++it;
            }
        }
        std::vector<std::string> names;
        if (!partners.empty()) names.push_back(join_indices(partners));
        if (std::find(walls_named.begin(), walls_named.end(), best) == walls_named.end()) {
            for (const std::string& w : wall_names(g, best)) names.push_back(w);
            walls_named.push_back(best);
        }
        std::string text = "disk " + std::to_string(best) + " touches ";
        for (std::size_t k = 0; k < names.size(); ++k) text += (k ? " and " : "") + names[k];
        out += (out.empty() ? "" : "; ") + text;
    }
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

}  // namespace

std::string contact_kind(std::size_t disks, std::size_t pairs, std::size_t walls) {
    if (pairs == 0 && walls == 0) return disks == 1 ? "no contact (a force or damping)" : "no contact";
    if (walls == 0) return disks == 2 ? "an isolated pair" : std::to_string(disks) + " disks in contact at once";
    if (pairs == 0) return disks == 1 ? "a disk at a wall" : std::to_string(disks) + " disks at walls";
    return disks == 2 ? "a disk touching a wall and a disk" : std::to_string(disks) + " disks and a wall";
}

std::vector<ContactGroup> attribute_change(const Scene& scene, const ParticleState<double>& before,
                                           const ParticleState<double>& after) {
    if (before.size() != after.size()) throw std::invalid_argument("attribute_change: states of different sizes");
    const std::size_t n = before.size();
    double mean_square = 0;
    for (std::size_t i = 0; i < n; ++i) mean_square += before.vx[i] * before.vx[i] + before.vy[i] * before.vy[i];
    const double speed_scale = std::sqrt(mean_square / double(std::max<std::size_t>(n, 1)));
    std::vector<std::size_t> changed;
    for (std::size_t i = 0; i < n; ++i)
        if (contact_changed(scene, before, after, i, speed_scale)) changed.push_back(i);

    // Contacts among the changed disks only: a step's impulse changes both disks of a pair.
    std::vector<std::size_t> parent(changed.size());
    std::iota(parent.begin(), parent.end(), std::size_t{0});
    std::vector<std::pair<std::size_t, std::size_t>> pairs;  // positions in `changed`
    for (std::size_t a = 0; a < changed.size(); ++a)
        for (std::size_t b = a + 1; b < changed.size(); ++b) {
            const std::size_t i = changed[a], j = changed[b];
            if (!touching(scene, before, i, j) && !touching(scene, after, i, j)) continue;
            pairs.emplace_back(a, b);
            parent[root(parent, a)] = root(parent, b);
        }

    std::vector<ContactGroup> groups;
    std::vector<std::size_t> group_of(changed.size(), SIZE_MAX), slot(changed.size(), SIZE_MAX);
    for (std::size_t a = 0; a < changed.size(); ++a) {
        const std::size_t r = root(parent, a);
        if (slot[r] == SIZE_MAX) {
            slot[r] = groups.size();
            groups.emplace_back();
        }
        group_of[a] = slot[r];
        ContactGroup& g = groups[group_of[a]];
        const std::size_t i = changed[a];
        g.disks.push_back({i, kinetic(before, i), kinetic(after, i)});
        g.kinetic_change += kinetic(after, i) - kinetic(before, i);
        auto walls = walls_touched(scene, before, i);
        for (const std::string& w : walls_touched(scene, after, i))
            if (std::find(walls.begin(), walls.end(), w) == walls.end()) walls.push_back(w);
        for (const std::string& w : walls) g.walls.emplace_back(i, w);
    }
    for (const auto& [a, b] : pairs) groups[group_of[a]].pairs.emplace_back(changed[a], changed[b]);
    for (ContactGroup& g : groups) g.kind = contact_kind(g.disks.size(), g.pairs.size(), g.walls.size());
    std::stable_sort(groups.begin(), groups.end(), [](const ContactGroup& x, const ContactGroup& y) {
        return std::fabs(x.kinetic_change) > std::fabs(y.kinetic_change);
    });
    return groups;
}

EnergyJump largest_energy_change(Solver& solver, const Scene& scene, double t_end) {
    const double dt = scene.run.dt;
    std::int64_t k = std::int64_t(std::llround(solver.time() / dt));
    const std::int64_t last = std::int64_t(std::floor(t_end / dt + 1e-9));
    if (last <= k)
        throw std::runtime_error("no whole step of dt = " + std::to_string(dt) + " lies between t = " +
                                 std::to_string(solver.time()) + " and t = " + std::to_string(t_end));
    ParticleState<double> before, after, worst_before, worst_after;
    EnergyJump jump;
    bool found = false;
    solver.read_state(before);
    for (; k < last; ++k) {
        solver.advance_to(double(k + 1) * dt);
        solver.read_state(after);
        const double k_before = total_kinetic(before), change = total_kinetic(after) - k_before;
        if (!found || std::fabs(change) > std::fabs(jump.kinetic_change)) {
            found = true;
            jump = {k, double(k) * dt, double(k + 1) * dt, k_before, change, {}};
            worst_before = before;
            worst_after = after;
        }
        std::swap(before, after);
    }
    jump.groups = attribute_change(scene, worst_before, worst_after);
    return jump;
}

std::string describe(const EnergyJump& jump) {
    char head[256];
    std::snprintf(head, sizeof head, "the step ending at t = %.6g changes K by %+.4g (%.3g %% of K)", jump.time_after,
                  jump.kinetic_change, 100 * jump.kinetic_change / (jump.kinetic_before > 0 ? jump.kinetic_before : 1));
    std::string text = head;
    if (jump.groups.empty()) return text + "; no disk changed its energy";
    const ContactGroup& g = jump.groups.front();
    double held = 0;
    for (const JumpDisk& d : g.disks) held += d.kinetic_before;
    const std::string contacts = contacts_text(g);
    char share[200];
    std::snprintf(share, sizeof share, " held %.4g and keep %.4g (%+.3g %%)", held, held + g.kinetic_change,
                  held > 0 ? 100 * g.kinetic_change / held : 0.0);
    text += "; " + g.kind + (contacts.empty() ? "" : " (" + contacts + ")") + share;
    if (jump.groups.size() > 1)
        text += "; " + std::to_string(jump.groups.size() - 1) + " other group" + (jump.groups.size() > 2 ? "s" : "") +
                " changed less";
    return text;
}

}  // namespace collide::validation
