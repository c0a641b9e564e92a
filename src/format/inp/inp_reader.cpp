#include "format/inp/inp_reader.hpp"

#include <fmt/format.h>

#include <fstream>
#include <map>
#include <sstream>

#include "format/inp/inp_module1.hpp"
#include "format/inp/inp_module3.hpp"
#include "format/text/inp_stream.hpp"
#include "format/text/input_file.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::format {

namespace {

/// The module line `MODULE {REID {CPID}}` (spec §2).
struct ModuleLine {
  int module = 0;
  int reid = 0;
  int cpid = 1;
  int line = 0;
};

ModuleLine read_module_line(InpStream& in) {
  const GroupValues g = in.read_group({{"MODULE", FieldKind::integer},
                                       {"REID", FieldKind::integer, true},
                                       {"CPID", FieldKind::integer, true}},
                                      "the module line (MODULE {REID {CPID}})");
  ModuleLine m;
  m.line = g.line(0);
  m.module = g.integer(0);
  if (m.module != 0 && m.module != 1 && m.module != 3) {
    in.fail(m.line, fmt::format("module number {} is not valid (expected 3, 1 or 0)", m.module),
            std::to_string(m.module));
  }
  if (g.has(1)) {
    m.reid = g.integer(1);
    if (m.reid < 0 || m.reid > 999) {
      in.fail(m.line, fmt::format("result element REID = {} outside 0..999", m.reid));
    }
  }
  if (g.has(2)) {
    m.cpid = g.integer(2);
    if (m.cpid < 1 || m.cpid > 9) {
      in.fail(m.line, fmt::format("contact problem CPID = {} outside 1..9", m.cpid));
    }
  }
  return m;
}

}  // namespace

std::vector<InputCase> read_input_string(const std::string& text, const std::string& name,
                                         const std::filesystem::path& base_dir,
                                         const InpReadOptions& options) {
  InpStream in(text, name);
  Module3Reader module3(base_dir, options);
  Module1Reader module1(base_dir, options);
  std::map<int, int> case_counts;  // per result element, shared by modules 1 and 3
  std::vector<InputCase> cases;

  if (in.at_end()) in.fail(in.line_count(), "no module line found (expected e.g. '3 MODULE')");
  while (!in.at_end()) {
    const ModuleLine m = read_module_line(in);
    if (m.module == 0) break;  // "0 MODULE": stop reading, the rest of the file is ignored
    int module_line = m.line;
    for (;;) {
      const int case_number = ++case_counts[m.reid];
      int r = 0;
      if (m.module == 1) {
        WheelRailRecord p = module1.read_case(in, m.reid, module_line, case_number);
        r = p.digits.r;
        cases.emplace_back(std::move(p));
      } else {
        CaseRecord p = module3.read_case(in, m.reid, m.cpid, module_line, case_number);
        r = p.digits.r;
        cases.emplace_back(std::move(p));
      }
      if (r == 1 || r == 3) break;  // a module line follows
      if (in.at_end()) {
        in.fail(in.line_count(),
                fmt::format("end of file where the control words of the case after case {} were "
                            "expected (R={} continues without a module line)",
                            case_number, r));
      }
      module_line = 0;
    }
  }
  return cases;
}

std::vector<InputCase> read_input_cases(const std::filesystem::path& path,
                                        const InpReadOptions& options) {
  return read_input_string(read_input_file(path, "input file"), path.string(), path.parent_path(),
                           options);
}

std::vector<CaseRecord> read_inp_string(const std::string& text, const std::string& name,
                                        const std::filesystem::path& base_dir,
                                        const InpReadOptions& options) {
  std::vector<InputCase> cases = read_input_string(text, name, base_dir, options);
  std::vector<CaseRecord> problems;
  problems.reserve(cases.size());
  for (InputCase& c : cases) {
    if (const auto* wr = std::get_if<WheelRailRecord>(&c)) {
      const int line = wr->source.module_line > 0 ? wr->source.module_line : wr->source.first_line;
      throw InputError(name, line,
                       "module 1 (wheel/rail) input is not supported yet by this reader (use "
                       "read_input_cases)");
    }
    problems.push_back(std::move(std::get<CaseRecord>(c)));
  }
  return problems;
}

std::vector<CaseRecord> read_inp_string(const std::string& text, const std::string& name,
                                        const std::filesystem::path& base_dir) {
  return read_inp_string(text, name, base_dir, InpReadOptions{});
}

std::vector<CaseRecord> read_inp_file(const std::filesystem::path& path,
                                      const InpReadOptions& options) {
  return read_inp_string(read_input_file(path, "input file"), path.string(), path.parent_path(),
                         options);
}

std::vector<CaseRecord> read_inp_file(const std::filesystem::path& path) {
  return read_inp_file(path, InpReadOptions{});
}

}  // namespace rollcontact::format
