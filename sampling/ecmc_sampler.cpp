#include "sampling/ecmc_sampler.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>

#include "core/numerics/target_time.h"
#include "core/scene/option_reader.h"
#include "core/structure/orientational_order.h"
#include "core/thermo/pressure_record.h"
#include "sampling/sampler_input.h"

namespace collide {

namespace {
constexpr SamplerLimits ecmc_limits{.walls = true};
}

std::optional<std::string> EcmcSampler::supports(const Scene& scene) { return outside_sampler_model(scene_features(scene), ecmc_limits); }

// ---------------------------------------------------------------------------------------
// Loading
// ---------------------------------------------------------------------------------------

void EcmcSampler::load(const Scene& scene, const ParticleState<double>& initial) {
    check_sampler_start("ecmc", scene, initial, ecmc_limits);
    scene_ = scene;
    start_ = initial;
    const std::size_t n = initial.size();
    sigma_ = 2 * initial.radius[0];
    sigma2_ = sigma_ * sigma_;
    const double area = scene.world.width() * scene.world.height();
    density_d2_ = double(n) * sigma2_ / area;

    OptionReader options("ecmc", &scene, options_.extra);
    chain_length_ = sigma_ * options.get_double("chain_length", default_chain_length_diameters, 0,
                                                "a chain length > 0, in disk diameters", true);
    options.refuse_unknown();

    // The run's length: [run] chains, or by default as many chains as move the disks, all
    // together, N x duration length units (docs/monte-carlo.md, "How long a sampler runs").
    chains_total_ = scene.run.chains > 0
                        ? scene.run.chains
                        : std::max<std::int64_t>(1, std::llround(std::ceil(double(n) * scene.run.duration / chain_length_)));
    // An entry of the pressure series moves the disks by one diameter each, on average.
    chains_per_entry_ = std::max<std::int64_t>(1, std::llround(double(n) * sigma_ / chain_length_));

    pos_[0] = initial.x;
    pos_[1] = initial.y;
    const World& w = scene.world;
    const double origin[2] = {w.xmin, w.ymin}, length[2] = {w.width(), w.height()};
    walls_ = !scene.periodic();
    if (walls_) {
        // A centre lies between its two wall contacts; a start that reaches past one by no more
        // than rounding (check_sampler_start) is put onto it.
        const double r = initial.radius[0], top[2] = {w.xmax, w.ymax};
        for (int a = 0; a < 2; ++a) {
            wall_contact_[a][0] = origin[a] + r;
            wall_contact_[a][1] = top[a] - r;
            for (double& p : pos_[a]) p = std::clamp(p, wall_contact_[a][0], wall_contact_[a][1]);
        }
        // x chains measure the pressure on the walls of length height, y chains on those of
        // length width: weighted so that their mean is the force per unit length of the whole
        // perimeter, (2 P_x h + 2 P_y w) / (2 (w + h)) (docs/monte-carlo.md, "Walls").
        axis_weight_[0] = 2 * w.height() / (w.width() + w.height());
        axis_weight_[1] = 2 * w.width() / (w.width() + w.height());
    } else {
        for (int a = 0; a < 2; ++a)
            for (double& p : pos_[a]) p = wrap_into_box(p, origin[a], length[a]);
        axis_weight_[0] = axis_weight_[1] = 1;
    }
    try {
        cells_.configure(origin, length, sigma_);
    } catch (const std::runtime_error& e) {
        throw std::runtime_error("ecmc: scene '" + scene.name + "': " + e.what());
    }
    place_in_cells();

    rng_.reset(gsl_rng_alloc(gsl_rng_mt19937));
    gsl_rng_set(rng_.get(), (unsigned long)(scene.seed ^ 0x45434d43u));  // a stream of its own ("ECMC")
    chains_done_ = lifts_ = wall_turns_ = entry_chains_ = 0;
    entry_sum_ = now_ = 0;
    series_ = {{}, double(chains_per_entry_), {}, density_d2_ * std::numbers::pi / 4, {}};
}

void EcmcSampler::place_in_cells() {
    const std::size_t n = pos_[0].size();
    for (int a = 0; a < 2; ++a) cell_[a].resize(n);
    slot_.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        cell_[0][i] = cells_.coordinate_of(0, pos_[0][i]);
        cell_[1][i] = cells_.coordinate_of(1, pos_[1][i]);
        slot_[i] = cells_.insert(cells_.index(cell_[0][i], cell_[1][i]), i);
    }
}

// ---------------------------------------------------------------------------------------
// The chains
// ---------------------------------------------------------------------------------------

void EcmcSampler::advance_to(double t) {
    check_target_time("ecmc", t, now_, scene_.run.dt, false);  // NaN, infinity, the past: refused
    const std::int64_t target = sampler_steps_at(t, scene_, chains_total_);
    while (chains_done_ < target) {
        const bool x_chain = chains_done_ % 2 == 0;
        if (walls_) x_chain ? run_chain<0, true>() : run_chain<1, true>();
        else x_chain ? run_chain<0, false>() : run_chain<1, false>();
        ++chains_done_;
    }
    now_ = t;
}

template <int A>
void EcmcSampler::cross_edge(std::uint32_t i, bool forward) {
    const int column = cell_[A][i], row = cell_[1 - A][i];
    const int old_cell = A == 0 ? cells_.index(column, row) : cells_.index(row, column);
    const std::uint32_t moved = cells_.erase(old_cell, slot_[i]);
    slot_[moved] = slot_[i];
    int next = forward ? column + 1 : column - 1;
    // The edge between the two cells: it belongs to both, so the disk sits on it in its new cell.
    double edge = cells_.origin(A) + (forward ? next : column) * cells_.side(A);
    // Only a periodic box's +A chains leave the box's last cell; chains along -A run in boxes
    // with walls, where the wall contact lies inside the first cell, before its edge.
    if (next == cells_.count(A)) {  // across the periodic boundary: the same point, one box back
        next = 0;
        edge = cells_.origin(A);
    }
    pos_[A][i] = edge;
    cell_[A][i] = next;
    slot_[i] = cells_.insert(A == 0 ? cells_.index(next, row) : cells_.index(row, next), i);
}

// The active disk moves along axis A, in the chain's direction `sense` (+1 or -1), by the least
// of: the chain's remaining length, the distance to its cell's edge ahead (beyond it the 6
// cells scanned no longer hold every disk it could meet), the distance to the wall ahead
// (Walls), and the distance to the first disk in its way, du - sqrt(sigma^2 - dw^2) for a disk
// ahead (du > 0 along `sense`) within sigma across (|dw| < sigma). Meeting a disk lifts the
// chain to it; meeting a wall turns the chain back (docs/monte-carlo.md, "Walls").
template <int A, bool Walls>
void EcmcSampler::run_chain() {
    constexpr int B = 1 - A;
    enum class Stop { chain_end, cell_edge, wall };
    const int columns = cells_.count(A), rows = cells_.count(B);
    const double box_a = cells_.length(A), box_b = cells_.length(B);
    std::uint32_t active = std::uint32_t(gsl_rng_uniform_int(rng_.get(), pos_[0].size()));
    // A periodic box always goes +A; with walls the direction is drawn, + or - with probability
    // 1/2, so that the chains a wall turns back are balanced by chains that start that way.
    double sense = Walls && gsl_rng_uniform_int(rng_.get(), 2) == 1 ? -1.0 : 1.0;
    double budget = chain_length_, lift_sum = 0;
    // Where a slide of `step` from u ends; with walls never past a wall contact (rounding).
    const auto slid = [&](double u, double step) {
        const double end = u + sense * step;
        return Walls ? std::clamp(end, wall_contact_[A][0], wall_contact_[A][1]) : end;
    };
    for (;;) {
        const int ca = cell_[A][active], cb = cell_[B][active];
        const double u = pos_[A][active], w = pos_[B][active];
        const bool forward = sense > 0;
        const double to_edge = sense * (cells_.origin(A) + (forward ? ca + 1 : ca) * cells_.side(A) - u);
        Stop stop = to_edge < budget ? Stop::cell_edge : Stop::chain_end;
        double step = stop == Stop::cell_edge ? to_edge : budget, reach = 0;
        if (Walls) {
            const double to_wall = sense * (wall_contact_[A][forward] - u);
            if (to_wall < step) stop = Stop::wall, step = std::max(to_wall, 0.0);
        }
        std::int64_t blocker = -1;
        for (int da = 0; da < 2; ++da) {
            int column = forward ? ca + da : ca - da;
            double shift_a = 0;  // the periodic image of the next column past the box's edge
            if (Walls) {
                if (column < 0 || column == columns) continue;  // beyond a wall: no disks there
            } else if (column == columns) {
                column = 0, shift_a = box_a;
            }
            for (int db = -1; db <= 1; ++db) {
                int row = cb + db;
                double shift_b = 0;
                if (Walls) {
                    if (row < 0 || row == rows) continue;
                } else if (row < 0) {
                    row = rows - 1, shift_b = -box_b;
                } else if (row == rows) {
                    row = 0, shift_b = box_b;
                }
                const int cell = A == 0 ? cells_.index(column, row) : cells_.index(row, column);
                const std::uint32_t* members = cells_.members(cell);
                for (int k = 0, m = cells_.occupancy(cell); k < m; ++k) {
                    const std::uint32_t j = members[k];
                    const double du = sense * (pos_[A][j] + shift_a - u);
                    const double dw = pos_[B][j] + shift_b - w, room = sigma2_ - dw * dw;
                    // In the way before `step` iff it is ahead (du > 0), within sigma across
                    // (room > 0) and du - step < sqrt(room), tested squared when du > step so
                    // that only a disk nearer than the best so far pays a sqrt. The tests are
                    // combined without branches: their outcomes are a coin toss per disk.
                    const double ahead = du - step;
                    const bool in_way = (du > 0) & (j != active) & (room > 0) & !((ahead > 0) & (ahead * ahead >= room));
                    if (!in_way) continue;
                    const double gap = du - std::sqrt(room);
                    if (gap < step) {
                        step = gap > 0 ? gap : 0;  // a pair touching to rounding: lift at once
                        blocker = j;
                        reach = du - step;  // x_ij at contact
                    }
                }
            }
        }
        budget -= step;
        if (blocker >= 0) {
            pos_[A][active] = slid(u, step);
            lift_sum += reach;
            ++lifts_;
            active = std::uint32_t(blocker);
        } else if (stop == Stop::wall) {
            // Turned back at the wall: a lift to the disk's mirror image, one diameter on.
            pos_[A][active] = wall_contact_[A][forward];
            lift_sum += sigma_;
            ++wall_turns_;
            sense = -sense;
        } else if (stop == Stop::cell_edge) {
            cross_edge<A>(active, forward);
        } else {
            pos_[A][active] = slid(u, step);
            break;
        }
    }
    record_chain(A, lift_sum);
}

// beta P / rho = 1 + (sum of x_ij) / l for this chain (Michel, Kapfer, Krauth 2014), averaged
// over an entry's chains and stored as beta P d^2 = (beta P / rho) rho sigma^2.
// With walls each chain is weighted by the length of the walls its axis pushes on (load()).
void EcmcSampler::record_chain(int axis, double lift_sum) {
    entry_sum_ += axis_weight_[axis] * (1 + lift_sum / chain_length_);
    if (++entry_chains_ < chains_per_entry_) return;
    series_.beta_pressure.push_back(entry_sum_ / double(entry_chains_) * density_d2_);
    // psi6 once per entry: each disk moved about one diameter since the last sample, so the
    // phase moves by far less than pi between samples (orientational_order.h's mixing check).
    ParticleState<double> configuration;
    read_state(configuration);
    series_.psi6_phase.push_back(std::arg(global_psi6(scene_.world, configuration)));
    entry_sum_ = 0;
    entry_chains_ = 0;
}

// ---------------------------------------------------------------------------------------
// Output
// ---------------------------------------------------------------------------------------

void EcmcSampler::read_state(ParticleState<double>& out) const {
    out = start_;
    out.x = pos_[0];
    out.y = pos_[1];
    const World& w = scene_.world;
    for (std::size_t i = 0; i < out.size(); ++i) {
        // A disk moved onto a periodic box's far edge is at the near edge of the next image.
        if (!walls_ && out.x[i] >= w.xmax) out.x[i] -= w.width();
        if (!walls_ && out.y[i] >= w.ymax) out.y[i] -= w.height();
        out.vx[i] = out.vy[i] = 0;  // a sampler has no velocities
    }
}

SolverStats EcmcSampler::stats() const {
    SolverStats s;
    s.steps = chains_done_;
    s.contacts = lifts_;
    auto& c = s.counters;
    c["chains"] = double(chains_done_);
    c["lifts"] = double(lifts_);
    if (walls_) c["wall_turns"] = double(wall_turns_);
    c["chain_length"] = chain_length_;
    c["chains_per_entry"] = double(chains_per_entry_);
    // The counters every backend records (core/thermo/pressure_record.h), lengths in chains.
    if (series_.beta_pressure.size() >= 2)
        for (const auto& [name, value] : counters_.counters(series_)) c[name] = value;
    return s;
}

}  // namespace collide
