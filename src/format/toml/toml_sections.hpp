#pragma once
// The section readers of a TOML case (one function per table: [solver], [normal], ...). Each
// reads its keys from the case table, checks them with file, line and key path, and fills its
// part of the CaseRecord.

#include "format/inp/wheelrail_record.hpp"
#include "format/toml/toml_table.hpp"

namespace rollcontact::format::toml_input {

/// [solver]: method, iteration limits, tolerance, relaxation.
void read_solver(Table& c, CaseRecord& p);
/// [normal]: prescribed force or approach, and the pressure model.
void read_normal(Table& c, CaseRecord& p);
/// [tangential]: kind of problem, creepages or forces, rolling step.
void read_tangential(Table& c, CaseRecord& p);
/// [friction]: the friction law and its values (per grid row when given so). `variation`, for a
/// wheel/rail case: friction sets at control points along `along` ("inclination" V=1: the rail
/// surface's inclination ALPHA [rad]; "track" V=2: SVF [mm]) as `points = [{at = …, <law
/// values>}, …]`; without it such a table is an error (module 3 has no rail).
void read_friction(Table& c, CaseRecord& p, VariableFriction* variation = nullptr);
/// [material]: the bodies, their compliance model, the influence-coefficient file. A wheel/rail
/// case (`wheel_rail`) has no conformal inclination table of its own: module 1 computes it.
void read_material(Table& c, const Context& ctx, CaseRecord& p, bool wheel_rail = false);
/// [grid]: the potential contact area (explicit or Hertzian).
void read_grid(Table& c, CaseRecord& p);
/// [geometry]: the undeformed distance of a non-Hertzian grid.
void read_geometry(Table& c, CaseRecord& p);
/// [output]: what is written and how much.
void read_output(Table& c, CaseRecord& p);
/// [damping]: damping of the iteration.
void read_damping(Table& c, CaseRecord& p);
/// [heat]: the temperature calculation.
void read_heat(Table& c, CaseRecord& p);
/// [subsurface]: blocks of points for subsurface stresses.
void read_subsurface(Table& c, CaseRecord& p);
/// Checks that need the grid: per-element arrays and friction rows.
void check_grid_sizes(Table& c, const CaseRecord& p);
/// The first case of a sequence (`element` names it: "result element 3") starts a new one:
/// previous_state other than "new" and initial_estimate other than "none" are overridden, a
/// warning each (spec/inp-format.md §3.2).
void start_new_sequence(ControlDigits& d, const std::string& element,
                        std::vector<std::string>& warnings);

}  // namespace rollcontact::format::toml_input
