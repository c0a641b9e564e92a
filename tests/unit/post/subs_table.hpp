#pragma once
// Reads the blocks of a .subs file (spec/outputs.md §6) for comparisons in tests.

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace rollcontact::post::testing {

struct RefBlock {
  int nx = 0, ny = 0, nz = 0;
  /// X Y Z UX UY UZ SIGHYD SIGVM [SIGXX SIGXY SIGXZ SIGYY SIGYZ SIGZZ] per point
  std::vector<std::vector<double>> rows;
};

inline std::vector<RefBlock> read_subs(const std::string& path) {
  std::ifstream in(path);
  std::vector<RefBlock> blocks;
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("%   NX", 0) == 0) {
      RefBlock b;
      std::getline(in, line);
      std::istringstream(line) >> b.nx >> b.ny >> b.nz;
      std::getline(in, line);  // column names
      for (int k = 0; k < b.nx * b.ny * b.nz && std::getline(in, line); ++k) {
        std::istringstream ls(line);
        std::vector<double> row;
        double v = 0.0;
        while (ls >> v) row.push_back(v);
        b.rows.push_back(row);
      }
      blocks.push_back(b);
    }
  }
  return blocks;
}

}  // namespace rollcontact::post::testing
