#include "cpu_solver.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <stdexcept>
#include <string>

#include "core/numerics/number_text.h"
#include "core/scene/option_reader.h"
#include "core/numerics/phase_timer.h"
#include "core/numerics/representability.h"
#include "physics/step_schedule.h"
#include "parallel_for.h"

namespace collide::cpu {
CpuSolver::CpuSolver(const BackendOptions& options) : options_(options) {
    if (options.threads < 0) throw std::invalid_argument("cpu: thread count must be >= 0, got " + std::to_string(options.threads));
    threads_ = options.threads > 0 ? options.threads : omp_get_max_threads();
    read_settings(nullptr);  // (bad options are refused at once)
}

// The settings: the scene's [backend.cpu] table (none before load), then the caller's options,
// which win (core/scene/option_reader.h).
void CpuSolver::read_settings(const Scene* scene) {
    OptionReader settings("cpu", scene, options_.extra);
    specialise_ = settings.get_choice("specialise", {"on", "off"}, "on") == "on";
    sort_interval_ = int(settings.get_int("sort_interval", kDefaultSortInterval, 0, INT_MAX,
                                          "an integer >= 0 (0: never reorder)"));
    skin_ = settings.get_double("skin", kDefaultSkin, 0.0, "a number >= 0 (0: the cell path, no pair list)");
    settings.refuse_unknown();
}

void CpuSolver::load(const Scene& scene, const ParticleState<double>& initial) {
    scene_ = scene;
    read_settings(&scene);
    const std::size_t n = initial.size();
    if (n >= std::size_t(UINT32_MAX)) throw std::invalid_argument("cpu: at most 2^32 - 1 disks (32-bit indices)");
    require_representable(scene, initial, Precision::single, Method::stepping_rules, "cpu");
    state_ = initial.as<float>();  // the one conversion to float; back to double only in read_state
    original_index_.resize(n);
    for (std::size_t i = 0; i < n; ++i) original_index_[i] = std::uint32_t(i);
    for (auto* a : {&dx_, &dy_, &dvx_, &dvy_}) a->assign(n, 0.0f);
    step_count_ = 0;
    grid_builds_ = 0;
    stats_ = SolverStats{};

    features_ = specialise_ ? FeatureSet::of(scene_features(scene, initial)) : FeatureSet::generic(scene);
    auto all_equal = [](const std::vector<float>& a) {
        return std::all_of(a.begin(), a.end(), [&](float v) { return v == a.front(); });
    };
    equal_radii_ = all_equal(state_.radius);
    equal_masses_ = all_equal(state_.mass) && all_equal(state_.inv_mass);
    reordered_ = ParticleState<float>{};  // no stale arrays: the constant ones are swapped in below
    const Physics& ph = scene.physics;
    const World& w = scene.world;
    params_ = PhaseParams{float(ph.restitution), float(ph.friction), float(ph.wall_restitution),
                          float(ph.gravity_x), float(ph.gravity_y), float(ph.damping),
                          n > 0 ? state_.radius[0] : 0.0f,
                          float(w.xmin), float(w.ymin), float(w.xmax), float(w.ymax),
                          float(w.width()), float(w.height())};
    const float r_max = n > 0 ? *std::max_element(state_.radius.begin(), state_.radius.end()) : 0.5f;
    // With a pair list the grid only builds the list: its cells must hold the reach.
    const double diameter = 2.0 * double(r_max);
    grid_.configure(w, diameter * (1.0 + skin_));
    stats_.counters["grid_cells"] = double(grid_.cell_count());
    pairs_.reset(float(skin_ * diameter));
}

void CpuSolver::advance_to(double t) {
    const std::int64_t target = target_step(scene_, t, step_count_, "cpu");
    while (step_count_ < target) step();
}

void CpuSolver::step() {
    step_by_rule<float>(scene_.run, [this](float dt) { step_collide_first(dt); },
                        [this](float h) { substep_integrate_first(h); });
    ++step_count_;
    ++stats_.steps;
}

void CpuSolver::step_collide_first(float dt) {
    contact_phase();
    correct_and_integrate(dt);
}

// The integrate-first sub-step in six steps: (1) field accelerations, (2) velocity with damping,
// (3) position, fused into one pass by integrate(); (4) grid rebuild; (5) contact pass;
// (6) corrections and world bounds.
void CpuSolver::substep_integrate_first(float h) {
    integrate(h);
    contact_phase();
    correct();
}

// Phases 4 and 5: with a skin, the pair list (rebuilt with the grid only when stale) and the
// contacts on it; without, the grid and the cell path's one-sided pass at every step.
void CpuSolver::contact_phase() {
    if (skin_ > 0) {
        collide_pairs();
    } else {
        build_grid();
        collide();
    }
}

// Runs update(begin, end) over the disks in parallel chunks. On the pair list each chunk first
// adds its own disks' contact shares to the corrections, in list order, and clears them after
// the update, in the thread that owns the chunk: no thread writes a correction another reads
// (phase_kernels.h, add_pair_shares).
template <typename Update>
void CpuSolver::update_with_corrections(Update&& update) {
    const bool on_pairs = skin_ > 0;
    const auto& found = pairs_.contact_chunks();
    parallel_for(state_.size(), threads_, [&](std::size_t b, std::size_t e) {
        const auto begin = std::uint32_t(b), end = std::uint32_t(e);
        if (on_pairs)
            for (std::size_t c = 0; c < found.size(); ++c)
                add_pair_shares(found[c].data(), shares_[c].data(), found[c].size(), corrections(), begin, end);
        update(b, e);
        if (on_pairs)
            for (const auto& contacts : found)
                clear_pair_corrections(contacts.data(), contacts.size(), corrections(), begin, end);
        return std::int64_t(0);
    });
}

void CpuSolver::integrate(float h) {
    PhaseTimer timer(stats_, phase::integrate);
    dispatch([&]<bool Gravity, bool Damping, bool Stones>() {
        parallel_for(state_.size(), threads_, [&](std::size_t b, std::size_t e) {
            return integrate_range<Gravity, Damping, Stones>(state_, params_, h, b, e);
        });
    }, features_.gravity, features_.damping, features_.stones);
}

void CpuSolver::build_grid() {
    PhaseTimer timer(stats_, phase::grid);
    const std::size_t n = state_.size();
    // Every sort_interval-th build moves the disks themselves into cell order, so that the
    // neighbours the contact pass reads lie next to each other in memory and it needs no index
    // (docs/cpu-backend.md measures it). The move is the counting sort's scatter: each disk's
    // data goes straight to its slot, one pass over memory.
    const bool reorder = sort_interval_ > 0 && grid_builds_ % sort_interval_ == 0;
    ++grid_builds_;
    if (!reorder) {
        grid_.build_index(state_.x.data(), state_.y.data(), n, threads_);
        in_cell_order_ = false;
        return;
    }
    reordered_.resize(n);
    reordered_index_.resize(n);
    const float *x = state_.x.data(), *y = state_.y.data(), *vx = state_.vx.data(), *vy = state_.vy.data();
    const float *radius = state_.radius.data(), *mass = state_.mass.data(), *inv_mass = state_.inv_mass.data();
    const std::uint32_t* index = original_index_.data();
    float *to_x = reordered_.x.data(), *to_y = reordered_.y.data(), *to_vx = reordered_.vx.data();
    float *to_vy = reordered_.vy.data(), *to_radius = reordered_.radius.data(), *to_mass = reordered_.mass.data();
    float* to_inv_mass = reordered_.inv_mass.data();
    std::uint32_t* to_index = reordered_index_.data();
    // An array holding one value for every disk (equal radii, equal masses) reads the same in
    // any order: it is not moved, which saves 8 bytes of traffic per disk and array.
    dispatch([&]<bool MoveRadius, bool MoveMass>() {
        grid_.build(x, y, n, threads_, [=](std::uint32_t i, std::uint32_t k) {
            to_x[k] = x[i];
            to_y[k] = y[i];
            to_vx[k] = vx[i];
            to_vy[k] = vy[i];
            if constexpr (MoveRadius) to_radius[k] = radius[i];
            if constexpr (MoveMass) {
                to_mass[k] = mass[i];
                to_inv_mass[k] = inv_mass[i];
            }
            to_index[k] = index[i];
        });
    }, !equal_radii_, !equal_masses_);
    if (equal_radii_) state_.radius.swap(reordered_.radius);
    if (equal_masses_) {
        state_.mass.swap(reordered_.mass);
        state_.inv_mass.swap(reordered_.inv_mass);
    }
    std::swap(state_, reordered_);
    original_index_.swap(reordered_index_);
    in_cell_order_ = true;
}

void CpuSolver::collide() {
    PhaseTimer timer(stats_, phase::collide);
    // Parallel over rows of cells; a row holds about cells_x * (disks per cell) disks.
    const std::size_t rows = std::size_t(grid_.cells_y());
    const std::size_t min_rows = std::max<std::size_t>(1, kMinChunk / std::size_t(std::max<std::int64_t>(1, grid_.cells_x())));
    dispatch([&]<bool Friction, bool Stones, bool UniformRadius, bool Periodic, bool InCellOrder>() {
        stats_.contacts += parallel_for(rows, threads_, [&](std::size_t b, std::size_t e) {
            return collide_range<Friction, Stones, UniformRadius, Periodic, InCellOrder>(state_, grid_, params_,
                                                                                       corrections(), b, e);
        }, state_.size(), min_rows);
    }, features_.friction, features_.stones, features_.uniform_radius, features_.periodic, in_cell_order_);
}

void CpuSolver::rebuild_pairs() {
    build_grid();
    PhaseTimer timer(stats_, phase::grid);
    dispatch([&]<bool UniformRadius, bool Periodic, bool InCellOrder>() {
        pairs_.build<UniformRadius, Periodic, InCellOrder>(state_, grid_, params_, threads_);
    }, features_.uniform_radius, features_.periodic, in_cell_order_);
    stats_.counters["pair_list_builds"] = double(pairs_.builds());
    stats_.counters["pair_list_pairs"] = double(pairs_.size());
}

// The stale test and the search in one parallel region; when the list is stale (every 8 to 10
// steps in the benchmark gas), the grid and the list rebuilt, then the search on its own.
void CpuSolver::collide_pairs() {
    auto size_for_chunks = [this] {
        shares_.resize(pairs_.chunks());
        contacts_per_chunk_.assign(pairs_.chunks(), 0);
    };
    dispatch([&]<bool Friction, bool Stones, bool UniformRadius, bool Periodic>() {
        auto shares_of_chunk = [&](std::size_t c, const std::vector<DiskPair>& found) {
            shares_[c].resize(found.size());
            contacts_per_chunk_[c] = pair_shares<Friction, Stones, UniformRadius, Periodic>(state_, params_, found.data(),
                                                                                       found.size(), shares_[c].data());
        };
        bool searched = false;
        {
            PhaseTimer timer(stats_, phase::collide);
            size_for_chunks();
            searched = pairs_.search_unless_stale<UniformRadius, Periodic>(state_, params_, threads_, shares_of_chunk);
        }
        if (searched) return;
        rebuild_pairs();
        PhaseTimer timer(stats_, phase::collide);
        size_for_chunks();
        pairs_.find_contacts<UniformRadius, Periodic>(state_, params_, threads_, shares_of_chunk);
    }, features_.friction, features_.stones, features_.uniform_radius, features_.periodic);
    // The shares reach the corrections in the update (update_with_corrections).
    for (const std::int64_t found : contacts_per_chunk_) stats_.contacts += found;
}

void CpuSolver::correct() {
    PhaseTimer timer(stats_, phase::correct);
    dispatch([&]<bool Stones, bool Periodic>() {
        update_with_corrections([&](std::size_t b, std::size_t e) {
            correct_range<Stones, Periodic>(state_, corrections(), params_, b, e);
        });
    }, features_.stones, features_.periodic);
}

void CpuSolver::correct_and_integrate(float dt) {
    PhaseTimer timer(stats_, phase::integrate);
    dispatch([&]<bool Gravity, bool Damping, bool Stones, bool Periodic>() {
        update_with_corrections([&](std::size_t b, std::size_t e) {
            correct_and_integrate_range<Gravity, Damping, Stones, Periodic>(state_, corrections(), params_, dt, b, e);
        });
    }, features_.gravity, features_.damping, features_.stones, features_.periodic);
}

void CpuSolver::read_state(ParticleState<double>& out) const {
    const std::size_t n = state_.size();
    out.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t i = original_index_[k];  // back to the scene's order
        out.x[i] = state_.x[k];
        out.y[i] = state_.y[k];
        out.vx[i] = state_.vx[k];
        out.vy[i] = state_.vy[k];
        out.radius[i] = state_.radius[k];
        out.mass[i] = state_.mass[k];
        out.inv_mass[i] = state_.inv_mass[k];
    }
}

std::map<std::string, std::string> CpuSolver::provenance() const {
    auto on_off = [](bool b) { return std::string(b ? "on" : "off"); };
    return {
        {"cpu.threads", std::to_string(threads_)},
        {"cpu.openmp", std::to_string(_OPENMP)},
        {"cpu.specialise", on_off(specialise_)},
        {"cpu.sort_interval", std::to_string(sort_interval_)},
        {"cpu.skin", round_trip_text(skin_)},
        {"cpu.features", "gravity=" + on_off(features_.gravity) + " damping=" + on_off(features_.damping) +
                             " friction=" + on_off(features_.friction) + " stones=" + on_off(features_.stones) +
                             " uniform_radius=" + on_off(features_.uniform_radius) +
                             " periodic=" + on_off(features_.periodic)},
    };
}

}  // namespace collide::cpu
