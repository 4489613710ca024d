// Technique tables: one row per value of a lab's enum (a shadow filter, a surface technique, a
// view), holding everything about that value that is not code: the name the CLI, presets and the
// panel use, the #define its shaders test, texture formats, what it needs. One table replaces
// parallel arrays matched by index, which still compile when they fall out of step.
//
// The enum ends with `Count`, one past its last value, and the table is checked where it is
// written, so adding an enumerator without its row (or rows out of order) does not compile:
//
//   enum class Tonemap { Linear, Reinhard, Count };
//   inline constexpr NamedDefine<Tonemap> kTonemaps[] = {{Tonemap::Linear, "linear", "TONEMAP_LINEAR"},
//                                                        {Tonemap::Reinhard, "reinhard", "TONEMAP_REINHARD"}};
//   static_assert(coversEnum<Tonemap>(kTonemaps));
//   ... v.enumParam(info, p.tonemap, namesOf<kTonemaps>);  rowOf(kTonemaps, p.tonemap).define
#pragma once
#include <array>
#include <cstddef>
#include <span>
#include <string_view>

namespace shadelab {

// The row of a table whose values need only a name (an input, a device).
template <typename E>
struct Named {
  E value;
  std::string_view name;  // as --set and presets spell it
};

// The row of a table whose values need only a name and a #define (views, mip modes).
template <typename E>
struct NamedDefine {
  E value;
  std::string_view name;    // as --set and presets spell it
  std::string_view define;  // what the lab's shaders test
};

// One row per enumerator of E, in order: row i holds the value E(i).
template <typename E, typename Row, std::size_t N>
constexpr bool coversEnum(const Row (&rows)[N]) {
  if (N != static_cast<std::size_t>(E::Count)) return false;
  for (std::size_t i = 0; i < N; ++i)
    if (static_cast<std::size_t>(rows[i].value) != i) return false;
  return true;
}

template <typename Row, std::size_t N, typename E>
constexpr const Row& rowOf(const Row (&rows)[N], E value) {
  return rows[static_cast<std::size_t>(value)];
}

// The names column of a table, in the form ParamVisitor::enumParam takes.
template <const auto& Rows>
inline constexpr auto kNamesColumn = [] {
  std::array<std::string_view, std::size(Rows)> names{};
  for (std::size_t i = 0; i < names.size(); ++i) names[i] = Rows[i].name;
  return names;
}();

template <const auto& Rows>
constexpr std::span<const std::string_view> namesOf() {
  return kNamesColumn<Rows>;
}

}  // namespace shadelab
