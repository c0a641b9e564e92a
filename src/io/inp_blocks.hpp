#pragma once
// Input blocks shared by module 1 (wheel/rail) and module 3 (basic contact): iteration
// parameters, friction-law lines, the material block, damping, heat and subsurface points
// (spec/inp-format.md §4, §4.1, §6). Each function reads its lines, validates ranges and
// stores the values; "keep" semantics are the caller's business.

#include <string>
#include <string_view>
#include <vector>

#include "io/inp_stream.hpp"
#include "rollcontact/problem.hpp"

namespace rollcontact::io {

/// Iteration line `MAXGS MAXIN MAXNR MAXOUT EPS {NPOT_MAX}` and the G-specific line (G=2,3,4,5).
/// Resets the G-specific parameters to their defaults first; sets solver.method = g.
void read_solver_lines(InpStream& in, int g, SolverSettings& solver);

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

}  // namespace rollcontact::io
