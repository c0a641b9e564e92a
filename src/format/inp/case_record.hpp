#pragma once
// CaseRecord: one module-3 case as CONTACT's input describes it — control digits, the values
// of each block, where it came from. The .inp and TOML readers produce it, the writers echo
// it, and to_patch_problem() (format/inp/to_model.hpp) turns it into the solver's
// model::PatchProblem. This is the only place the control digits live.
// Units as in CONTACT: mm, N, N/mm², s, rad.

#include <array>
#include <string>
#include <vector>

#include "rollcontact/model/geometry.hpp"

namespace rollcontact::format {

using model::PotentialContact;
using model::SubsurfaceBlock;
using model::UndeformedDistance;

/// Debug print levels of control word 4 (read when X=1). They have no effect on results.
struct DebugDigits {
  int p = 0;       ///< profiles
  int s = 0;       ///< smoothing
  int f = 0;       ///< force loop
  int l = 0;       ///< contact search
  int c = 0;       ///< contact patches
  int i = 0;       ///< influence coefficients
  int n = 0;       ///< solver tables
  int readln = 0;  ///< input echo level (optional second integer of word 4)
};

/// Control digits of a case, as defined in spec/inp-format.md §3 (after the reader's consistency
/// overrides). They are kept verbatim because reports echo them and because several digits mean
/// "keep the stored value" in sequences.
struct ControlDigits {
  // word 1: P B T N F S
  int p = 2;  ///< previous time: 0 continue, 2 new sequence, 3 keep
  int b = 0;  ///< normal method: 0 full elastic, 2 elliptic, 3 parabolic, 4 SDEC, 5 KPEC, 6 ANALYN
  int t = 0;  ///< tangential: 0 none, 1 shift, 2 transient rolling, 3 steady rolling
  int n = 0;  ///< 0 approach PEN prescribed, 1 normal force FN prescribed
  int f = 0;  ///< 0 creepages prescribed, 1 FX and CETA, 2 FX and FY
  int s = 0;  ///< subsurface stresses
  // word 2: (V) L D C M Z E {10*GAPWGT + M2}
  int v = 0;       ///< variable friction
  int l = 0;       ///< friction law (0 Coulomb)
  int d = 2;       ///< discretisation: 0 keep, 1 rebuild, 2 new IPOTCN block
  int c = 2;       ///< influence coefficients: 0 keep, 1 recompute, 2 piecewise-constant half-space
  int m = 0;       ///< material model: 0 elastic
  int z = 2;       ///< undeformed distance: 0 keep, 1 rebuild, 2 new block
  int e = 0;       ///< extra rigid slip
  int m2 = 1;      ///< damping (0 off, 1 keep, 2 read)
  int gapwgt = 0;  ///< module 1 only
  // word 3: X H G I A O W R
  int x = 0;  ///< 1: word 4 (debug digits) present
  int h = 0;  ///< heat
  int g = 0;  ///< solver choice
  int i = 0;  ///< initial estimate
  int a = 0;  ///< .mat output
  int o = 1;  ///< report level 0..5
  int w = 0;  ///< trace level
  int r = 1;  ///< return digit
  // word 4 (only if x == 1)
  DebugDigits debug;  ///< debug print levels
};

/// Iteration parameters (line 5 of a module-3 case).
struct SolverSettings {
  int maxgs = 999;                      ///< max inner iterations (CG / Gauss-Seidel)
  int maxin = 100;                      ///< max outer (active-set / TANG) iterations
  int maxnr = 30;                       ///< max Newton iterations (F=1,2)
  int maxout = 1;                       ///< max Panagiotopoulos passes
  double eps = 1e-5;                    ///< relative tolerance
  double omega_h = 0.0, omega_s = 0.0;  ///< G=2,3 relaxation parameters (0: default)
  int inislp = 0;                       ///< G=2,3,4 initial slip velocity choice
  double omgslp = 1.0;                  ///< G=2,3,4 slip-velocity relaxation
  /// Effective solver choice after resolving G=1 ("keep"): 0 default, 2 ConvexGS, 3 SteadyGS,
  /// 4 default with slip-velocity parameters, 5 GDsteady.
  int method = 0;
  /// G=5 (GDsteady, experimental) parameters, as read.
  struct GdSteady {
    double fdecay = 0.0, betath = 0.0;
    int kdowfb = 0;
    double d_ifc = 0.0, d_lin = 0.0, d_cns = 0.0, d_slp = 0.0, pow_s = 0.0;
  } gd;
};

/// Loading and kinematics (line 7 and the rolling line). Which members are meaningful follows
/// from the N, F and T digits.
struct Kinematics {
  double pen = 0.0;                   ///< approach [mm] (N=0)
  double fn = 0.0;                    ///< total normal force [N] (N=1)
  double cksi = 0.0;                  ///< longitudinal creepage [-] (T=2,3) or shift [mm] (T=1)
  double ceta = 0.0;                  ///< lateral creepage [-] or shift [mm]
  double cphi = 0.0;                  ///< spin creepage [rad/mm] (T=2,3) or rotation [rad] (T=1)
  double fx_rel = 0.0;                ///< prescribed FX/(μ FN) (F=1,2)
  double fy_rel = 0.0;                ///< prescribed FY/(μ FN) (F=2)
  double spinxo = 0.0, spinyo = 0.0;  ///< spin centre [mm]
  double chi = 0.0;                   ///< rolling direction [rad]
  double dq = 1.0;                    ///< rolling step [mm]
  double veloc = 1.0;                 ///< rolling velocity [mm/s]
  double facphi = 1.0 / 6.0;          ///< spin-term offset factor
  /// Effective extra rigid slip (E digit after resolving E=1 "keep"): 0 none, 2/3 drop the spin
  /// term in w_y / w_x, 9 per-element values in extra_slip.
  int extra_slip_mode = 0;
  /// E=9: extra rigid slip per element, interleaved wx(1) wy(1) wx(2) wy(2) ..., element order
  /// ix fastest (2*mx*my values); same unit as CKSI/CETA ([-] rolling, [mm] shift T=1).
  std::vector<double> extra_slip;
};

/// One set of friction-law values (one line of spec/inp-format.md §4.1).
struct FrictionValues {
  double fstat = 0.3;              ///< static coefficient [-]
  double fkin = 0.3;               ///< kinetic coefficient [-] (L=6: FREF)
  std::array<double, 4> params{};  ///< values after FKIN (L=2,3,4: F1 SABSH1 F2 SABSH2; L=6: TREF
                                   ///< DFHEAT DTHEAT)
};

/// Friction law (line 8/9). law = L digit after resolving L=1 ("keep"); Coulomb uses fstat = fkin.
/// For the falling laws L=2,3,4 fstat is derived as FKIN + F1 + F2 (the value at zero slip
/// velocity); for L=6 fstat = fkin = FREF.
struct Friction {
  int law = 0;
  double fstat = 0.3;                 ///< static coefficient μ_s [-]
  double fkin = 0.3;                  ///< kinetic coefficient [-]
  std::array<double, 4> params{};     ///< law-specific values after FKIN (L=2,3,4,6)
  double memdst = 0.0, mem_s0 = 0.0;  ///< L=2,3,4,6 memory distance [mm], velocity [mm/s]
  /// V=3 (variable friction, one set per grid row iy=1..MY); empty for V=0. The scalar members
  /// above then hold the set of row 1.
  std::vector<FrictionValues> rows;
};

/// Elastic constants of the two bodies (line 13) and model-specific material data.
struct Materials {
  double poiss1 = 0.28, poiss2 = 0.28;   ///< Poisson ratios [-]
  double gg1 = 82000.0, gg2 = 82000.0;   ///< shear moduli [N/mm²]
  std::array<double, 4> model_params{};  ///< M-specific line (FLX.., GG3 LAYTHK ..) as read
                                         ///< (M=4: TAU_C0 >= 1e10 is stored as 0, no plasticity)
  double flxz = 0.0;                     ///< B=1 normal layer flexibility [mm³/N]
  /// Influence coefficients in effect (C digit after resolving C=0/1 "keep"): 2 piecewise
  /// constant, 3 bilinear, 4 conformal correction, 9 from file.
  int influence_type = 2;
  /// C=9: path of the coefficient file, resolved against the .inp folder (not read by io).
  std::string influence_file;
  /// C=4 (experimental) conformal correction: IF_METH, VARIANT and the NN pairs (y [mm], alpha
  /// [rad]) of the surface inclination table.
  struct Conformal {
    int if_meth = 0, variant = 1;
    std::vector<double> y, alpha;
  } conformal;
};

/// Damping (M2=2 line). Active when `enabled` (M2=2, or M2=1 keeping an active setting).
struct Damping {
  bool enabled = false;
  double cdampn = 0.0, cdampt = 0.0;  ///< time constants [s]
  double dfnmax = 0.0, dftmax = 0.0;  ///< maximum force rates [N/s]
};

/// Temperature calculation (H=3 lines); used when digits.h >= 1.
struct HeatParameters {
  double bktemp1 = 0.0, heatcp1 = 0.0, lambda1 = 0.0, dens1 = 0.0;  ///< body 1: °C, J/(kg °C),
                                                                    ///< W/(mm °C), kg/mm³
  double bktemp2 = 0.0, heatcp2 = 0.0, lambda2 = 0.0, dens2 = 0.0;  ///< body 2, same units
  double betapl = 0.0;  ///< M=4: fraction of plastic work turned into heat [0..1]
};

/// Subsurface stress request (S>=2 input); evaluated when digits.s >= 1.
struct Subsurface {
  int matfil = 0;  ///< 0 no .subs file, 1 displacements + σ_hyd, σ_vm, 2 also the tensor
  int output = 0;  ///< 0 nothing, 1-3 maxima per block, 4 also all points to the .out
  std::vector<SubsurfaceBlock> blocks;
};

/// Where a case came from, for messages (empty/0 for API-built problems).
struct SourceInfo {
  std::string file;
  int first_line = 0;                ///< line of control word 1
  std::array<int, 4> digit_lines{};  ///< line of control words 1..4
  int module_line = 0;               ///< line of the module line before this case (0: none, R=0/2)
  /// Consistency overrides applied while reading (spec/inp-format.md §3.2), one sentence each.
  std::vector<std::string> warnings;
  /// Non-empty: this case cannot be computed (e.g. its C=9 coefficient file is missing). Report
  /// the message for this case and continue with the next one.
  std::string case_error;
};

/// One module-3 contact case.
struct CaseRecord {
  int case_number = 1;      ///< 1-based, per result element
  int result_element = 0;   ///< REID
  int contact_problem = 1;  ///< CPID
  ControlDigits digits;
  SolverSettings solver;
  Kinematics kinematics;
  Friction friction;
  Materials materials;
  PotentialContact potential;
  UndeformedDistance geometry;
  Damping damping;
  HeatParameters heat;
  Subsurface subsurface;
  SourceInfo source;
};

}  // namespace rollcontact::format
