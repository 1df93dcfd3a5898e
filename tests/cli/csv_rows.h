#pragma once
// The cells of each line of a program's CSV output (no quoting: insmc's
// numeric tables need none), for the end-to-end tests.
#include <sstream>
#include <string>
#include <vector>

namespace insmc::testing {

inline std::vector<std::vector<std::string>> csv_rows(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::istringstream l(line);
    for (std::string cell; std::getline(l, cell, ',');) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.emplace_back();
    rows.push_back(cells);
  }
  return rows;
}

}  // namespace insmc::testing
