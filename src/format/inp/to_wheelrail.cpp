// WheelRailRecord → model::WheelRailProblem (spec/inp-format.md §5, physics.md §13).

#include "format/inp/to_wheelrail.hpp"

#include <fmt/format.h>

#include "format/inp/to_model.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::format {

namespace {

[[noreturn]] void not_supported(const std::string& what) {
  throw NotSupportedError("not supported yet: module 1 " + what);
}

}  // namespace

model::WheelRailProfile to_wheelrail_profile(const ProfileSpec& s) {
  model::WheelRailProfile p;
  p.points = *s.profile;
  p.smoothing.method = s.ismooth;
  p.smoothing.smooth = s.smooth;
  p.smoothing.zigzag_threshold_rad = s.zigthrs;
  p.smoothing.kink_high_rad = s.kinkhigh;
  p.smoothing.kink_low_rad = s.kinklow;
  p.smoothing.kink_window_mm = s.kinkwid;
  p.smoothing.max_omitted_fraction = s.maxomit;
  return p;
}

namespace {

/// The settings every patch shares, through the module-3 adapter: a case record with the
/// module-1 meanings of N, F, E, Z taken out (each patch is posed with its approach and its
/// creepages; F=1's FX_WS is the wheelset's, not a patch's relative force).
model::PatchProblem patch_template(const WheelRailRecord& r) {
  CaseRecord t = settings_record(r);
  t.digits.n = 0;
  t.digits.f = 0;
  t.digits.e = 0;
  t.digits.z = 0;
  t.digits.v = 0;
  t.digits.g = r.solver.method;
  return to_patch_problem(t);
}

}  // namespace

CaseRecord identity_record(const WheelRailRecord& r) {
  CaseRecord p;
  p.case_number = r.case_number;
  p.result_element = r.result_element;
  p.digits = r.digits;
  p.solver = r.solver;
  p.friction = r.friction;
  p.source = r.source;
  return p;
}

CaseRecord settings_record(const WheelRailRecord& r) {
  CaseRecord p = identity_record(r);
  p.materials = r.materials;
  p.damping = r.damping;
  p.heat = r.heat;
  p.subsurface = r.subsurface;
  return p;
}

void check_supported(const WheelRailRecord& r) {
  const ControlDigits& d = r.digits;
  // D=4 (conformal contact) solves each patch on a curved reference surface
  // (wheelrail-advanced.md §1); D=3, 6-9 only choose CONTACT's search variant and are solved
  // with D=2 or D=5 (contact_search_note()).
  // F=1 (FX_WS prescribed), F=2 (MY_WS prescribed; both experimental in CONTACT, VPITCH solved)
  // and F=3 (massless rail) are solved.
  // KPEC/ANALYN (B=5, 6) reproduce mbench_a22_kpec cases 2-5; the wheel/rail solver refuses
  // the patches where they do not (cases 1 and 6; model::WheelRailProblem::validated_only).
  // V=1, 2: the wheel/rail solver interpolates the friction per patch (model::FrictionVariation);
  // mbench_a22_varfric cases 1, 2, 4 and 6 give CONTACT's digits. Case 3, whose two patches lie
  // between D_SEP and D_TURN, is refused by the solver (validated_only) until the turning rule
  // agrees (docs/decisions.md).
  // Wheel slices (wheelflat): refused by the solver unless the run solves unvalidated
  // features (model::WheelRailProblem::validated_only; docs/decisions.md, "Variable wheel
  // profiles").
  // Flash temperatures per patch as in module 3 (spec/physics.md §15), steady rolling and
  // static cases only, like module 3.
  if (d.h != 0 && d.t != 0 && d.t != 3)
    not_supported(fmt::format("temperature H={} with T={} (steady rolling only)", d.h, d.t));
  // Force damping (M2=2, physics.md §12) adds C·dF/dt to a patch's forces, the rate taken from
  // the previous case of the sequence. The first case of a sequence (P=2) has no damping and is
  // solved as it stands; later ones are refused rather than reported undamped, until the rate's
  // time step between cases is settled (no reference case uses it; docs/decisions.md).
  const Damping& damping = r.damping;
  if (damping.enabled && d.p != 2 && (damping.cdampn != 0.0 || damping.cdampt != 0.0))
    not_supported(
        fmt::format("force damping M2=2 (CDAMPN = {} s, CDAMPT = {} s) in a case that "
                    "continues a sequence (P={}); a new sequence (P=2) has no damping",
                    damping.cdampn, damping.cdampt, d.p));
}

model::WheelRailProblem to_wheelrail_problem(const WheelRailRecord& r, bool solve_unvalidated) {
  check_supported(r);
  model::WheelRailProblem p;
  p.side = r.is_left() ? model::WheelSide::Left : model::WheelSide::Right;
  p.patch = patch_template(r);
  p.rail = to_wheelrail_profile(r.rail);
  p.wheel = to_wheelrail_profile(r.wheel);
  if (r.wheel.sliced) {
    p.wheel.slices = *r.wheel.slices;
    if (!p.wheel.slices.slices.empty()) p.wheel.points = p.wheel.slices.slices.front();
  }
  if (r.rail.sliced) {
    p.rail.slices = *r.rail.slices;
    if (!p.rail.slices.slices.empty()) p.rail.points = p.rail.slices.slices.front();
  }
  const TrackDimensions& tr = r.track;
  p.track = {tr.gaught, tr.gaugwd, tr.raily0, tr.railz0, r.is_roller() ? 0.0 : tr.cant, tr.curv};
  if (r.is_roller()) p.roller = {true, tr.nomradr, r.motion.rpitch};
  const RailDeviations& rd = r.rail_deviations;
  p.rail_state = {rd.dy, rd.dz, rd.droll, rd.vy, rd.vz, rd.vroll};
  const WheelsetDimensions& w = r.wheelset;
  p.wheelset = {w.fbdist, w.fbpos, w.nomradw, w.ytape};
  const WheelsetMotion& m = r.motion;
  p.motion = {m.s,  m.y,  m.z,  m.fz,    m.roll, m.yaw,   m.pitch,
              m.vs, m.vy, m.vz, m.vroll, m.vyaw, m.vpitch};
  const WheelDeviations& wd = r.wheel_deviations;
  p.wheel_deviation = {wd.dx, wd.dy, wd.dz, wd.droll, wd.dyaw, wd.dpitch,
                       wd.vx, wd.vy, wd.vz, wd.vroll, wd.vyaw, wd.vpitch};
  p.vertical = r.digits.n == 1 ? model::VerticalLoading::Force : model::VerticalLoading::Position;
  if (r.digits.f == 1) {
    p.longitudinal = model::LongitudinalLoading::Force;
    p.motion.fx_ws_N = m.fx;
  }
  if (r.digits.f == 2) {
    p.longitudinal = model::LongitudinalLoading::Moment;
    p.motion.my_ws_Nmm = m.my;
  }
  if (r.digits.f == 3) {
    if (!r.has_massless_rail)
      throw ProblemError("F=3 (massless rail) without the rail stiffness line");
    const MasslessRail& mr = r.massless_rail;
    p.massless_rail = {true, mr.ky, mr.fy, mr.kz, mr.fz, mr.dystep0};
  }
  const WheelRailDiscretisation& ds = r.discretisation;
  p.search = {ds.dx,     ds.ds,     ds.dqrel,  ds.a_sep,   ds.d_sep,
              ds.d_comb, ds.d_turn, ds.g_miss, r.npot_max, r.digits.gapwgt == 1};
  if (ds.method == 5 || ds.method == 6 || ds.method == 9)
    p.search.method = model::ContactSearch::GapGrid;
  p.search.conformal = ds.method == 4;
  p.first_of_sequence = r.case_number == 1;
  p.estimate_from_previous_case = r.digits.i >= 1;
  p.validated_only = !solve_unvalidated;
  const VariableFriction& vf = r.variable_friction;
  if (vf.v == 1 || vf.v == 2) {
    p.friction_variation.along = vf.v == 1 ? model::FrictionVariation::Along::RailInclination
                                           : model::FrictionVariation::Along::TrackPosition;
    p.friction_variation.positions = vf.positions;
    for (const FrictionValues& f : vf.sets)
      p.friction_variation.values.push_back(
          to_model_friction(r.friction.law, f, r.friction.memdst, r.friction.mem_s0));
  }
  return p;
}

}  // namespace rollcontact::format
