#pragma once
// What is prescribed for one contact patch: the normal load, the tangential loading (creepages
// or shifts, or total forces) and the rolling motion.
// Units: mm, N, rad, s; creepages dimensionless, spin in rad/mm.

#include <vector>

namespace rollcontact::model {

/// How the normal problem is posed.
enum class NormalLoadKind {
  Approach,  ///< the approach (penetration) is given, the force follows
  Force,     ///< the total normal force is given, the approach follows
};

/// Pressure model of the normal problem.
enum class PressureModel {
  ExactHalfSpace,     ///< solved with Kalker's half-space theory on the grid
  EllipticHertzian,   ///< prescribed elliptic (Hertzian) pressure of the Hertz solution
  ParabolicHertzian,  ///< prescribed parabolic pressure of the Hertz solution
  Kpec,               ///< KPEC approximation for a prescribed approach (B=5)
  Analyn,             ///< modified ANALYN approximation for a prescribed approach (B=6)
  Sdec,  ///< prescribed pressure on two half-ellipses of semi-axes a, b_neg, b_pos (B=4, IPOTCN=−6)
};

struct NormalLoading {
  NormalLoadKind kind = NormalLoadKind::Force;
  double approach_mm = 0.0;  ///< used when kind == Approach
  double force_N = 0.0;      ///< used when kind == Force (> 0)
  PressureModel pressure = PressureModel::ExactHalfSpace;
};

/// The tangential problem posed.
enum class TangentialKind {
  None,              ///< frictionless: normal problem only
  Shift,             ///< a quasi-static shift of one body against the other
  TransientRolling,  ///< one step of rolling from the previous state of a sequence
  SteadyRolling,     ///< the steady state of rolling
};

/// What the tangential loading prescribes.
enum class TangentialPrescribed {
  Creepages,                         ///< creepages (or shifts) given, forces follow
  LongitudinalForceLateralCreepage,  ///< FX/(μFN) and the lateral creepage given
  Forces,                            ///< FX/(μFN) and FY/(μFN) given
};

/// Rigid creepages of body 1 relative to body 2 (rolling) or, for shifts, the rigid shift
/// distances [mm, mm] and rotation [rad].
struct Creepages {
  double longitudinal = 0.0;     ///< ξ [-] (shift: x [mm])
  double lateral = 0.0;          ///< η [-] (shift: y [mm])
  double spin_rad_per_mm = 0.0;  ///< φ [rad/mm] (shift: rotation [rad])
};

/// Which rigid-slip components carry the spin term (CONTACT's E = 2, 3, experimental):
/// w_x = ξ − φ·y, w_y = η + φ·x with both, or one of them without its φ term.
enum class SpinInRigidSlip {
  Both,              ///< E = 0, 1, 9
  LongitudinalOnly,  ///< E = 2: w_y = η
  LateralOnly,       ///< E = 3: w_x = ξ
};

struct TangentialLoading {
  TangentialKind kind = TangentialKind::None;
  TangentialPrescribed prescribed = TangentialPrescribed::Creepages;
  Creepages creepage;
  double force_x_over_mu_fn = 0.0;                        ///< prescribed FX/(μ FN) [-]
  double force_y_over_mu_fn = 0.0;                        ///< prescribed FY/(μ FN) [-]
  double spin_centre_x_mm = 0.0, spin_centre_y_mm = 0.0;  ///< centre of the spin rotation [mm]
  /// Extra rigid slip per element, interleaved (x, y) per element with ix fastest (2·mx·my
  /// values), in the unit of the creepages; empty: none.
  std::vector<double> extra_slip;
  SpinInRigidSlip spin_terms = SpinInRigidSlip::Both;
};

/// The rolling motion (rolling problems only).
struct Rolling {
  double direction_rad = 0.0;             ///< χ: rolling direction [rad]
  double step_mm = 1.0;                   ///< δq: distance rolled per step [mm]
  double velocity_mm_per_s = 1.0;         ///< V [mm/s]
  double spin_offset_factor = 1.0 / 6.0;  ///< f_φ: where along the step spin is evaluated
};

}  // namespace rollcontact::model
