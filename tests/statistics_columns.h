// SPDX-License-Identifier: LGPL-2.1-or-later
// The columns of a `statistics` file by name (its `# N: name` header lines), for the tests that read one.
#ifndef fluid_surface_tests_statistics_columns_h
#define fluid_surface_tests_statistics_columns_h

#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

/// The columns of the statistics file @p file by name.
inline std::map<std::string, std::vector<double>>
read_statistics_columns(const std::string &file)
{
  std::ifstream                              in(file);
  std::vector<std::string>                   names;
  std::map<std::string, std::vector<double>> columns;
  for (std::string line; std::getline(in, line);)
    {
      if (line.rfind("# ", 0) == 0)
        {
          const auto colon = line.find(": ");
          names.push_back(line.substr(colon + 2));
          continue;
        }
      std::istringstream words(line);
      double             value;
      for (unsigned int c = 0; c < names.size() && (words >> value); ++c)
        columns[names[c]].push_back(value);
    }
  return columns;
}

#endif
