#pragma once
// Text files of rows of numbers (TUM trajectories, .relations files): '#' comments and blank
// lines skipped, every other line exactly N finite numbers.

#include <array>
#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace swslam::common
{
/** Reads the rows; throws std::runtime_error "<what>: cannot open '<path>'" or
 * "<what>: '<path>' line L: expected N finite numbers '<format>'", or "<what>: '<path>'
 * line L: <problem>" when `check` (if given) finds a problem with a row's values. */
template <size_t N>
std::vector<std::array<double, N>> readNumberRows(
    const std::string& path, const std::string& what, const std::string& format,
    const std::function<std::string(const std::array<double, N>&)>& check = {})
{
  std::ifstream f(path);
  if (!f) throw std::runtime_error(what + ": cannot open '" + path + "'");
  std::vector<std::array<double, N>> rows;
  std::string line;
  size_t line_no = 0;
  while (std::getline(f, line))
  {
    line_no++;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    std::istringstream ss(line);
    std::array<double, N> row;
    bool ok = true;
    for (double& x : row) ok = ok && (ss >> x) && std::isfinite(x);
    std::string rest;
    if (!ok || (ss >> rest))
      throw std::runtime_error(what + ": '" + path + "' line " + std::to_string(line_no) +
                               ": expected " + std::to_string(N) + " finite numbers '" + format + "'");
    if (check)
      if (const std::string problem = check(row); !problem.empty())
        throw std::runtime_error(what + ": '" + path + "' line " + std::to_string(line_no) + ": " + problem);
    rows.push_back(row);
  }
  return rows;
}

}  // namespace swslam::common
