#pragma once
// Vocabulary of TOML case files (docs/case-files.md): the names that replace the control digits
// of .inp files. Shared by the TOML reader and writer so both spell every choice the same way.

#include <array>
#include <optional>
#include <span>
#include <string_view>

namespace rollcontact::format::toml_schema {

/// One named choice and the digit (or code) it stands for in a CaseRecord.
struct Choice {
  int code;
  std::string_view name;
};

/// The code of `name`, or nothing when `name` is not one of `choices`.
inline std::optional<int> code_of(std::span<const Choice> choices, std::string_view name) {
  for (const Choice& c : choices)
    if (c.name == name) return c.code;
  return std::nullopt;
}

/// The name of `code`; empty when the code has no name (callers validate before writing).
inline std::string_view name_of(std::span<const Choice> choices, int code) {
  for (const Choice& c : choices)
    if (c.code == code) return c.name;
  return {};
}

/// P digit (previous time).
inline constexpr std::array<Choice, 4> previous_state{
    {{2, "new"}, {0, "continue"}, {1, "continue_normal"}, {3, "keep"}}};
/// I digit (initial estimate).
inline constexpr std::array<Choice, 4> initial_estimate{
    {{0, "none"}, {1, "previous_regularised"}, {2, "previous_normal"}, {3, "previous"}}};
/// B digit (normal method).
inline constexpr std::array<Choice, 7> normal_method{{{0, "exact"},
                                                      {1, "exact_with_layer"},
                                                      {2, "elliptic"},
                                                      {3, "parabolic"},
                                                      {4, "sdec"},
                                                      {5, "kpec"},
                                                      {6, "analyn"}}};
/// T digit (tangential problem).
inline constexpr std::array<Choice, 4> tangential_problem{
    {{0, "none"}, {1, "shift"}, {2, "transient_rolling"}, {3, "steady_rolling"}}};
/// E digit after resolving "keep" (Kinematics::extra_slip_mode).
inline constexpr std::array<Choice, 4> extra_slip{
    {{0, "none"}, {2, "drop_spin_y"}, {3, "drop_spin_x"}, {9, "per_element"}}};
/// L digit after resolving "keep" (Friction::law).
inline constexpr std::array<Choice, 5> friction_law{{{0, "coulomb"},
                                                     {2, "linear_falling"},
                                                     {3, "rational_falling"},
                                                     {4, "exponential_falling"},
                                                     {6, "temperature"}}};
/// M digit (material model).
inline constexpr std::array<Choice, 8> material_model{{{0, "elastic"},
                                                       {1, "viscoelastic"},
                                                       {2, "fastsim_one_flexibility"},
                                                       {3, "fastsim_three_flexibilities"},
                                                       {4, "interfacial_layer"},
                                                       {5, "fastrip"},
                                                       {6, "fastrip_variant_6"},
                                                       {7, "fastrip_variant_7"}}};
/// C digit after resolving "keep" (Materials::influence_type).
inline constexpr std::array<Choice, 4> influence{
    {{2, "half_space"}, {3, "half_space_bilinear"}, {4, "conformal"}, {9, "from_file"}}};
/// G digit after resolving "keep" (SolverSettings::method).
inline constexpr std::array<Choice, 5> solver_method{{{0, "default"},
                                                      {2, "convex_gs"},
                                                      {3, "steady_gs"},
                                                      {4, "default_with_slip_velocity"},
                                                      {5, "gd_steady"}}};
/// A digit (.mat output).
inline constexpr std::array<Choice, 3> mat_file{
    {{0, "none"}, {1, "contact"}, {2, "potential_contact"}}};
/// GAPWGT (module 1 centre weighting; carried by module-3 input too).
inline constexpr std::array<Choice, 2> gap_weighting{{{0, "squared"}, {1, "linear"}}};
/// MATFIL_S (subsurface .subs file contents).
inline constexpr std::array<Choice, 3> subsurface_file{
    {{0, "none"}, {1, "stresses"}, {2, "stress_tensor"}}};

/// Version of the schema written by the writer and accepted by the reader.
inline constexpr int version = 1;

}  // namespace rollcontact::format::toml_schema
