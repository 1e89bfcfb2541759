// How a lighting model describes its parameters: one entry per field of the
// model's struct (shading/model/<name>.h), in the order the scene file
// documents them, the loader reads them and the writer writes them.
//
// The scene loader and writer and the precision limits iterate these
// entries (forEachParam) and name no field themselves, so a model's
// parameter is declared once: its name and field here, its default as the
// struct member's initializer, its range and unit beside it.
#pragma once

#include <glm/glm.hpp>

#include <array>
#include <tuple>
#include <utility>

namespace xval::model {

// The values a number (or each channel of a colour) may take; the loader
// rejects others with its range message (scene/json_reader.h Range).
struct ParamRange {
  double lo = -1e300, hi = 1e300;
  bool lo_open = false, hi_open = false;
};
inline constexpr ParamRange kAnyNumber{};
inline constexpr ParamRange kNonNegative{0.0, 1e300, false, false};
inline constexpr ParamRange kUnitInterval{0.0, 1.0, false, false};

enum class Unit {
  Weight,    // a dimensionless factor of a term
  Exponent,  // the specular power n of clamp(R.V)^n
  Luma,      // a luma (Y of YIQ) added to the result
  Colour,    // linear RGB per unit light colour, multiplying the light's colour
};

// A number's part in the precision bound (scene_file/precision_limits.cpp): the
// model coefficients K sum the |value| of Coefficient and Specular numbers;
// Specular is also the ks of the specular weight; the Forsyth colours F sum
// the colours. A model whose specular term can exceed 1 per unit ks has
// `double specularGain() const`, its bound, which multiplies its Specular
// number in K (cook_torrance).
enum class Role { None, Coefficient, Specular };

template <class M> struct NumberParam {
  const char* name;
  double M::*field;
  Unit unit;
  ParamRange range;
  Role role;
};
// A colour [r, g, b]; every channel in `range`. Part of F (above).
template <class M> struct ColourParam {
  const char* name;
  glm::dvec3 M::*field;
  ParamRange range;
};
// One of named values (a string in the scene file).
template <class M, class E, std::size_t N> struct ChoiceParam {
  const char* name;
  E M::*field;
  std::array<std::pair<const char*, E>, N> options;
  const char* nameOf(E v) const {
    for (const auto& [n, e] : options)
      if (e == v) return n;
    return options[0].first;  // unreachable: every value of E is an option
  }
};

// f(param, m.*param.field) for every parameter of m, in order.
template <class M, class F> void forEachParam(M& m, F&& f) {
  std::apply([&](const auto&... p) { (f(p, m.*p.field), ...); }, std::remove_const_t<M>::params());
}

// For std::visit and forEachParam with one lambda per alternative.
template <class... Fs> struct Overloaded : Fs... {
  using Fs::operator()...;
};
template <class... Fs> Overloaded(Fs...) -> Overloaded<Fs...>;

}  // namespace xval::model
