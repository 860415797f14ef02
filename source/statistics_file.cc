#include <fluid_surface/statistics_file.h>

#include <iomanip>
#include <stdexcept>

namespace FluidSurface
{
  void
  StatisticsFile::open(const std::string &filename, const unsigned int rank)
  {
    writes = (rank == 0);
    columns.clear();
    row.clear();
    if (writes)
      {
        file.open(filename, std::ios::out | std::ios::trunc);
        if (!file)
          throw std::runtime_error("cannot write the statistics file " + filename);
      }
  }

  void
  StatisticsFile::add_value(const std::string &name, const double value)
  {
    for (auto &entry : row)
      if (entry.first == name)
        {
          entry.second = value;
          return;
        }
    row.emplace_back(name, value);
  }

  void
  StatisticsFile::end_row()
  {
    if (columns.empty())
      {
        for (const auto &entry : row)
          columns.push_back(entry.first);
        if (writes)
          for (unsigned int c = 0; c < columns.size(); ++c)
            file << "# " << c + 1 << ": " << columns[c] << '\n';
      }
    else if (row.size() != columns.size())
      throw std::logic_error("statistics: a row has " + std::to_string(row.size()) + " columns, the header " +
                             std::to_string(columns.size()));
    if (writes)
      {
        file << std::setprecision(12);
        for (unsigned int c = 0; c < columns.size(); ++c)
          {
            double value = 0;
            bool   found = false;
            for (const auto &entry : row)
              if (entry.first == columns[c])
                {
                  value = entry.second;
                  found = true;
                }
            if (!found)
              throw std::logic_error("statistics: column '" + columns[c] + "' missing in a row");
            file << (c == 0 ? "" : " ") << value;
          }
        file << std::endl;
      }
    row.clear();
  }
} // namespace FluidSurface
