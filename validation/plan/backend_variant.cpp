#include "validation/plan/backend_variant.h"

#include <algorithm>
#include <memory>

namespace collide::validation {
namespace {

std::string settings_text(const BackendVariant& variant) {
    std::string text;
    for (const auto& [key, value] : variant.settings) text += (text.empty() ? "" : ", ") + key + " = " + value;
    return text;
}

// Passes every call to the base backend's solver; only load() changes the scene.
class VariantSolver : public Solver {
public:
    VariantSolver(std::unique_ptr<Solver> inner, BackendVariant variant)
        : inner_(std::move(inner)), variant_(std::move(variant)) {}

    std::string name() const override { return inner_->name(); }
    void load(const Scene& scene, const ParticleState<double>& initial) override {
        inner_->load(scene_for_variant(scene, variant_), initial);
    }
    void plan_outputs(const std::vector<double>& times) override { inner_->plan_outputs(times); }
    void advance_to(double t) override { inner_->advance_to(t); }
    void read_state(ParticleState<double>& out) const override { inner_->read_state(out); }
    double time() const override { return inner_->time(); }
    SolverStats stats() const override { return inner_->stats(); }
    // The base's own record of its effective settings, plus which variant asked for them.
    std::map<std::string, std::string> provenance() const override {
        auto p = inner_->provenance();
        p["variant"] = variant_.label;
        p["variant_settings"] = settings_text(variant_);
        return p;
    }

private:
    std::unique_ptr<Solver> inner_;
    BackendVariant variant_;
};

}  // namespace

Scene scene_for_variant(const Scene& scene, const BackendVariant& variant) {
    Scene out = scene;
    auto& table = out.backend_options[variant.base];
    for (const auto& [key, value] : variant.settings) {
        table[key] = value;
        out.backend_option_origins[variant.base].erase(key);  // (the suite's value, not the file's)
    }
    return out;
}

BackendInfo variant_backend(const BackendInfo& base, const BackendVariant& variant) {
    BackendInfo info = base;
    info.name = variant.label;
    info.description = base.description + " [" + settings_text(variant) + "]";
    info.supports = [supports = base.supports, variant](const Scene& scene) { return supports(scene_for_variant(scene, variant)); };
    info.create = [create = base.create, variant](const BackendOptions& options) -> std::unique_ptr<Solver> {
        return std::make_unique<VariantSolver>(create(options), variant);
    };
    return info;
}

std::string backend_id_token(const std::string& label) {
    std::string token = label;
    std::replace(token.begin(), token.end(), '[', '-');
    token.erase(std::remove(token.begin(), token.end(), ']'), token.end());
    return token;
}

void apply_variant_leave_outs(std::vector<CheckResult>& checks, const std::vector<BackendVariant>& variants) {
    for (const BackendVariant& v : variants)
        for (CheckResult& c : checks)
            if (c.backend == v.label && std::find(v.leave_out.begin(), v.leave_out.end(), c.check) != v.leave_out.end()) {
                c.status = CheckStatus::left_out;
                c.detail = v.leave_out_reason;
            }
}

}  // namespace collide::validation
