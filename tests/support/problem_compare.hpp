#pragma once
// Field-by-field comparison of Problems for the case-file round trips (.inp <-> TOML, .inp ->
// .inp). Both writers make every case explicit, so "keep" digits and values a case does not use
// (stale members kept from earlier cases by the .inp reader) are first brought to one canonical
// form; everything else must be equal, reals exactly or to 1e-15 relative.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "format/inp/case_record.hpp"

namespace rollcontact::test {

/// `p` with explicit digits (D=2, Z=2, C, L, G, E resolved; M2 0/2; H, S 0/3; R 1/3) and the
/// members its choices do not use reset to their defaults.
inline format::CaseRecord canonical(format::CaseRecord p) {
  format::ControlDigits& d = p.digits;
  d.d = 2;
  d.z = 2;
  d.c = p.materials.influence_type;
  d.l = p.friction.law;
  d.g = p.solver.method;
  d.e = p.kinematics.extra_slip_mode;
  d.m2 = p.damping.enabled ? 2 : 0;
  d.h = d.h >= 1 ? 3 : 0;
  d.s = d.s >= 1 ? 3 : 0;
  d.r = (d.r == 2 || d.r == 3) ? 3 : 1;
  if (d.x == 0) d.debug = format::DebugDigits{};

  const format::Kinematics k0;
  format::Kinematics& k = p.kinematics;
  if (d.n == 1) k.pen = k0.pen;
  if (d.n == 0) k.fn = k0.fn;
  if (d.f >= 1) k.cksi = k0.cksi;
  if (d.f == 0) k.fx_rel = k0.fx_rel;
  if (d.f == 2) k.ceta = k0.ceta;
  if (d.f != 2) k.fy_rel = k0.fy_rel;
  if (d.t < 2) {
    k.chi = k0.chi;
    k.dq = k0.dq;
    k.veloc = k0.veloc;
    k.facphi = k0.facphi;
  }
  if (k.extra_slip_mode != 9) k.extra_slip.clear();

  format::Friction& f = p.friction;
  if (!(f.law == 2 || f.law == 3 || f.law == 4 || f.law == 6)) f.memdst = f.mem_s0 = 0.0;
  if (d.v != 3) f.rows.clear();

  const format::SolverSettings s0;
  format::SolverSettings& s = p.solver;
  if (s.method != 2 && s.method != 3) s.omega_h = s.omega_s = 0.0;
  if (s.method < 2 || s.method > 4) {
    s.inislp = s0.inislp;
    s.omgslp = s0.omgslp;
  }
  if (s.method != 5) s.gd = s0.gd;

  format::Materials& m = p.materials;
  if (d.b != 1) m.flxz = 0.0;
  if (d.m == 0 || d.m == 6 || d.m == 7) m.model_params = {};
  if (m.influence_type != 9) m.influence_file.clear();
  if (m.influence_type != 4) m.conformal = format::Materials::Conformal{};

  if (p.potential.ipotcn < 0) p.geometry = model::UndeformedDistance{};
  if (!p.damping.enabled) p.damping = format::Damping{};
  if (d.h == 0) p.heat = format::HeatParameters{};
  if (d.m != 4) p.heat.betapl = 0.0;
  if (d.s == 0) p.subsurface = format::Subsurface{};

  // Where a case came from is not part of the problem; whether it can be computed is.
  const bool failed = !p.source.case_error.empty();
  p.source = format::SourceInfo{};
  if (failed) p.source.case_error = "error";
  return p;
}

inline bool same_real(double a, double b) {
  if (a == b) return true;
  return std::abs(a - b) <= 1e-15 * std::max(std::abs(a), std::abs(b));
}

#define RC_EXPECT_REAL(a, b, name) \
  EXPECT_TRUE(same_real(a, b)) << name << ": " << (a) << " vs " << (b)

inline void expect_same_reals(const std::vector<double>& a, const std::vector<double>& b,
                              const std::string& name) {
  ASSERT_EQ(a.size(), b.size()) << name;
  for (std::size_t i = 0; i < a.size(); ++i)
    RC_EXPECT_REAL(a[i], b[i], name + "[" + std::to_string(i) + "]");
}

template <std::size_t N>
void expect_same_reals(const std::array<double, N>& a, const std::array<double, N>& b,
                       const std::string& name) {
  for (std::size_t i = 0; i < N; ++i)
    RC_EXPECT_REAL(a[i], b[i], name + "[" + std::to_string(i) + "]");
}

/// Compares every member of two Problems (call with canonical() forms).
inline void expect_same_problem(const format::CaseRecord& a, const format::CaseRecord& b) {
  EXPECT_EQ(a.case_number, b.case_number);
  EXPECT_EQ(a.result_element, b.result_element);
  EXPECT_EQ(a.contact_problem, b.contact_problem);

  const format::ControlDigits& x = a.digits;
  const format::ControlDigits& y = b.digits;
#define RC_DIGIT(m) EXPECT_EQ(x.m, y.m) << "digit " #m
  RC_DIGIT(p);
  RC_DIGIT(b);
  RC_DIGIT(t);
  RC_DIGIT(n);
  RC_DIGIT(f);
  RC_DIGIT(s);
  RC_DIGIT(v);
  RC_DIGIT(l);
  RC_DIGIT(d);
  RC_DIGIT(c);
  RC_DIGIT(m);
  RC_DIGIT(z);
  RC_DIGIT(e);
  RC_DIGIT(m2);
  RC_DIGIT(gapwgt);
  RC_DIGIT(x);
  RC_DIGIT(h);
  RC_DIGIT(g);
  RC_DIGIT(i);
  RC_DIGIT(a);
  RC_DIGIT(o);
  RC_DIGIT(w);
  RC_DIGIT(r);
  RC_DIGIT(debug.p);
  RC_DIGIT(debug.s);
  RC_DIGIT(debug.f);
  RC_DIGIT(debug.l);
  RC_DIGIT(debug.c);
  RC_DIGIT(debug.i);
  RC_DIGIT(debug.n);
  RC_DIGIT(debug.readln);
#undef RC_DIGIT

  const format::SolverSettings& s = a.solver;
  const format::SolverSettings& t = b.solver;
  EXPECT_EQ(s.maxgs, t.maxgs);
  EXPECT_EQ(s.maxin, t.maxin);
  EXPECT_EQ(s.maxnr, t.maxnr);
  EXPECT_EQ(s.maxout, t.maxout);
  RC_EXPECT_REAL(s.eps, t.eps, "eps");
  RC_EXPECT_REAL(s.omega_h, t.omega_h, "omega_h");
  RC_EXPECT_REAL(s.omega_s, t.omega_s, "omega_s");
  EXPECT_EQ(s.inislp, t.inislp);
  RC_EXPECT_REAL(s.omgslp, t.omgslp, "omgslp");
  EXPECT_EQ(s.method, t.method);
  RC_EXPECT_REAL(s.gd.fdecay, t.gd.fdecay, "gd.fdecay");
  RC_EXPECT_REAL(s.gd.betath, t.gd.betath, "gd.betath");
  EXPECT_EQ(s.gd.kdowfb, t.gd.kdowfb);
  RC_EXPECT_REAL(s.gd.d_ifc, t.gd.d_ifc, "gd.d_ifc");
  RC_EXPECT_REAL(s.gd.d_lin, t.gd.d_lin, "gd.d_lin");
  RC_EXPECT_REAL(s.gd.d_cns, t.gd.d_cns, "gd.d_cns");
  RC_EXPECT_REAL(s.gd.d_slp, t.gd.d_slp, "gd.d_slp");
  RC_EXPECT_REAL(s.gd.pow_s, t.gd.pow_s, "gd.pow_s");

  const format::Kinematics& k = a.kinematics;
  const format::Kinematics& q = b.kinematics;
  RC_EXPECT_REAL(k.pen, q.pen, "pen");
  RC_EXPECT_REAL(k.fn, q.fn, "fn");
  RC_EXPECT_REAL(k.cksi, q.cksi, "cksi");
  RC_EXPECT_REAL(k.ceta, q.ceta, "ceta");
  RC_EXPECT_REAL(k.cphi, q.cphi, "cphi");
  RC_EXPECT_REAL(k.fx_rel, q.fx_rel, "fx_rel");
  RC_EXPECT_REAL(k.fy_rel, q.fy_rel, "fy_rel");
  RC_EXPECT_REAL(k.spinxo, q.spinxo, "spinxo");
  RC_EXPECT_REAL(k.spinyo, q.spinyo, "spinyo");
  RC_EXPECT_REAL(k.chi, q.chi, "chi");
  RC_EXPECT_REAL(k.dq, q.dq, "dq");
  RC_EXPECT_REAL(k.veloc, q.veloc, "veloc");
  RC_EXPECT_REAL(k.facphi, q.facphi, "facphi");
  EXPECT_EQ(k.extra_slip_mode, q.extra_slip_mode);
  expect_same_reals(k.extra_slip, q.extra_slip, "extra_slip");

  const format::Friction& f = a.friction;
  const format::Friction& g = b.friction;
  EXPECT_EQ(f.law, g.law);
  RC_EXPECT_REAL(f.fstat, g.fstat, "fstat");
  RC_EXPECT_REAL(f.fkin, g.fkin, "fkin");
  expect_same_reals(f.params, g.params, "friction.params");
  RC_EXPECT_REAL(f.memdst, g.memdst, "memdst");
  RC_EXPECT_REAL(f.mem_s0, g.mem_s0, "mem_s0");
  ASSERT_EQ(f.rows.size(), g.rows.size());
  for (std::size_t r = 0; r < f.rows.size(); ++r) {
    RC_EXPECT_REAL(f.rows[r].fstat, g.rows[r].fstat, "rows.fstat");
    RC_EXPECT_REAL(f.rows[r].fkin, g.rows[r].fkin, "rows.fkin");
    expect_same_reals(f.rows[r].params, g.rows[r].params, "rows.params");
  }

  const format::Materials& m = a.materials;
  const format::Materials& n = b.materials;
  RC_EXPECT_REAL(m.poiss1, n.poiss1, "poiss1");
  RC_EXPECT_REAL(m.poiss2, n.poiss2, "poiss2");
  RC_EXPECT_REAL(m.gg1, n.gg1, "gg1");
  RC_EXPECT_REAL(m.gg2, n.gg2, "gg2");
  expect_same_reals(m.model_params, n.model_params, "model_params");
  RC_EXPECT_REAL(m.flxz, n.flxz, "flxz");
  EXPECT_EQ(m.influence_type, n.influence_type);
  EXPECT_EQ(m.influence_file, n.influence_file);
  EXPECT_EQ(m.conformal.if_meth, n.conformal.if_meth);
  EXPECT_EQ(m.conformal.variant, n.conformal.variant);
  expect_same_reals(m.conformal.y, n.conformal.y, "conformal.y");
  expect_same_reals(m.conformal.alpha, n.conformal.alpha, "conformal.alpha");

  EXPECT_EQ(a.potential.ipotcn, b.potential.ipotcn);
  EXPECT_EQ(a.potential.mx, b.potential.mx);
  EXPECT_EQ(a.potential.my, b.potential.my);
  expect_same_reals(a.potential.values, b.potential.values, "potential.values");

  const model::UndeformedDistance& u = a.geometry;
  const model::UndeformedDistance& w = b.geometry;
  EXPECT_EQ(u.ibase, w.ibase);
  EXPECT_EQ(u.iplan, w.iplan);
  expect_same_reals(u.coeffs, w.coeffs, "geometry.coeffs");
  RC_EXPECT_REAL(u.xm, w.xm, "xm");
  RC_EXPECT_REAL(u.rm, w.rm, "rm");
  RC_EXPECT_REAL(u.y1, w.y1, "y1");
  RC_EXPECT_REAL(u.dy1, w.dy1, "dy1");
  expect_same_reals(u.values, w.values, "geometry.values");
  expect_same_reals(u.planform, w.planform, "planform");
  EXPECT_EQ(u.npatch, w.npatch);
  expect_same_reals(u.patch_factors, w.patch_factors, "patch_factors");

  EXPECT_EQ(a.damping.enabled, b.damping.enabled);
  RC_EXPECT_REAL(a.damping.cdampn, b.damping.cdampn, "cdampn");
  RC_EXPECT_REAL(a.damping.cdampt, b.damping.cdampt, "cdampt");
  RC_EXPECT_REAL(a.damping.dfnmax, b.damping.dfnmax, "dfnmax");
  RC_EXPECT_REAL(a.damping.dftmax, b.damping.dftmax, "dftmax");

  const format::HeatParameters& h = a.heat;
  const format::HeatParameters& j = b.heat;
  expect_same_reals(std::array<double, 9>{h.bktemp1, h.heatcp1, h.lambda1, h.dens1, h.bktemp2,
                                          h.heatcp2, h.lambda2, h.dens2, h.betapl},
                    std::array<double, 9>{j.bktemp1, j.heatcp1, j.lambda1, j.dens1, j.bktemp2,
                                          j.heatcp2, j.lambda2, j.dens2, j.betapl},
                    "heat");

  EXPECT_EQ(a.subsurface.matfil, b.subsurface.matfil);
  EXPECT_EQ(a.subsurface.output, b.subsurface.output);
  ASSERT_EQ(a.subsurface.blocks.size(), b.subsurface.blocks.size());
  for (std::size_t i = 0; i < a.subsurface.blocks.size(); ++i) {
    const model::SubsurfaceBlock& c = a.subsurface.blocks[i];
    const model::SubsurfaceBlock& e = b.subsurface.blocks[i];
    EXPECT_EQ(c.isubs, e.isubs);
    EXPECT_EQ(std::vector<int>({c.ixl, c.ixinc, c.ixh, c.iyl, c.iyinc, c.iyh}),
              std::vector<int>({e.ixl, e.ixinc, e.ixh, e.iyl, e.iyinc, e.iyh}));
    EXPECT_EQ(c.ix, e.ix);
    EXPECT_EQ(c.iy, e.iy);
    RC_EXPECT_REAL(c.zl, e.zl, "zl");
    RC_EXPECT_REAL(c.dz, e.dz, "dz");
    expect_same_reals(c.x, e.x, "subsurface.x");
    expect_same_reals(c.y, e.y, "subsurface.y");
    expect_same_reals(c.z, e.z, "subsurface.z");
  }

  EXPECT_EQ(a.source.case_error.empty(), b.source.case_error.empty());
}

/// `problems` without their origin (writers print it as a comment), e.g. to compare texts.
inline std::vector<format::CaseRecord> without_source(std::vector<format::CaseRecord> problems) {
  for (format::CaseRecord& p : problems) p.source = format::SourceInfo{};
  return problems;
}

/// Compares two lists of Problems case by case after canonical().
inline void expect_same_problems(const std::vector<format::CaseRecord>& a,
                                 const std::vector<format::CaseRecord>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    SCOPED_TRACE("case index " + std::to_string(i));
    expect_same_problem(canonical(a[i]), canonical(b[i]));
  }
}

}  // namespace rollcontact::test
