// The compiled part of the Python package `rollcontact` (module rollcontact._rollcontact):
// running CONTACT input files and solving cases given as TOML text, results as dicts with
// NumPy arrays (py_convert.hpp). The pure-Python part (python/rollcontact/) builds the TOML text
// from dicts, sweeps parameters and plots. C++ exceptions become Python exceptions:
// InputError → ValueError (bad input, with file and line), other rollcontact errors →
// RuntimeError.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <string>

#include "batch/run_input.hpp"
#include "bindings/python/py_convert.hpp"
#include "format/inp/inp_reader.hpp"
#include "format/inp/inp_writer.hpp"
#include "format/inp/to_wheelrail.hpp"
#include "format/toml/toml_case_reader.hpp"
#include "rollcontact/creep_lookup.hpp"
#include "rollcontact/errors.hpp"
#include "rollcontact/solve.hpp"
#include "rollcontact/version.hpp"

namespace py = pybind11;
using namespace rollcontact;

namespace {

/// One case of a run: its number, module, status and results.
py::dict outcome_to_dict(batch::CaseOutcome& o) {
  py::dict d;
  if (o.wheel_rail && o.solved) {
    d = python::wheelrail_to_dict(std::move(o.wheelrail));
  } else if (o.solved) {
    d = python::solution_to_dict(std::move(o.solution));
  }
  d["case"] = o.problem.case_number;
  d["result_element"] = o.problem.result_element;
  d["module"] = o.wheel_rail ? 1 : 3;
  d["solved"] = o.solved;
  d["skipped"] = o.skipped;
  d["error"] = o.error;
  return d;
}

py::dict profile_points(const Profile& p) {
  py::dict d;
  d["y"] = p.y;
  d["z"] = p.z;
  return d;
}

/// Module-1 cases get their side and the rail and wheel profiles as read (profile coordinates,
/// mm, z down), for plots in track coordinates with the markers of the solution.
void attach_profiles(const batch::RunResult& r, py::list& cases) {
  for (std::size_t k = 0; k < r.inputs.size() && k < r.cases.size(); ++k) {
    const auto* w = std::get_if<format::WheelRailRecord>(&r.inputs[k]);
    if (w == nullptr || !r.cases[k].solved) continue;
    py::dict d = cases[k];
    d["side"] = w->is_left() ? "left" : "right";
    d["rail_profile"] = profile_points(*w->rail.profile);
    d["wheel_profile"] = profile_points(*w->wheel.profile);
  }
}

/// Runs an input file as `rollcontact run` does (reports next to it or in `output_dir`).
py::list run_file(const std::filesystem::path& path, const std::filesystem::path& output_dir,
                  bool unvalidated) {
  batch::RunOptions options;
  options.output_dir = output_dir;
  options.solve_unvalidated = unvalidated;
  batch::RunResult r;
  {
    py::gil_scoped_release release;
    r = batch::run_input_file(path, options);
  }
  py::list cases;
  for (auto& o : r.cases) cases.append(outcome_to_dict(o));
  attach_profiles(r, cases);
  return cases;
}

/// A solver that keeps its state between cases (operators, sequences, profile curves): for
/// sweeps. Module-3 cases go to its PatchSolver, wheel/rail cases to its WheelsetSolver.
class Solver {
 public:
  /// Solves every [[case]] of `toml` in order; returns one dict per case. Relative profile file
  /// names are resolved against `base_dir`.
  py::list solve_toml(const std::string& toml, const std::string& name,
                      const std::filesystem::path& base_dir) {
    auto cases = format::read_toml_input_string(toml, name, base_dir);
    py::list out;
    for (auto& c : cases) {
      py::dict d;
      if (auto* m3 = std::get_if<format::CaseRecord>(&c)) {
        Solution s;
        {
          py::gil_scoped_release release;
          s = batch::solve_case(*m3, patch_solver_);
        }
        d = python::solution_to_dict(std::move(s));
        d["case"] = m3->case_number;
        d["module"] = 3;
      } else {
        const auto& w = std::get<format::WheelRailRecord>(c);
        WheelRailSolution s;
        {
          py::gil_scoped_release release;
          s = wheelset_solver_.solve(format::to_wheelrail_problem(w));
        }
        d = python::wheelrail_to_dict(std::move(s));
        d["case"] = w.case_number;
        d["module"] = 1;
        d["side"] = w.is_left() ? "left" : "right";
        d["rail_profile"] = profile_points(*w.rail.profile);
        d["wheel_profile"] = profile_points(*w.wheel.profile);
      }
      out.append(d);
    }
    return out;
  }

 private:
  PatchSolver patch_solver_;
  WheelsetSolver wheelset_solver_;
};

}  // namespace

/// CreepLookupTable::evaluate over NumPy arrays (broadcast): a (…, 3) array fx, fy, mz.
/// Arguments are taken as objects so that scalars stay 0-dimensional (a scalar query gives
/// shape (3,)).
py::array_t<double> evaluate_lookup(const CreepLookupTable& t, const py::object& a_over_b,
                                    const py::object& ksi, const py::object& eta,
                                    const py::object& phi) {
  auto args = py::make_tuple(a_over_b, ksi, eta, phi);
  py::object broadcast = py::module_::import("numpy").attr("broadcast_arrays")(*args);
  auto arrays = broadcast.cast<py::list>();
  std::vector<py::array_t<double, py::array::c_style | py::array::forcecast>> in;
  for (auto a : arrays)
    in.emplace_back(py::module_::import("numpy").attr("ascontiguousarray")(a, "float64"));
  // The broadcast shape (0-d for scalars; ascontiguousarray makes those 1-d).
  std::vector<py::ssize_t> shape;
  for (auto d : arrays[0].attr("shape").cast<py::tuple>()) shape.push_back(d.cast<py::ssize_t>());
  const py::ssize_t n = in[0].size();
  shape.push_back(3);
  py::array_t<double> out(shape);
  double* o = out.mutable_data();
  const double *ab = in[0].data(), *x = in[1].data(), *y = in[2].data(), *z = in[3].data();
  {
    py::gil_scoped_release release;
    for (py::ssize_t i = 0; i < n; ++i) {
      const CreepLookupValue v = t.evaluate(ab[i], x[i], y[i], z[i]);
      o[3 * i] = v.fx;
      o[3 * i + 1] = v.fy;
      o[3 * i + 2] = v.mz;
    }
  }
  return out;
}

/// Writes the cases of TOML text as a CONTACT .inp file (`rollcontact convert`): profile files
/// named in the text are found relative to `base_dir` and named relative to the .inp file.
void write_inp_from_toml(const std::string& toml, const std::filesystem::path& path,
                         const std::filesystem::path& base_dir) {
  (void)format::write_inp_input_file(path,
                                     format::read_toml_input_string(toml, "python", base_dir));
}

PYBIND11_MODULE(_rollcontact, m) {
  m.doc() = "rollcontact: rolling and sliding contact (CONTACT-compatible), compiled core";
  m.attr("__version__") = rollcontact::version_string;
  // Translators are tried latest first: the general one first, the input errors after it.
  py::register_exception<Error>(m, "Error", PyExc_RuntimeError);
  py::register_exception<InputError>(m, "InputError", PyExc_ValueError);
  m.def("run_file", &run_file, py::arg("path"), py::arg("output_dir") = std::filesystem::path{},
        py::arg("unvalidated") = false,
        "Run every case of a CONTACT .inp or TOML file like `rollcontact run`; returns a list of "
        "dicts, one per case (fields as NumPy arrays of shape (my, mx)). unvalidated: also "
        "solve the wheel/rail features not yet validated against CONTACT, with a warning each "
        "(`rollcontact run --unvalidated`).");
  m.def("write_inp_from_toml", &write_inp_from_toml, py::arg("toml"), py::arg("path"),
        py::arg("base_dir") = std::filesystem::path{},
        "Write the [[case]]s of TOML text as a CONTACT .inp file (module 3 and wheel/rail), every "
        "value explicit; profiles given as points become tables beside it.");
  py::class_<Solver>(m, "Solver",
                     "Solves cases given as TOML text, keeping operators and "
                     "sequences between calls.")
      .def(py::init<>())
      .def("solve_toml", &Solver::solve_toml, py::arg("toml"), py::arg("name") = "python",
           py::arg("base_dir") = std::filesystem::path{},
           "Solve every [[case]] of the TOML text (module 3 or wheel/rail); one dict per case.");
  py::class_<CreepLookupTable>(m, "CreepLookupTable",
                               "A creep-force lookup table (HDF5, `rollcontact lookup -o`): "
                               "normalised creep forces over a/b and normalised creepages.")
      .def(py::init(&load_creep_lookup), py::arg("path"), "Load a table written by rollcontact.")
      .def("evaluate", &evaluate_lookup, py::arg("a_over_b"), py::arg("ksi_n"), py::arg("eta_n"),
           py::arg("phi_n"),
           "Normalised results (Fx/(mu FN), Fy/(mu FN), Mz/(mu FN c)) as an array (..., 3); "
           "arguments broadcast like NumPy arrays.")
      .def(
          "forces",
          [](const CreepLookupTable& t, double a, double b, double fn, double g, double mu,
             double ksi, double eta, double phi) {
            const CreepLookupForces f = t.forces(a, b, fn, g, mu, ksi, eta, phi);
            return py::make_tuple(f.fx_N, f.fy_N, f.mz_Nmm);
          },
          py::arg("a_mm"), py::arg("b_mm"), py::arg("fn_N"), py::arg("g_N_mm2"), py::arg("mu"),
          py::arg("ksi"), py::arg("eta"), py::arg("phi_rad_mm"),
          "(Fx [N], Fy [N], Mz [N mm]) in physical units.")
      .def_property_readonly("method", [](const CreepLookupTable& t) { return t.info().method; })
      .def_property_readonly("mx", [](const CreepLookupTable& t) { return t.info().mx; })
      .def_property_readonly("axes", [](const CreepLookupTable& t) {
        const CreepLookupAxes& a = t.axes();
        py::dict d;
        d["a_over_b"] = a.a_over_b;
        d["ksi_n"] = a.ksi;
        d["eta_n"] = a.eta;
        d["phi_n"] = a.phi;
        return d;
      });
}
