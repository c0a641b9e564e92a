// The CONTACT example inputs (spec/inp-format.md: acceptance set) parse, with spot checks of
// parsed values against the files.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "format/inp/inp_reader.hpp"
#include "rollcontact/errors.hpp"
#include "support/examples.hpp"

namespace rollcontact::format {
namespace {

using test_support::kExamples;

std::vector<format::CaseRecord> read_example(const std::string& name) {
  return read_inp_file(kExamples / name);
}

constexpr double kDeg = std::numbers::pi / 180.0;

struct ExampleCount {
  const char* file;
  std::size_t cases;
};

// The 13 module-3 examples and their number of cases (as in the matching .ref_out files).
constexpr ExampleCount kModule3Examples[] = {
    {"bentall.inp", 6},      {"carter2d.inp", 1},     {"catt_to_cart.inp", 171},
    {"cattaneo.inp", 2},     {"conformal.inp", 5},    {"ertz_temperature.inp", 4},
    {"fastsim.inp", 8},      {"plastic_3bl.inp", 57}, {"spence35.inp", 35},
    {"subsurf.inp", 2},      {"tractcurv.inp", 120},  {"veldep_fric.inp", 53},
    {"visc_cylindr.inp", 6},
};

TEST(InpExamples, AllModule3ExamplesParse) {
  REQUIRE_EXAMPLES();
  for (const auto& ex : kModule3Examples) {
    SCOPED_TRACE(ex.file);
    std::vector<format::CaseRecord> problems;
    ASSERT_NO_THROW(problems = read_example(ex.file));
    EXPECT_EQ(problems.size(), ex.cases);
    for (std::size_t k = 0; k < problems.size(); ++k) {
      EXPECT_EQ(problems[k].case_number, static_cast<int>(k) + 1);
      EXPECT_EQ(problems[k].source.file, (kExamples / ex.file).string());
      EXPECT_GT(problems[k].source.first_line, 0);
    }
  }
}

TEST(InpExamples, Module1ExamplesParseButTheModule3ReaderRefusesThem) {
  REQUIRE_EXAMPLES();
  // read_inp_file() returns module-3 Problems only: it reads the whole file (so malformed
  // module-1 input is reported as such) and then refuses the wheel/rail cases at their module
  // line. read_input_cases() returns them (test_inp_module1_examples.cpp).
  for (const char* file : {"mbench_a22_kpec.inp", "mbench_a22_left.inp", "mbench_a22_right.inp",
                           "mbench_a22_varfric.inp", "wheelflat.inp"}) {
    SCOPED_TRACE(file);
    try {
      read_example(file);
      FAIL() << "expected InputError";
    } catch (const InputError& e) {
      EXPECT_NE(e.message().find("module 1 (wheel/rail) input is not supported yet"),
                std::string::npos);
      EXPECT_GT(e.line(), 0);
    }
    std::vector<InputCase> cases;
    ASSERT_NO_THROW(cases = read_input_cases(kExamples / file));
    EXPECT_FALSE(cases.empty());
  }
}

TEST(InpExamples, CattaneoWorkedExample) {
  REQUIRE_EXAMPLES();
  const auto problems = read_example("cattaneo.inp");
  ASSERT_EQ(problems.size(), 2u);

  const format::CaseRecord& c1 = problems[0];
  EXPECT_EQ(c1.digits.t, 0);
  EXPECT_EQ(c1.digits.n, 1);
  EXPECT_EQ(c1.potential.ipotcn, -3);
  EXPECT_EQ(c1.potential.mx, 19);
  EXPECT_DOUBLE_EQ(c1.potential.values[2], 1.26667);
  EXPECT_EQ(c1.solver.maxgs, 100);
  EXPECT_DOUBLE_EQ(c1.solver.eps, 1e-4);

  const format::CaseRecord& c = problems[1];
  EXPECT_EQ(c.source.module_line, 34);
  EXPECT_EQ(c.source.first_line, 35);
  EXPECT_EQ(c.source.digit_lines[1], 36);
  EXPECT_EQ(c.source.digit_lines[2], 37);
  const ControlDigits& d = c.digits;
  EXPECT_EQ(d.p, 2);
  EXPECT_EQ(d.b, 0);
  EXPECT_EQ(d.t, 1);
  EXPECT_EQ(d.n, 1);
  EXPECT_EQ(d.f, 2);
  EXPECT_EQ(d.s, 0);
  EXPECT_EQ(d.l, 0);
  EXPECT_EQ(d.d, 2);
  EXPECT_EQ(d.c, 2);
  EXPECT_EQ(d.m, 0);
  EXPECT_EQ(d.z, 2);
  EXPECT_EQ(d.e, 0);
  EXPECT_EQ(d.m2, 1);
  EXPECT_EQ(d.h, 0);
  EXPECT_EQ(d.g, 1);
  EXPECT_EQ(d.i, 0);
  EXPECT_EQ(d.a, 1);
  EXPECT_EQ(d.o, 5);
  EXPECT_EQ(d.w, 4);
  EXPECT_EQ(d.r, 1);
  // G=1 keeps the iteration parameters of case 1.
  EXPECT_EQ(c.solver.maxgs, 100);
  EXPECT_DOUBLE_EQ(c.solver.eps, 1e-4);
  EXPECT_DOUBLE_EQ(c.kinematics.fn, 9.1954);
  EXPECT_DOUBLE_EQ(c.kinematics.fx_rel, -0.875);
  EXPECT_DOUBLE_EQ(c.kinematics.fy_rel, 0.0);
  EXPECT_DOUBLE_EQ(c.friction.fstat, 0.4);
  EXPECT_DOUBLE_EQ(c.friction.fkin, 0.4);
  EXPECT_DOUBLE_EQ(c.materials.poiss1, 0.42);
  EXPECT_DOUBLE_EQ(c.materials.gg2, 200.0);
  EXPECT_EQ(c.potential.ipotcn, 1);
  EXPECT_EQ(c.potential.mx, 19);
  EXPECT_EQ(c.potential.my, 19);
  EXPECT_DOUBLE_EQ(c.potential.values[0], -1.26667);
  EXPECT_DOUBLE_EQ(c.potential.values[2], 0.13333);
  EXPECT_EQ(c.geometry.ibase, 1);
  EXPECT_EQ(c.geometry.iplan, 1);
  ASSERT_EQ(c.geometry.coeffs.size(), 6u);
  EXPECT_DOUBLE_EQ(c.geometry.coeffs[0], 0.01);
  EXPECT_DOUBLE_EQ(c.geometry.coeffs[2], 0.01);
  EXPECT_TRUE(c.source.warnings.empty());
}

TEST(InpExamples, Carter2dDebugWord) {
  REQUIRE_EXAMPLES();
  const auto problems = read_example("carter2d.inp");
  ASSERT_EQ(problems.size(), 1u);
  const format::CaseRecord& c = problems[0];
  EXPECT_EQ(c.digits.x, 1);
  EXPECT_EQ(c.digits.h, 0);
  EXPECT_EQ(c.digits.o, 5);
  EXPECT_EQ(c.digits.debug.p, 1);
  EXPECT_EQ(c.digits.debug.n, 5);
  EXPECT_EQ(c.digits.debug.readln, 0);
  EXPECT_EQ(c.source.digit_lines[3], 15);
  EXPECT_EQ(c.solver.maxgs, 999);
  EXPECT_DOUBLE_EQ(c.kinematics.fn, 35780.0);
  EXPECT_DOUBLE_EQ(c.kinematics.cksi, -0.00024);
  EXPECT_DOUBLE_EQ(c.kinematics.dq, 0.0401);
  EXPECT_DOUBLE_EQ(c.kinematics.veloc, 30000.0);
  EXPECT_DOUBLE_EQ(c.kinematics.facphi, 1.0 / 6.0);
  EXPECT_EQ(c.potential.ipotcn, 3);
  EXPECT_EQ(c.potential.mx, 55);
  EXPECT_EQ(c.potential.my, 1);
  EXPECT_DOUBLE_EQ(c.geometry.coeffs[0], 0.001);
}

TEST(InpExamples, TractcurvKeepsAcrossSeries) {
  REQUIRE_EXAMPLES();
  const auto problems = read_example("tractcurv.inp");
  ASSERT_EQ(problems.size(), 120u);
  // Series 1: Coulomb, half-space. Case 2 keeps everything but the creepage.
  EXPECT_EQ(problems[1].friction.law, 0);
  EXPECT_EQ(problems[1].digits.l, 1);
  EXPECT_EQ(problems[1].potential.ipotcn, -2);
  EXPECT_EQ(problems[1].potential.mx, 48);
  EXPECT_EQ(problems[1].solver.maxgs, 80);
  EXPECT_DOUBLE_EQ(problems[1].kinematics.cksi, 0.0004);
  // Series 2 (case 31): exponential falling friction, interface layer M=4.
  const format::CaseRecord& s2 = problems[30];
  EXPECT_EQ(s2.digits.l, 4);
  EXPECT_EQ(s2.friction.law, 4);
  EXPECT_DOUBLE_EQ(s2.friction.fkin, 0.14);
  EXPECT_DOUBLE_EQ(s2.friction.params[0], 0.19);
  EXPECT_DOUBLE_EQ(s2.friction.params[1], 1250.0);
  EXPECT_DOUBLE_EQ(s2.friction.fstat, 0.14 + 0.19);
  EXPECT_DOUBLE_EQ(s2.friction.memdst, 0.003);
  EXPECT_DOUBLE_EQ(s2.materials.model_params[0], 8200.0);
  EXPECT_DOUBLE_EQ(s2.materials.model_params[1], 1.25);
  // Case 32 keeps the law (L=1).
  EXPECT_EQ(problems[31].friction.law, 4);
  EXPECT_DOUBLE_EQ(problems[31].friction.fkin, 0.14);
  EXPECT_DOUBLE_EQ(problems[31].materials.model_params[0], 8200.0);
  // Series 4 (case 91): modified Fastsim, M=3, static 0.36.
  const format::CaseRecord& s4 = problems[90];
  EXPECT_EQ(s4.digits.m, 3);
  EXPECT_EQ(s4.digits.b, 3);
  EXPECT_NEAR(s4.friction.fstat, 0.36, 1e-12);
  EXPECT_DOUBLE_EQ(s4.materials.model_params[0], 0.54);
  EXPECT_DOUBLE_EQ(s4.materials.model_params[2], 0.62);
  EXPECT_DOUBLE_EQ(problems.back().kinematics.cksi, problems[29].kinematics.cksi);
}

TEST(InpExamples, CattToCartSequences) {
  REQUIRE_EXAMPLES();
  const auto problems = read_example("catt_to_cart.inp");
  ASSERT_EQ(problems.size(), 171u);
  EXPECT_EQ(problems[0].digits.t, 1);
  EXPECT_EQ(problems[1].digits.t, 2);
  EXPECT_EQ(problems[1].digits.p, 0);
  EXPECT_DOUBLE_EQ(problems[1].kinematics.dq, 0.25);
  EXPECT_DOUBLE_EQ(problems[1].kinematics.veloc, 1000.0);
  EXPECT_EQ(problems[56].potential.mx, 34);
  EXPECT_EQ(problems[57].potential.mx, 90);  // case 58 starts the second sequence
  EXPECT_EQ(problems[57].digits.p, 2);
  // Third sequence: T=1 with a grid shifted by one element per case (D=2, P=0).
  const format::CaseRecord& c116 = problems[115];
  EXPECT_EQ(c116.digits.p, 0);
  EXPECT_EQ(c116.digits.d, 2);
  EXPECT_EQ(c116.digits.n, 0);
  EXPECT_DOUBLE_EQ(c116.kinematics.pen, 0.07258);
  EXPECT_DOUBLE_EQ(c116.potential.values[0], -3.875);
  EXPECT_DOUBLE_EQ(problems[116].potential.values[0], -3.625);
  EXPECT_EQ(problems.back().case_number, 171);
}

TEST(InpExamples, ConformalIbase9AndExtraSlip) {
  REQUIRE_EXAMPLES();
  const auto problems = read_example("conformal.inp");
  ASSERT_EQ(problems.size(), 5u);
  const format::CaseRecord& c2 = problems[1];
  EXPECT_EQ(c2.geometry.ibase, 9);
  ASSERT_EQ(c2.geometry.values.size(), 1989u);
  EXPECT_DOUBLE_EQ(c2.geometry.values.front(), 0.06625925);
  EXPECT_DOUBLE_EQ(c2.geometry.values.back(), 0.06625925);
  // Case 3: C=9 with a coefficient file that is not provided -> per-case error, no throw.
  const format::CaseRecord& c3 = problems[2];
  EXPECT_EQ(c3.digits.c, 9);
  EXPECT_EQ(c3.materials.influence_type, 9);
  EXPECT_NE(c3.materials.influence_file.find("inflcf_r10_mx51.txt"), std::string::npos);
  EXPECT_NE(c3.source.case_error.find("inflcf_r10_mx51.txt' not found"), std::string::npos);
  EXPECT_EQ(c3.geometry.values.size(), 1989u);  // Z=0 keeps the geometry
  EXPECT_EQ(c3.solver.maxout, 1);               // K = 0 -> MAXOUT overridden
  EXPECT_FALSE(c3.source.warnings.empty());
  // Case 4: E=9, 2*51*39 values.
  const format::CaseRecord& c4 = problems[3];
  EXPECT_TRUE(c4.source.case_error.empty());
  EXPECT_EQ(c4.materials.influence_type, 2);
  EXPECT_EQ(c4.kinematics.extra_slip_mode, 9);
  ASSERT_EQ(c4.kinematics.extra_slip.size(), 3978u);
  EXPECT_DOUBLE_EQ(c4.kinematics.extra_slip[0], -0.01880288);
  EXPECT_DOUBLE_EQ(c4.kinematics.extra_slip[1], 0.02126760);
  EXPECT_DOUBLE_EQ(c4.kinematics.extra_slip[3977], -0.01470643);
  // Case 5: E=1 keeps the extra slip.
  EXPECT_EQ(problems[4].kinematics.extra_slip_mode, 9);
  EXPECT_EQ(problems[4].kinematics.extra_slip.size(), 3978u);
  EXPECT_FALSE(problems[4].source.case_error.empty());
}

TEST(InpExamples, ConformalStrictFilesThrows) {
  REQUIRE_EXAMPLES();
  InpReadOptions strict;
  strict.missing_files_are_errors = true;
  try {
    read_inp_file(kExamples / "conformal.inp", strict);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 2053);
    EXPECT_NE(e.message().find("'inflcf_r10_mx51.txt' not found"), std::string::npos);
  }
}

TEST(InpExamples, VeldepFrictionSolverLines) {
  REQUIRE_EXAMPLES();
  const auto problems = read_example("veldep_fric.inp");
  ASSERT_EQ(problems.size(), 53u);
  const format::CaseRecord& c1 = problems[0];
  EXPECT_EQ(c1.digits.g, 2);
  EXPECT_EQ(c1.solver.method, 2);
  EXPECT_EQ(c1.solver.maxgs, 5000);
  EXPECT_DOUBLE_EQ(c1.solver.eps, 1e-7);
  EXPECT_DOUBLE_EQ(c1.solver.omega_h, 0.5);
  EXPECT_DOUBLE_EQ(c1.solver.omega_s, 1.0);
  EXPECT_EQ(c1.solver.inislp, 1);
  EXPECT_DOUBLE_EQ(c1.solver.omgslp, 1.1);
  EXPECT_DOUBLE_EQ(c1.kinematics.cksi, -0.0009999);
  EXPECT_EQ(c1.friction.law, 4);
  EXPECT_DOUBLE_EQ(c1.friction.fkin, 0.18);
  EXPECT_DOUBLE_EQ(c1.friction.mem_s0, 1.0);
  EXPECT_EQ(c1.geometry.ibase, 2);
  EXPECT_DOUBLE_EQ(c1.geometry.rm, 460.0);
  EXPECT_DOUBLE_EQ(c1.geometry.dy1, 20.0);
  EXPECT_EQ(c1.geometry.coeffs.size(), 2u);
  const format::CaseRecord& c2 = problems[1];
  EXPECT_EQ(c2.digits.g, 4);
  EXPECT_EQ(c2.solver.method, 4);
  EXPECT_EQ(c2.solver.inislp, 1);
  EXPECT_DOUBLE_EQ(c2.solver.omgslp, 1.1);
  EXPECT_DOUBLE_EQ(c2.solver.omega_h, 0.0);  // G=4 resets the G=2 parameters
  EXPECT_EQ(c2.digits.p, 0);
  EXPECT_EQ(problems[3].solver.inislp, -1);
  EXPECT_EQ(problems.back().friction.law, 4);
}

TEST(InpExamples, SubsurfaceBlocks) {
  REQUIRE_EXAMPLES();
  const auto subsurf = read_example("subsurf.inp");
  ASSERT_EQ(subsurf.size(), 2u);
  const Subsurface& s = subsurf[0].subsurface;
  EXPECT_EQ(s.matfil, 2);
  EXPECT_EQ(s.output, 1);
  ASSERT_EQ(s.blocks.size(), 2u);
  EXPECT_EQ(s.blocks[0].isubs, 9);
  ASSERT_EQ(s.blocks[0].z.size(), 15u);
  EXPECT_DOUBLE_EQ(s.blocks[0].x[0], 1e-5);
  EXPECT_DOUBLE_EQ(s.blocks[0].z[11], 1.25);
  EXPECT_EQ(s.blocks[1].x.size(), 21u);
  EXPECT_DOUBLE_EQ(s.blocks[1].y[0], -5.0);
  EXPECT_DOUBLE_EQ(s.blocks[1].y[20], 5.0);
  // Case 2: S=1 reuses the points; T=3 with C=2 reads the rolling line.
  EXPECT_EQ(subsurf[1].digits.s, 1);
  EXPECT_EQ(subsurf[1].subsurface.blocks.size(), 2u);
  EXPECT_DOUBLE_EQ(subsurf[1].kinematics.fx_rel, 0.999);

  const auto spence = read_example("spence35.inp");
  ASSERT_EQ(spence.size(), 35u);
  const SubsurfaceBlock& b = spence[0].subsurface.blocks.at(0);
  EXPECT_EQ(b.isubs, 2);
  EXPECT_EQ(b.ixl, 1);
  EXPECT_EQ(b.ixh, 45);
  EXPECT_EQ(b.iyl, 23);
  EXPECT_EQ(b.iyh, 23);
  ASSERT_EQ(b.z.size(), 1u);
  EXPECT_DOUBLE_EQ(b.zl, 1e-6);
  EXPECT_EQ(spence[0].subsurface.matfil, 1);
  EXPECT_EQ(spence[0].subsurface.output, 0);
  EXPECT_DOUBLE_EQ(spence[0].materials.poiss1, 0.0);
  EXPECT_DOUBLE_EQ(spence[0].materials.gg1, 0.5);
  EXPECT_EQ(spence[0].solver.maxout, 10);  // K != 0: no override
  EXPECT_EQ(spence[5].digits.s, 2);        // S=2: new MATFIL/OUTPUT, stored points
  EXPECT_EQ(spence[5].subsurface.output, 1);
  EXPECT_EQ(spence[5].subsurface.blocks.size(), 1u);
  EXPECT_EQ(spence[6].subsurface.output, 0);
  EXPECT_EQ(spence[34].subsurface.output, 4);
  EXPECT_DOUBLE_EQ(spence[34].kinematics.fn, 0.470508);
  EXPECT_EQ(spence[1].digits.i, 1);
}

TEST(InpExamples, FastsimMaterialLines) {
  REQUIRE_EXAMPLES();
  const auto problems = read_example("fastsim.inp");
  ASSERT_EQ(problems.size(), 8u);
  EXPECT_EQ(problems[0].digits.m, 0);
  EXPECT_EQ(problems[1].digits.m, 3);
  EXPECT_EQ(problems[1].digits.b, 3);
  EXPECT_DOUBLE_EQ(problems[1].materials.model_params[0], 1.0);
  EXPECT_EQ(problems[3].digits.m, 5);
  EXPECT_EQ(problems[3].digits.b, 2);
  EXPECT_EQ(problems[4].potential.mx, 220);
  EXPECT_NEAR(problems[7].kinematics.chi, std::numbers::pi, 1e-15);  // 180.0d
  EXPECT_DOUBLE_EQ(problems[7].kinematics.cphi, -0.000625);
  // Case 2 keeps the Coulomb friction of case 1 (L=1, V=0).
  EXPECT_DOUBLE_EQ(problems[1].friction.fkin, 0.3);
}

TEST(InpExamples, BentallMaterialsAndForces) {
  REQUIRE_EXAMPLES();
  const auto problems = read_example("bentall.inp");
  ASSERT_EQ(problems.size(), 6u);
  const format::CaseRecord& c1 = problems[0];
  EXPECT_EQ(c1.result_element, 0);
  EXPECT_EQ(c1.contact_problem, 1);
  EXPECT_NEAR(c1.kinematics.chi, 180.0 * kDeg, 1e-15);
  EXPECT_DOUBLE_EQ(c1.materials.poiss1, 0.31);
  EXPECT_DOUBLE_EQ(c1.materials.gg1, 23000.0);
  EXPECT_DOUBLE_EQ(c1.materials.gg2, 82000.0);
  EXPECT_EQ(c1.potential.mx, 216);
  EXPECT_DOUBLE_EQ(c1.friction.fkin, 0.0001);
  const format::CaseRecord& c2 = problems[1];
  EXPECT_EQ(c2.digits.f, 1);
  EXPECT_EQ(c2.digits.i, 1);
  EXPECT_EQ(c2.digits.l, 0);
  EXPECT_EQ(c2.digits.d, 0);
  EXPECT_EQ(c2.potential.mx, 216);              // D=0 keeps the grid
  EXPECT_DOUBLE_EQ(c2.materials.gg1, 23000.0);  // C=0 keeps the materials
  EXPECT_NEAR(c2.kinematics.chi, std::numbers::pi, 1e-15);
  EXPECT_EQ(problems[2].solver.maxout, 10);  // different materials: K != 0
  EXPECT_DOUBLE_EQ(problems[2].friction.fkin, 10.0);
  EXPECT_DOUBLE_EQ(problems[4].kinematics.fx_rel, 0.75);
  EXPECT_DOUBLE_EQ(problems[5].kinematics.fx_rel, -0.75);
}

TEST(InpExamples, ViscoelasticPlasticAndHeat) {
  REQUIRE_EXAMPLES();
  const auto visc = read_example("visc_cylindr.inp");
  ASSERT_EQ(visc.size(), 6u);
  EXPECT_EQ(visc[0].digits.m, 1);
  EXPECT_DOUBLE_EQ(visc[1].materials.model_params[2], 0.009);
  EXPECT_DOUBLE_EQ(visc[3].materials.model_params[3], 2.0);
  EXPECT_DOUBLE_EQ(visc[4].materials.gg1, 571.5);

  const auto plastic = read_example("plastic_3bl.inp");
  ASSERT_EQ(plastic.size(), 57u);
  EXPECT_EQ(plastic[1].digits.m, 4);
  EXPECT_DOUBLE_EQ(plastic[1].materials.model_params[0], 176.63);
  EXPECT_DOUBLE_EQ(plastic[1].materials.model_params[2], 560.0);
  EXPECT_DOUBLE_EQ(plastic.back().materials.model_params[3], 20.4);

  const auto ertz = read_example("ertz_temperature.inp");
  ASSERT_EQ(ertz.size(), 4u);
  EXPECT_EQ(ertz[0].digits.h, 3);
  EXPECT_DOUBLE_EQ(ertz[0].heat.heatcp1, 450.0);
  EXPECT_DOUBLE_EQ(ertz[0].heat.lambda2, 50e-3);
  EXPECT_DOUBLE_EQ(ertz[0].heat.dens2, 7.85e-6);
  EXPECT_DOUBLE_EQ(ertz[1].heat.bktemp2, 150.0);
  EXPECT_EQ(ertz[3].digits.h, 1);
  EXPECT_DOUBLE_EQ(ertz[3].heat.bktemp2, 150.0);  // H=1 keeps the parameters
  EXPECT_DOUBLE_EQ(ertz[3].kinematics.cphi, 0.0002);
  EXPECT_EQ(ertz[0].potential.mx, 216);
  EXPECT_EQ(ertz[0].potential.my, 45);
}

}  // namespace
}  // namespace rollcontact::format
