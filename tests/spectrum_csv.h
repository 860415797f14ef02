// SPDX-License-Identifier: LGPL-2.1-or-later
// The rows of a spectrum.csv of scene stability (the header first), each split at commas; for the stability tests.
#ifndef fluid_surface_tests_spectrum_csv_h
#define fluid_surface_tests_spectrum_csv_h

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

inline std::vector<std::vector<std::string>>
read_spectrum_csv(const std::string &path)
{
  std::vector<std::vector<std::string>> rows;
  std::ifstream                         csv(path);
  for (std::string line; std::getline(csv, line);)
    {
      std::vector<std::string> fields;
      std::istringstream       split(line);
      for (std::string field; std::getline(split, field, ',');)
        fields.push_back(field);
      rows.push_back(fields);
    }
  return rows;
}

#endif
