// for_each_field(object, f): calls f on every field of a plain aggregate struct, in declaration
// order, without naming them. Used where every field must count and a field added later must
// count too without anyone remembering to list it (a case's definition hashes an outside
// solver's whole spec, validation/plan/case_definition.h).
//
// How: the number of fields is the most initialisers `T{...}` accepts from an object that
// converts to anything (C++20 aggregate initialisation), and structured bindings then name
// them. This holds for structs of scalars, strings and containers (not for a field that is
// itself an aggregate, whose braces could be elided), up to 16 fields; more fails to compile.
#pragma once

#include <cstddef>

namespace collide {
namespace aggregate_detail {

struct AnyField {
    template <class T>
    operator T() const;  // never defined: only asked about in unevaluated contexts
};

template <class T, class... Fields>
constexpr std::size_t field_count() {
    if constexpr (requires { T{Fields{}..., AnyField{}}; })
        return field_count<T, Fields..., AnyField>();
    else
        return sizeof...(Fields);
}

}  // namespace aggregate_detail

template <class T>
inline constexpr std::size_t field_count_v = aggregate_detail::field_count<T>();

template <class T, class F>
void for_each_field(const T& t, F&& f) {
    constexpr std::size_t n = field_count_v<T>;
    static_assert(n >= 1 && n <= 16, "for_each_field: 1 to 16 fields");
    if constexpr (n == 1) { const auto& [a] = t; f(a); }
    else if constexpr (n == 2) { const auto& [a, b] = t; f(a), f(b); }
    else if constexpr (n == 3) { const auto& [a, b, c] = t; f(a), f(b), f(c); }
    else if constexpr (n == 4) { const auto& [a, b, c, d] = t; f(a), f(b), f(c), f(d); }
    else if constexpr (n == 5) { const auto& [a, b, c, d, e] = t; f(a), f(b), f(c), f(d), f(e); }
    else if constexpr (n == 6) { const auto& [a, b, c, d, e, g] = t; f(a), f(b), f(c), f(d), f(e), f(g); }
    else if constexpr (n == 7) { const auto& [a, b, c, d, e, g, h] = t; f(a), f(b), f(c), f(d), f(e), f(g), f(h); }
    else if constexpr (n == 8) {
        const auto& [a, b, c, d, e, g, h, i] = t;
        f(a), f(b), f(c), f(d), f(e), f(g), f(h), f(i);
    } else if constexpr (n == 9) {
        const auto& [a, b, c, d, e, g, h, i, j] = t;
        f(a), f(b), f(c), f(d), f(e), f(g), f(h), f(i), f(j);
    } else if constexpr (n == 10) {
        const auto& [a, b, c, d, e, g, h, i, j, k] = t;
        f(a), f(b), f(c), f(d), f(e), f(g), f(h), f(i), f(j), f(k);
    } else if constexpr (n == 11) {
        const auto& [a, b, c, d, e, g, h, i, j, k, l] = t;
        f(a), f(b), f(c), f(d), f(e), f(g), f(h), f(i), f(j), f(k), f(l);
    } else if constexpr (n == 12) {
        const auto& [a, b, c, d, e, g, h, i, j, k, l, m] = t;
        f(a), f(b), f(c), f(d), f(e), f(g), f(h), f(i), f(j), f(k), f(l), f(m);
    } else if constexpr (n == 13) {
        const auto& [a, b, c, d, e, g, h, i, j, k, l, m, o] = t;
        f(a), f(b), f(c), f(d), f(e), f(g), f(h), f(i), f(j), f(k), f(l), f(m), f(o);
    } else if constexpr (n == 14) {
        const auto& [a, b, c, d, e, g, h, i, j, k, l, m, o, p] = t;
        f(a), f(b), f(c), f(d), f(e), f(g), f(h), f(i), f(j), f(k), f(l), f(m), f(o), f(p);
    } else if constexpr (n == 15) {
        const auto& [a, b, c, d, e, g, h, i, j, k, l, m, o, p, q] = t;
        f(a), f(b), f(c), f(d), f(e), f(g), f(h), f(i), f(j), f(k), f(l), f(m), f(o), f(p), f(q);
    } else {
        const auto& [a, b, c, d, e, g, h, i, j, k, l, m, o, p, q, r] = t;
        f(a), f(b), f(c), f(d), f(e), f(g), f(h), f(i), f(j), f(k), f(l), f(m), f(o), f(p), f(q), f(r);
    }
}

}  // namespace collide
