// SPDX-License-Identifier: LGPL-2.1-or-later
#include <fluid_surface/io/checkpoint.h>
#include <fluid_surface/io/statistics_file.h>

#include <fcntl.h>
#include <unistd.h>

#include <filesystem>

#include <iomanip>
#include <stdexcept>

namespace FluidSurface
{
  void
  StatisticsFile::open(const std::string &filename, const unsigned int rank)
  {
    writes = (rank == 0);
    path   = filename;
    length = 0;
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
        length = static_cast<std::uint64_t>(file.tellp());
      }
    row.clear();
  }

  void
  StatisticsFile::save(CheckpointData &data) const
  {
    std::string names;
    for (const auto &name : columns)
      names += (names.empty() ? "" : "|") + name;
    data.set("statistics/columns", names);
    std::uint64_t bytes = 0;
    if (writes)
      {
        bytes = length;
        // The rows a checkpoint refers to must survive a crash of the machine, too.
        const int fd = ::open(path.c_str(), O_RDONLY);
        if (fd >= 0)
          {
            ::fsync(fd);
            ::close(fd);
          }
      }
    data.set("statistics/bytes", bytes);
  }

  void
  StatisticsFile::resume(const std::string &filename, const unsigned int rank, const CheckpointData &data)
  {
    writes = (rank == 0);
    path   = filename;
    row.clear();
    columns.clear();
    const std::string names = data.get_string("statistics/columns");
    for (std::size_t begin = 0; !names.empty() && begin <= names.size();)
      {
        const std::size_t end = std::min(names.find('|', begin), names.size());
        columns.push_back(names.substr(begin, end - begin));
        begin = end + 1;
      }
    if (!writes)
      return;
    const std::uintmax_t bytes = data.get_uint64("statistics/bytes");
    std::error_code      ec;
    const std::uintmax_t size = std::filesystem::file_size(filename, ec);
    if (ec || size < bytes)
      throw std::runtime_error("the statistics file " + filename + " has " + (ec ? std::string("gone") :
                               std::to_string(size) + " bytes") + ", fewer than the " + std::to_string(bytes) +
                               " it had at the checkpoint; it was changed after the run, cannot resume");
    std::filesystem::resize_file(filename, bytes);
    length = bytes;
    file.open(filename, std::ios::out | std::ios::app);
    if (!file)
      throw std::runtime_error("cannot write the statistics file " + filename);
  }
} // namespace FluidSurface
