#include "core/scene/option_reader.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "core/scene/toml_fields.h"

namespace collide {
namespace {

// The whole text as a number of type T (std::from_chars: no sign '+', no spaces, nothing after).
template <typename T>
std::optional<T> parse_whole(const std::string& text) {
    T value{};
    const char* end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, value);
    if (error != std::errc() || stop != end || text.empty()) return std::nullopt;
    return value;
}

}  // namespace

OptionReader::OptionReader(std::string backend, const Scene* scene, const std::map<std::string, std::string>& given)
    : backend_(std::move(backend)), scene_name_(scene ? scene->name : "") {
    if (scene) {
        const auto table = scene->backend_options.find(backend_);
        const auto origins = scene->backend_option_origins.find(backend_);
        if (table != scene->backend_options.end())
            for (const auto& [key, text] : table->second) {
                std::string origin;
                if (origins != scene->backend_option_origins.end())
                    if (const auto o = origins->second.find(key); o != origins->second.end()) origin = o->second;
                values_[key] = Value{text, origin, false};
            }
    }
    for (const auto& [key, text] : given) values_[key] = Value{text, "", true};
}

bool OptionReader::has(std::string_view key) const { return values_.find(key) != values_.end(); }

const OptionReader::Value* OptionReader::use(std::string_view key) {
    if (std::find(asked_.begin(), asked_.end(), key) == asked_.end()) asked_.emplace_back(key);
    const auto it = values_.find(key);
    return it == values_.end() ? nullptr : &it->second;
}

std::string OptionReader::where(const Value* v) const {
    if (v && v->given) return backend_ + ": option";
    const std::string prefix = v && !v->origin.empty() ? v->origin + ": " : "";
    return prefix + backend_ + ": scene '" + scene_name_ + "' [backend." + backend_ + "]";
}

void OptionReader::fail(std::string_view key, std::string_view expected) const {
    const auto it = values_.find(key);
    const Value* v = it == values_.end() ? nullptr : &it->second;
    throw BackendOptionError(where(v) + " " + std::string(key) + " = '" + shortened(v ? v->text : "") +
                             "': expected " + std::string(expected));
}

std::optional<std::int64_t> OptionReader::find_int(std::string_view key, std::int64_t min, std::int64_t max,
                                                   std::string_view expected) {
    const Value* v = use(key);
    if (!v) return std::nullopt;
    const auto n = parse_whole<std::int64_t>(v->text);
    if (!n || *n < min || *n > max) fail(key, expected);
    return n;
}

std::int64_t OptionReader::get_int(std::string_view key, std::int64_t fallback, std::int64_t min, std::int64_t max,
                                   std::string_view expected) {
    return find_int(key, min, max, expected).value_or(fallback);
}

std::optional<double> OptionReader::find_double(std::string_view key, double min, std::string_view expected,
                                                bool above) {
    const Value* v = use(key);
    if (!v) return std::nullopt;
    const auto x = parse_whole<double>(v->text);
    if (!x || !std::isfinite(*x) || (above ? !(*x > min) : !(*x >= min))) fail(key, expected);
    return x;
}

double OptionReader::get_double(std::string_view key, double fallback, double min, std::string_view expected,
                                bool above) {
    return find_double(key, min, expected, above).value_or(fallback);
}

bool OptionReader::get_bool(std::string_view key, bool fallback) {
    const Value* v = use(key);
    if (!v) return fallback;
    if (v->text != "true" && v->text != "false") fail(key, "true or false");
    return v->text == "true";
}

std::string OptionReader::get_string(std::string_view key, std::string_view fallback) {
    const Value* v = use(key);
    return v ? v->text : std::string(fallback);
}

std::string OptionReader::get_choice(std::string_view key, std::initializer_list<std::string_view> choices,
                                     std::string_view fallback) {
    const Value* v = use(key);
    if (!v) return std::string(fallback);
    for (std::string_view c : choices)
        if (v->text == c) return v->text;
    std::string list;
    std::size_t k = 0;
    for (std::string_view c : choices) {
        if (k > 0) list.append(k + 1 == choices.size() ? " or " : ", ");
        list.append(1, '"').append(c).append(1, '"');
        ++k;
    }
    fail(key, list);
}

void OptionReader::refuse_unknown() const {
    for (const auto& [key, value] : values_) {
        if (std::find(asked_.begin(), asked_.end(), key) != asked_.end()) continue;
        std::string known;
        for (const auto& k : asked_) known += (known.empty() ? "" : ", ") + k;
        throw BackendOptionError(where(&value) + ": unknown key '" + shortened(key) + "' (known: " + known + ")");
    }
}

}  // namespace collide
