#pragma once
// Input blocks shared by module 1 (wheel/rail) and module 3 (basic contact): iteration
// parameters, friction-law lines, the material block, damping, heat and subsurface points
// (spec/inp-format.md §4, §4.1, §6). Each function reads its lines, validates ranges and
// stores the values; "keep" semantics are the caller's business.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "format/inp/case_record.hpp"
#include "format/text/inp_stream.hpp"

namespace rollcontact::format {

/// The note a case with the solver digit G=5 (GDsteady, an algorithm choice) gets in its report.
inline constexpr const char* kGdSteadyNote =
    "G=5 (GDsteady) is solved with rollcontact's steady-rolling solver (semismooth Newton); its "
    "parameter line is read and not used";

/// The note a wheel/rail case gets for a contact-search digit that only chooses CONTACT's
/// variant of the search (D = 3, 6, 7, 8, 9; empty for the others).
std::string contact_search_note(int d);

/// Iteration line `MAXGS MAXIN MAXNR MAXOUT EPS {NPOT_MAX}` and the G-specific line (G=2,3,4,5).
/// Resets the G-specific parameters to their defaults first; sets solver.method = g. Returns
/// NPOT_MAX when given (module 1 uses it, module 3 ignores it).
std::optional<int> read_solver_lines(InpStream& in, int g, SolverSettings& solver);

/// Coulomb friction (L=0) needs FSTAT = FKIN within 0.1 % and FKIN ≥ 1e-4; sets FSTAT := FKIN.
/// `line_fstat`/`line_fkin` are the lines of the two values for the messages.
void check_coulomb_values(InpStream& in, FrictionValues& fv, int line_fstat, int line_fkin);

/// Rules of the material-model digits shared by modules 1 and 3: M=1 (viscoelastic) and H ≥ 1
/// (temperature) need steady rolling T=3; H=1 needs heat parameters read before (`has_heat`).
void check_rolling_model_digits(InpStream& in, const ControlDigits& d, bool has_heat,
                                const std::string& element, int line2, int line3);

/// L=6 (temperature-dependent friction, `law` in effect) needs H ≥ 1 and is not allowed with the
/// simplified theories M=2, 3, 5, 6, 7.
void check_friction_law_digits(InpStream& in, const ControlDigits& d, int law, int line2);

/// Consistency rules of inp-format.md §3.2 that modules 1 and 3 share: in the first case of a
/// result element P and I are overridden (message to `warnings`) and L=1, D=0/1 are errors
/// (`kept_grid` names what D keeps, `keep_grid_hint` ends the message); S=1,2 need stored
/// subsurface points; L=1 may not
/// keep the friction while V changes (`previous_v` of the last case, ignored in a first case).
/// `line2`/`line1` are the lines of control words 2 and 1 for the messages.
void apply_shared_digit_rules(InpStream& in, ControlDigits& d, bool first, int previous_v,
                              bool has_subsurface, const std::string& element, int line1, int line2,
                              std::string_view kept_grid, std::string_view keep_grid_hint,
                              std::vector<std::string>& warnings);

/// True for the friction laws followed by a `MEMDST MEM_S0` line (L=2,3,4,6).
constexpr bool friction_law_has_memory(int law) {
  return law == 2 || law == 3 || law == 4 || law == 6;
}

/// One friction-law line of §4.1 for law 0, 2, 3, 4 or 6 (no V=1/2 prefix); `what` names it in
/// messages. Checks FSTAT = FKIN (0.1 %) and FKIN >= 1e-4 for L=0, FKIN >= 0 for L=2..4.
FrictionValues read_friction_values(InpStream& in, int law, std::string_view what);

/// The `MEMDST MEM_S0` line.
void read_friction_memory(InpStream& in, Friction& friction);

/// Copies one set of values into the scalar members of `friction`.
void assign_friction_values(const FrictionValues& values, Friction& friction);

/// Material block: `POISS1 POISS2 GG1 GG2`, then `FLXZ` (b=1) and the M-specific line (m=1..5).
/// Checks POISS in [0, 0.5] and GG >= 1e-5. M=4: TAU_C0 >= 1e10 is stored as 0.
void read_material_block(InpStream& in, int b, int m, Materials& materials);

/// Damping line `CDAMPN CDAMPT DFNMAX DFTMAX` (M2=2); enables damping.
void read_damping_line(InpStream& in, Damping& damping);

/// Heat lines for both bodies (H=3), then `BETAPL` when `with_betapl` (M=4).
void read_heat_lines(InpStream& in, bool with_betapl, HeatParameters& heat);

/// Subsurface block (S>=2): `MATFIL_S OUTPUT_S` (clamped to 0..2, 0..4 with a warning), and for
/// s=3 the list of ISUBS blocks that replaces the stored one. Warnings are appended.
void read_subsurface_block(InpStream& in, int s, Subsurface& subsurface,
                           std::vector<std::string>& warnings);

}  // namespace rollcontact::format
