#include "bindings/python/py_convert.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <memory>

namespace py = pybind11;

namespace rollcontact::python {
namespace {

/// A (my, mx) array over `field`, owned by `owner` (no copy).
py::array_t<double> field_view(const Grid& g, std::vector<double>& field, py::handle owner) {
  if (field.size() != g.size()) return py::array_t<double>(0);
  const auto mx = static_cast<py::ssize_t>(g.mx), my = static_cast<py::ssize_t>(g.my);
  return py::array_t<double>(
      {my, mx},
      {mx * static_cast<py::ssize_t>(sizeof(double)), static_cast<py::ssize_t>(sizeof(double))},
      field.data(), owner);
}

py::array_t<double> coordinates(int n, double first_centre, double step) {
  py::array_t<double> a(n);
  auto v = a.mutable_unchecked<1>();
  for (int i = 0; i < n; ++i) v(i) = first_centre + i * step;
  return a;
}

/// The subsurface blocks: coordinate lists [mm] and fields of shape (nz, ny, nx) [mm, N/mm²].
py::list subsurface_to_list(std::vector<SubsurfaceResult>& blocks, py::handle owner) {
  py::list out;
  for (SubsurfaceResult& b : blocks) {
    py::dict d;
    d["x"] = b.x;
    d["y"] = b.y;
    d["z"] = b.z;
    const auto nx = static_cast<py::ssize_t>(b.x.size()), ny = static_cast<py::ssize_t>(b.y.size()),
               nz = static_cast<py::ssize_t>(b.z.size());
    const auto e = static_cast<py::ssize_t>(sizeof(double));
    for (auto [name, field] : {std::pair{"ux", &b.ux},
                               {"uy", &b.uy},
                               {"uz", &b.uz},
                               {"sighyd", &b.sighyd},
                               {"sigvm", &b.sigvm},
                               {"sigtr", &b.sigtr},
                               {"sig1", &b.sig1},
                               {"sig2", &b.sig2},
                               {"sig3", &b.sig3},
                               {"sxx", &b.sxx},
                               {"sxy", &b.sxy},
                               {"sxz", &b.sxz},
                               {"syy", &b.syy},
                               {"syz", &b.syz},
                               {"szz", &b.szz}})
      if (field->size() == b.size())
        d[name] = py::array_t<double>({nz, ny, nx}, {nx * ny * e, nx * e, e}, field->data(), owner);
    out.append(d);
  }
  return out;
}

py::dict marker(const ProfileMarker& m) {
  py::dict d;
  d["y"] = m.position.y;
  d["z"] = m.position.z;
  d["x"] = m.position.x;
  d["roll"] = m.roll_rad;
  d["yaw"] = m.yaw_rad;
  return d;
}

}  // namespace

py::dict solution_to_dict(Solution solution) {
  auto* held = new Solution(std::move(solution));
  const py::capsule owner(held, [](void* p) { delete static_cast<Solution*>(p); });
  Solution& s = *held;
  const Grid& g = s.grid;
  py::dict d;
  d["converged"] = s.solver.converged;
  d["message"] = s.solver.message;
  d["warnings"] = s.warnings;
  py::dict grid;
  grid["mx"] = g.mx;
  grid["my"] = g.my;
  grid["dx"] = g.dx;
  grid["dy"] = g.dy;
  grid["x"] = coordinates(g.mx, g.x_centre(0), g.dx);  // element centres [mm]
  grid["y"] = coordinates(g.my, g.y_centre(0), g.dy);
  d["grid"] = grid;
  const Totals& t = s.totals;
  d["fn"] = t.fn;
  d["fx"] = t.fx;
  d["fy"] = t.fy;
  d["mz"] = t.mz;
  d["pen"] = t.pen;
  d["pmax"] = t.pmax;
  d["creep_x"] = t.creep_x;
  d["creep_y"] = t.creep_y;
  d["spin"] = t.spin;
  d["shift_x"] = t.shift_x;
  d["shift_y"] = t.shift_y;
  d["elastic_energy"] = t.elastic_energy;
  d["frictional_power"] = t.frictional_power;
  d["contact_area"] = t.contact_area;
  const Statistics& st = s.statistics;
  d["statistics"] =
      py::dict(py::arg("npot") = st.npot, py::arg("ncon") = st.ncon, py::arg("nadh") = st.nadh,
               py::arg("nslip") = st.nslip, py::arg("nplast") = st.nplast);
  d["material"] = py::dict(py::arg("g") = s.material.g, py::arg("nu") = s.material.nu,
                           py::arg("k") = s.material.k);
  for (auto [name, field] : {std::pair{"pn", &s.pn},
                             {"px", &s.px},
                             {"py", &s.py},
                             {"sx", &s.sx},
                             {"sy", &s.sy},
                             {"ux", &s.ux},
                             {"uy", &s.uy},
                             {"un", &s.un},
                             {"h", &s.h}})
    d[name] = field_view(g, *field, owner);
  // Fields that only some physics has (present as arrays when the solver made them): the rigid
  // slip the tangential problem posed (W/δq; T=1: the shift [mm]), the local
  // friction coefficient (velocity- and temperature-dependent laws), the interfacial layer's
  // yield limit and plastic displacement (M=4 with plasticity), surface temperatures (H >= 1).
  for (auto [name, field] : {std::pair{"wx", &s.wx},
                             {"wy", &s.wy},
                             {"mu", &s.mu},
                             {"yield_limit", &s.yield_limit},
                             {"plastic_x", &s.plastic_x},
                             {"plastic_y", &s.plastic_y},
                             {"temp1", &s.temp1},
                             {"temp2", &s.temp2}})
    if (field->size() == g.size()) d[name] = field_view(g, *field, owner);
  if (!s.temp1.empty()) {
    d["max_temp1"] = t.max_temp1;
    d["max_temp2"] = t.max_temp2;
  }
  py::array_t<std::int8_t> state({static_cast<py::ssize_t>(g.my), static_cast<py::ssize_t>(g.mx)});
  auto sv = state.mutable_unchecked<2>();
  for (int iy = 0; iy < g.my; ++iy)
    for (int ix = 0; ix < g.mx; ++ix)
      sv(iy, ix) = s.state.empty() ? 0 : static_cast<std::int8_t>(s.state[g.index(ix, iy)]);
  d["state"] = state;  // 0 exterior, 1 adhesion, 2 slip, 3 plastic
  d["subsurface"] = subsurface_to_list(s.subsurface, owner);
  return d;
}

py::dict wheelrail_to_dict(WheelRailSolution solution) {
  py::dict d;
  d["converged"] = solution.converged;
  d["message"] = solution.message;
  d["warnings"] = solution.warnings;
  d["force_tr"] =
      std::vector<double>{solution.force_tr.x, solution.force_tr.y, solution.force_tr.z};
  d["force_ws"] =
      std::vector<double>{solution.force_ws.x, solution.force_ws.y, solution.force_ws.z};
  d["z_ws"] = solution.z_ws_mm;
  d["vpitch"] = solution.vpitch_rad_s;
  d["moment_tr"] =
      std::vector<double>{solution.moment_tr.x, solution.moment_tr.y, solution.moment_tr.z};
  d["moment_ws"] =
      std::vector<double>{solution.moment_ws.x, solution.moment_ws.y, solution.moment_ws.z};
  d["rail_marker"] = marker(solution.rail_marker_tr);
  d["wheel_marker"] = marker(solution.wheel_marker_tr);
  py::list patches;
  for (WheelRailPatch& w : solution.patches) {
    py::dict p = solution_to_dict(std::move(w.solution));
    p["reference_tr"] = std::vector<double>{w.reference_tr.x, w.reference_tr.y, w.reference_tr.z};
    p["contact_angle"] = w.contact_angle_rad;
    p["reference_rail"] = std::vector<double>{w.y_rail_mm, w.z_rail_mm};
    p["reference_wheel"] =
        std::vector<double>{w.reference_wheel.x, w.reference_wheel.y, w.reference_wheel.z};
    p["xi"] = w.xi;
    p["eta"] = w.eta;
    p["phi"] = w.phi_per_mm;
    p["force_tr"] = std::vector<double>{w.force_tr.x, w.force_tr.y, w.force_tr.z};
    p["force_ws"] = std::vector<double>{w.force_ws.x, w.force_ws.y, w.force_ws.z};
    if (w.conformal.active) {  // D=4: the curved reference and both force integrals
      const ConformalPatch& c = w.conformal;
      py::dict cd;
      cd["bar_force"] = std::vector<double>{c.bar_fx, c.bar_fs, c.bar_fn};
      cd["tilde_force"] = std::vector<double>{c.tilde_fx, c.tilde_fs, c.tilde_fn};
      cd["moments_planar"] =
          std::vector<double>{c.moment_planar.x, c.moment_planar.y, c.moment_planar.z};
      cd["row_y"] = c.row_y_mm;
      cd["row_z"] = c.row_z_mm;
      cd["row_alpha"] = c.row_alpha_rad;
      cd["row_friction"] = c.row_friction;
      p["conformal"] = cd;
    }
    patches.append(p);
  }
  d["patches"] = patches;
  return d;
}

}  // namespace rollcontact::python
