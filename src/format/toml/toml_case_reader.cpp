#include "format/toml/toml_case_reader.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>

#include "format/inp/grid_extent.hpp"
#include "format/inp/inp_blocks.hpp"
#include "format/inp/reader_checks.hpp"
#include "format/text/input_file.hpp"
#include "format/toml/toml_sections.hpp"
#include "format/toml/toml_table.hpp"
#include "format/toml/toml_wheelrail.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::format {

namespace {

using namespace toml_input;

CaseRecord read_case(Table& c, const Context& ctx, Sequence& seq, const std::string& file) {
  CaseRecord p;
  p.source.file = file;
  p.source.first_line = c.line();
  ControlDigits& d = p.digits;
  auto warn = [&p](std::string text) { p.source.warnings.push_back(std::move(text)); };

  (void)c.opt_text("name");  // a label for humans; CaseRecord has no place for it
  p.result_element = c.integer_in("result_element", 0, 0, 999);
  p.contact_problem = c.integer_in("contact_problem", 1, 1, 9);
  d.r = c.boolean_or("solve", true) ? 1 : 3;
  d.p = c.choice_or("previous_state", schema::previous_state, 2);
  d.i = c.choice_or("initial_estimate", schema::initial_estimate, 0);
  d.gapwgt = c.choice_or("gap_weighting", schema::gap_weighting, 0);
  d.d = 2;
  d.z = 2;

  read_solver(c, p);
  d.g = p.solver.method;
  if (p.solver.method == 5) p.source.warnings.push_back(kGdSteadyNote);
  read_normal(c, p);
  read_tangential(c, p);
  read_friction(c, p);
  read_material(c, ctx, p);
  read_damping(c, p);
  read_heat(c, p);
  read_grid(c, p);
  read_geometry(c, p);
  read_subsurface(c, p);
  read_output(c, p);
  check_grid_sizes(c, p);
  if (p.friction.law == 6 && d.h == 0)
    c.fail("friction.law = \"temperature\" requires a [heat] table");
  if (p.friction.law == 6 && (d.m == 2 || d.m == 3 || d.m == 5 || d.m == 6 || d.m == 7))
    c.fail("friction.law = \"temperature\" is not allowed with this material.model");
  c.finish();

  const auto key = std::make_pair(p.result_element, p.contact_problem);
  const auto prev = seq.last.find(key);
  const std::string element = p.contact_problem == 1
                                  ? fmt::format("result element {}", p.result_element)
                                  : fmt::format("result element {} contact problem {}",
                                                p.result_element, p.contact_problem);
  if (prev == seq.last.end()) {
    start_new_sequence(d, element, p.source.warnings);
  } else if (d.p != 2 || d.i != 0) {
    // Continuing from the previous case needs the same elements, possibly shifted by whole ones.
    const GridExtent ext = grid_extent(p.potential);
    const GridExtent old = grid_extent(prev->second.potential);
    if (ext.known && old.known) {
      if (differs(ext.dx, old.dx, 1e-6) || differs(ext.dy, old.dy, 1e-6)) {
        c.fail(
            fmt::format("continuing from the previous case: element size {}, {} must equal "
                        "the previous {}, {}",
                        ext.dx, ext.dy, old.dx, old.dy));
      }
      if (!is_multiple(ext.xl - old.xl, old.dx) || !is_multiple(ext.yl - old.yl, old.dy)) {
        c.fail(
            fmt::format("continuing from the previous case: the grid offset ({:.6g}, {:.6g}) "
                        "must be a whole number of elements",
                        ext.xl - old.xl, ext.yl - old.yl));
      }
    }
  }
  if (p.solver.maxout > 1 && std::abs(material_k(p.materials)) < 1e-10 &&
      p.materials.influence_type != 4) {  // C=4 couples whatever K is (spec-additions §B8)
    warn(
        fmt::format("max_coupling_iterations = {} overridden to 1: the materials are "
                    "quasi-identical (K = 0)",
                    p.solver.maxout));
    p.solver.maxout = 1;
  }
  p.case_number = ++seq.case_counts[p.result_element];
  seq.last[key] = p;
  return p;
}

}  // namespace

std::vector<InputCase> read_toml_input_string(const std::string& text, const std::string& name,
                                              const std::filesystem::path& base_dir,
                                              const TomlReadOptions& options) {
  toml::table root;
  try {
    root = toml::parse(std::string_view(text), std::string_view(name));
  } catch (const toml::parse_error& e) {
    throw InputError(name, static_cast<int>(e.source().begin.line),
                     fmt::format("TOML syntax error: {}", e.description()));
  }
  Table top(root, "", name);
  if (auto v = top.opt_integer("version"); v && *v != toml_schema::version) {
    top.fail_key("version", fmt::format("case-file version {} is not supported (expected {})", *v,
                                        toml_schema::version));
  }
  std::vector<Table> cases = top.tables("case");
  top.finish();
  if (cases.empty()) top.fail("no [[case]] found");
  const Context ctx{base_dir, options};
  Sequence seq;
  std::vector<InputCase> problems;
  problems.reserve(cases.size());
  for (Table& c : cases) {
    if (c.has("wheel_rail")) {
      const int element = c.integer_in("result_element", 0, 0, 999);
      problems.emplace_back(read_wheelrail_case(c, ctx, name, ++seq.case_counts[element]));
    } else {
      problems.emplace_back(read_case(c, ctx, seq, name));
    }
  }
  return problems;
}

std::vector<InputCase> read_toml_input_file(const std::filesystem::path& path,
                                            const TomlReadOptions& options) {
  return read_toml_input_string(read_input_file(path, "input file"), path.string(),
                                path.parent_path(), options);
}

std::vector<CaseRecord> read_toml_string(const std::string& text, const std::string& name,
                                         const std::filesystem::path& base_dir,
                                         const TomlReadOptions& options) {
  std::vector<CaseRecord> out;
  for (InputCase& c : read_toml_input_string(text, name, base_dir, options)) {
    auto* m3 = std::get_if<CaseRecord>(&c);
    if (m3 == nullptr)
      throw InputError(name, std::get<WheelRailRecord>(c).source.first_line,
                       "a wheel/rail case ([case.wheel_rail]) where only module-3 cases are "
                       "taken (rollcontact run reads both)");
    out.push_back(std::move(*m3));
  }
  return out;
}

std::vector<CaseRecord> read_toml_file(const std::filesystem::path& path,
                                       const TomlReadOptions& options) {
  return read_toml_string(read_input_file(path, "input file"), path.string(), path.parent_path(),
                          options);
}

}  // namespace rollcontact::format
