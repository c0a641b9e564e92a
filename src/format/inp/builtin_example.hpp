#pragma once
// The built-in default example run by `rollcontact example` (and the README's first command).

#include <string_view>

namespace rollcontact::format {

/// A wheel on a rail, normal contact only: S1002-like wheel (rolling radius 460 mm) on a rail head
/// with a 300 mm crown radius, 80 kN wheel load, steel (G = 82 GPa, ν = 0.28), Hertzian geometry
/// (IPOTCN = −1) on a 40 × 40 grid. In CONTACT's .inp language.
inline constexpr std::string_view builtin_example_inp =
    R"(% rollcontact built-in example: wheel on rail, normal contact.
% Wheel radius 460 mm (A1 = 1/(2*460) 1/mm), rail crown radius 300 mm (B1 = 1/(2*300) 1/mm),
% wheel load FN = 80 kN, steel on steel. Solved with Kalker's exact half-space theory.
 3  MODULE
  200100     P-B-T-N-F-S        PVTIME, BOUND , TANG  , NORM , FORCE, STRESS
  022020     L-D-C-M-Z-E        FRCLAW, DISCNS, INFLCF, MATER, RZNORM, EXRHS
 0000331   H-G-I-A-O-W-R  HEAT, GAUSEI, IESTIM, MATFIL, OUTPUT, FLOW, RETURN
   999   100    30     1   1e-5                     MAXGS, MAXIN, MAXNR, MAXOUT, EPS
  80000.      0.000        0.000       0.000        FN, CKSI, CETA, CPHI
  0.300       0.300                                 FSTAT, FKIN
  0.280       0.280        82000.      82000.       POISS 1,2,  GG 1,2
   -1                                               IPOTCN
   40   40   1.0869565e-3   1.6666667e-3   1.2      MX, MY, A1, B1, SCALE
 0  MODULE
)";

}  // namespace rollcontact::format
