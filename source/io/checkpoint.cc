// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/utilities.h>
#include <deal.II/grid/cell_id.h>

#include <fluid_surface/io/checkpoint.h>
#include <fluid_surface/io/parameter_file.h>

#include <boost/crc.hpp>

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace FluidSurface
{
  using namespace dealii;
  namespace fs = std::filesystem;

  // ------------------------------------------------------------------ CheckpointData
  namespace
  {
    /// %a: the exact binary value as text (strtod reads it back, including inf and nan).
    std::string
    exact(const double value)
    {
      char buffer[64];
      std::snprintf(buffer, sizeof(buffer), "%a", value);
      return buffer;
    }

    double
    parse_exact(const std::string &key, const std::string &text)
    {
      char        *end   = nullptr;
      const double value = std::strtod(text.c_str(), &end);
      if (end == text.c_str() || *end != '\0')
        throw std::runtime_error("checkpoint entry '" + key + "' = '" + text + "' is not a number");
      return value;
    }

    template <typename T>
    void
    append(std::vector<char> &buffer, const T &value)
    {
      const char *bytes = reinterpret_cast<const char *>(&value);
      buffer.insert(buffer.end(), bytes, bytes + sizeof(T));
    }

    /// Reads a T at @p position of @p buffer, advancing it; throws if the buffer ends early.
    template <typename T>
    T
    extract(const std::vector<char> &buffer, std::size_t &position)
    {
      if (position + sizeof(T) > buffer.size())
        throw std::runtime_error("checkpoint fields end early (truncated)");
      T value;
      std::memcpy(&value, buffer.data() + position, sizeof(T));
      position += sizeof(T);
      return value;
    }

    std::uint32_t
    crc32(const char *data, const std::size_t size)
    {
      boost::crc_32_type crc;
      crc.process_bytes(data, size);
      return crc.checksum();
    }
  } // namespace

  void
  CheckpointData::set(const std::string &key, const double value)
  {
    scalars[key] = exact(value);
  }

  void
  CheckpointData::set(const std::string &key, const unsigned int value)
  {
    scalars[key] = std::to_string(value);
  }

  void
  CheckpointData::set(const std::string &key, const std::uint64_t value)
  {
    scalars[key] = std::to_string(value);
  }

  void
  CheckpointData::set(const std::string &key, const bool value)
  {
    scalars[key] = value ? "true" : "false";
  }

  void
  CheckpointData::set(const std::string &key, const Tensor<1, 3> &value)
  {
    scalars[key] = exact(value[0]) + " " + exact(value[1]) + " " + exact(value[2]);
  }

  void
  CheckpointData::set(const std::string &key, const char *value)
  {
    set(key, std::string(value));
  }

  void
  CheckpointData::set(const std::string &key, const std::string &value)
  {
    Assert(value.find('\n') == std::string::npos, ExcMessage("a checkpoint string holds a line break"));
    scalars[key] = value;
  }

  const std::string &
  CheckpointData::get_string(const std::string &key) const
  {
    const auto entry = scalars.find(key);
    if (entry == scalars.end())
      throw std::runtime_error("the checkpoint has no entry '" + key + "'");
    return entry->second;
  }

  double
  CheckpointData::get_double(const std::string &key) const
  {
    return parse_exact(key, get_string(key));
  }

  std::uint64_t
  CheckpointData::get_uint64(const std::string &key) const
  {
    const std::string &text = get_string(key);
    if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
      throw std::runtime_error("checkpoint entry '" + key + "' = '" + text + "' is not a count");
    return std::stoull(text);
  }

  unsigned int
  CheckpointData::get_unsigned(const std::string &key) const
  {
    return static_cast<unsigned int>(get_uint64(key));
  }

  bool
  CheckpointData::get_bool(const std::string &key) const
  {
    const std::string &text = get_string(key);
    if (text != "true" && text != "false")
      throw std::runtime_error("checkpoint entry '" + key + "' = '" + text + "' is not true|false");
    return text == "true";
  }

  Tensor<1, 3>
  CheckpointData::get_tensor(const std::string &key) const
  {
    std::istringstream in(get_string(key));
    Tensor<1, 3>       value;
    for (unsigned int d = 0; d < 3; ++d)
      {
        std::string word;
        if (!(in >> word))
          throw std::runtime_error("checkpoint entry '" + key + "' needs three numbers");
        value[d] = parse_exact(key, word);
      }
    return value;
  }

  void
  CheckpointData::set_fields(const std::string                    &name,
                             const DoFHandler<2, 3>               &dofs,
                             const std::vector<const VectorType *> &vectors)
  {
    const MPI_Comm     communicator = dofs.get_communicator();
    const unsigned int n       = dofs.get_fe().n_dofs_per_cell();
    std::vector<char>  local;
    Vector<double>     values(n);
    unsigned int       n_cells = 0;
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          // The text form of the CellId: to_binary() does not round-trip in deal.II 9.4.
          const std::string id = cell->id().to_string();
          append(local, static_cast<std::uint32_t>(id.size()));
          local.insert(local.end(), id.begin(), id.end());
          for (const VectorType *vector : vectors)
            {
              cell->get_dof_values(*vector, values);
              local.insert(local.end(),
                           reinterpret_cast<const char *>(values.begin()),
                           reinterpret_cast<const char *>(values.end()));
            }
          ++n_cells;
        }
    const std::vector<std::vector<char>> parts = Utilities::MPI::gather(communicator, local, 0);
    const std::vector<unsigned int>      counts = Utilities::MPI::gather(communicator, n_cells, 0);
    std::vector<char>                    block;
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        unsigned int total = 0;
        for (const unsigned int c : counts)
          total += c;
        append(block, static_cast<std::uint32_t>(vectors.size()));
        append(block, static_cast<std::uint32_t>(n));
        append(block, static_cast<std::uint32_t>(total));
        for (const auto &part : parts)
          block.insert(block.end(), part.begin(), part.end());
      }
    fields[name] = std::move(block);
  }

  void
  CheckpointData::get_fields(const std::string              &name,
                             const DoFHandler<2, 3>         &dofs,
                             const std::vector<VectorType *> &vectors) const
  {
    const auto entry = fields.find(name);
    if (entry == fields.end())
      throw std::runtime_error("the checkpoint has no fields '" + name + "'");
    const std::vector<char> &block    = entry->second;
    std::size_t              position = 0;
    const auto               n_vectors = extract<std::uint32_t>(block, position);
    const auto               n         = extract<std::uint32_t>(block, position);
    const auto               n_cells   = extract<std::uint32_t>(block, position);
    if (n_vectors != vectors.size() || n != dofs.get_fe().n_dofs_per_cell() ||
        n_cells != dofs.get_triangulation().n_global_active_cells())
      throw std::runtime_error("the checkpoint's fields '" + name + "' have " + std::to_string(n_vectors) +
                               " vectors of " + std::to_string(n) + " values per cell on " +
                               std::to_string(n_cells) + " cells; this run has " + std::to_string(vectors.size()) +
                               " of " + std::to_string(dofs.get_fe().n_dofs_per_cell()) + " on " +
                               std::to_string(dofs.get_triangulation().n_global_active_cells()) +
                               " (different geometry or element parameters)");
    const std::size_t values_size = std::size_t(n_vectors) * n * sizeof(double);
    std::map<std::string, std::size_t> where;
    for (std::uint32_t c = 0; c < n_cells; ++c)
      {
        const auto length = extract<std::uint32_t>(block, position);
        if (position + length + values_size > block.size())
          throw std::runtime_error("the checkpoint's fields '" + name + "' end early (truncated)");
        where[std::string(block.data() + position, length)] = position + length;
        position += length + values_size;
      }
    if (position != block.size() || where.size() != n_cells)
      throw std::runtime_error("the checkpoint's fields '" + name + "' are malformed");

    const IndexSet                      &owned = dofs.locally_owned_dofs();
    std::vector<types::global_dof_index> indices(n);
    for (VectorType *vector : vectors)
      vector->reinit(owned, dofs.get_communicator());
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto found = where.find(cell->id().to_string());
          if (found == where.end())
            throw std::runtime_error("the checkpoint's fields '" + name + "' lack cell " + cell->id().to_string());
          cell->get_dof_indices(indices);
          for (unsigned int v = 0; v < vectors.size(); ++v)
            {
              const char *values = block.data() + found->second + std::size_t(v) * n * sizeof(double);
              for (unsigned int i = 0; i < n; ++i)
                if (owned.is_element(indices[i]))
                  {
                    double value;
                    std::memcpy(&value, values + i * sizeof(double), sizeof(double));
                    (*vectors[v])[indices[i]] = value;
                  }
            }
        }
    for (VectorType *vector : vectors)
      vector->compress(VectorOperation::insert);
  }

  std::string
  CheckpointData::state_text() const
  {
    std::string text = "# fluid_surface checkpoint state: key = value (numbers in C99 %a notation)\n";
    for (const auto &[key, value] : scalars)
      text += key + " = " + value + "\n";
    return text + "end\n";
  }

  std::vector<char>
  CheckpointData::field_bytes() const
  {
    std::vector<char> bytes;
    append(bytes, static_cast<std::uint32_t>(fields.size()));
    for (const auto &[name, block] : fields)
      {
        append(bytes, static_cast<std::uint32_t>(name.size()));
        bytes.insert(bytes.end(), name.begin(), name.end());
        append(bytes, static_cast<std::uint64_t>(block.size()));
        bytes.insert(bytes.end(), block.begin(), block.end());
      }
    return bytes;
  }

  CheckpointData
  CheckpointData::from_buffers(const std::string &state, const std::vector<char> &field_bytes)
  {
    CheckpointData     data;
    std::istringstream in(state);
    bool               complete = false;
    for (std::string line; std::getline(in, line);)
      {
        if (line.empty() || line[0] == '#')
          continue;
        if (line == "end")
          {
            complete = true;
            break;
          }
        const auto eq = line.find(" = ");
        if (eq == std::string::npos)
          throw std::runtime_error("malformed checkpoint state line '" + line + "'");
        data.scalars[line.substr(0, eq)] = line.substr(eq + 3);
      }
    if (!complete)
      throw std::runtime_error("the checkpoint state ends early (truncated)");
    std::size_t position = 0;
    const auto  n_blocks = extract<std::uint32_t>(field_bytes, position);
    for (std::uint32_t b = 0; b < n_blocks; ++b)
      {
        const auto length = extract<std::uint32_t>(field_bytes, position);
        if (position + length > field_bytes.size())
          throw std::runtime_error("checkpoint fields end early (truncated)");
        const std::string name(field_bytes.data() + position, length);
        position += length;
        const auto size = extract<std::uint64_t>(field_bytes, position);
        if (position + size > field_bytes.size())
          throw std::runtime_error("checkpoint fields end early (truncated)");
        data.fields[name].assign(field_bytes.begin() + position, field_bytes.begin() + position + size);
        position += size;
      }
    if (position != field_bytes.size())
      throw std::runtime_error("checkpoint fields have trailing bytes");
    return data;
  }

  // ------------------------------------------------------------------ files

  namespace
  {
    /// Writes @p size bytes to @p path and fsyncs them; "" or the reason of the failure.
    std::string
    write_durably(const std::string &path, const char *data, const std::size_t size)
    {
      const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      if (fd < 0)
        return "cannot create " + path + ": " + std::strerror(errno);
      std::size_t written = 0;
      while (written < size)
        {
          const ssize_t n = ::write(fd, data + written, size - written);
          if (n < 0)
            {
              if (errno == EINTR)
                continue;
              const std::string reason = "cannot write " + path + ": " + std::strerror(errno);
              ::close(fd);
              return reason;
            }
          written += static_cast<std::size_t>(n);
        }
      if (::fsync(fd) != 0)
        {
          const std::string reason = "cannot flush " + path + " to disk: " + std::strerror(errno);
          ::close(fd);
          return reason;
        }
      if (::close(fd) != 0)
        return "cannot close " + path + ": " + std::strerror(errno);
      return "";
    }

    /// Makes a rename or creation inside @p directory durable.
    void
    sync_directory(const std::string &directory)
    {
      const int fd = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY);
      if (fd >= 0)
        {
          ::fsync(fd);
          ::close(fd);
        }
    }

    bool
    read_whole_file(const std::string &path, std::vector<char> &bytes)
    {
      std::ifstream in(path, std::ios::binary);
      if (!in)
        return false;
      bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
      return !in.bad();
    }

    const char *slot_names[2] = {"slot-0", "slot-1"};

    /// The manifest: name, size and CRC-32 of each file, then "end".
    std::string
    manifest_line(const std::string &name, const std::vector<char> &bytes)
    {
      return name + " " + std::to_string(bytes.size()) + " " + std::to_string(crc32(bytes.data(), bytes.size())) +
             "\n";
    }
  } // namespace

  // ------------------------------------------------------------------ Checkpoint

  void
  Checkpoint::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("checkpoint");
    prm.declare_entry("steps between checkpoints",
                      "0",
                      Patterns::Integer(0),
                      "N_c ≥ 0: write a checkpoint after every N_c-th time step (0: not by steps). Checkpoints go "
                      "to <output directory>/checkpoint/ (scene full only).");
    prm.declare_entry("wall time between checkpoints",
                      "600",
                      RealRange::at_least(0),
                      "T_c ≥ 0 in seconds: write a checkpoint when T_c seconds of wall time have passed since the "
                      "last one (0: not by wall time). With both entries 0 no checkpoints are written.");
    prm.declare_entry("resume",
                      "false",
                      Patterns::Selection("true|false|auto"),
                      "Continue the run from the last good checkpoint in the output directory. true: a "
                      "usable checkpoint must exist; auto: resume when one exists, else start a new run; "
                      "false: start a new run (and remove old checkpoints). A resumed run continues exactly as "
                      "the run that wrote the checkpoint would have: bit for bit on one MPI rank, to rounding on "
                      "several (as two uninterrupted parallel runs differ), also on a different number of ranks "
                      "than the checkpoint's. The factorization kept across steps (linear solver/reuse "
                      "factorization) and the last solution, GMRES's initial guess, are dropped at every "
                      "checkpoint, so a run that writes no checkpoints differs from one that does at the linear "
                      "solver tolerance.");
    prm.declare_entry("steps per run",
                      "0",
                      Patterns::Integer(0),
                      "N_run ≥ 0: after N_run time steps of this run, write a checkpoint and stop with exit status "
                      "0 (to split a long run into jobs; resume with resume = auto). 0: no limit.");
    prm.leave_subsection();
  }

  void
  Checkpoint::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("checkpoint");
    steps_between     = prm.get_integer("steps between checkpoints");
    wall_time_between = prm.get_double("wall time between checkpoints");
    const std::string r = prm.get("resume");
    resume            = (r == "true" ? Resume::yes : r == "auto" ? Resume::automatic : Resume::no);
    max_steps_per_run = prm.get_integer("steps per run");
    prm.leave_subsection();
  }

  namespace
  {
    double
    wall_seconds()
    {
      return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
    }
  } // namespace

  void
  Checkpoint::initialize(const std::string &dir, const MPI_Comm comm)
  {
    directory            = dir.empty() || dir.back() == '/' ? dir : dir + "/";
    communicator         = comm;
    current_slot         = "";
    last_write_wall_time = wall_seconds();
  }

  std::string
  Checkpoint::verify(const std::string &slot) const
  {
    const std::string path = directory + slot + "/";
    std::ifstream     manifest(path + "manifest");
    if (!manifest)
      return "missing (no " + slot + "/manifest)";
    std::string name;
    bool        complete = false;
    unsigned int n_files = 0;
    while (manifest >> name)
      {
        if (name == "end")
          {
            complete = true;
            break;
          }
        std::uint64_t size = 0, crc = 0;
        if (!(manifest >> size >> crc))
          return "its manifest is malformed";
        std::vector<char> bytes;
        if (!read_whole_file(path + name, bytes))
          return "its file " + name + " is missing";
        if (bytes.size() != size)
          return "its file " + name + " has " + std::to_string(bytes.size()) + " bytes instead of " +
                 std::to_string(size) + " (truncated)";
        if (crc32(bytes.data(), bytes.size()) != crc)
          return "its file " + name + " fails the CRC-32 check (corrupt)";
        ++n_files;
      }
    if (!complete || n_files != 2)
      return "its manifest is incomplete";
    return "";
  }

  bool
  Checkpoint::find(std::ostream &log)
  {
    current_slot = "";
    if (resume == Resume::no)
      return false;
    std::string chosen, report;
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        // The slot `last` names first; without (a readable) `last`, the slot with the later step.
        std::string   preferred;
        std::ifstream last(directory + "last");
        if (last)
          last >> preferred;
        if (preferred != slot_names[0] && preferred != slot_names[1])
          {
            preferred          = "";
            unsigned int steps[2] = {0, 0};
            for (unsigned int s = 0; s < 2; ++s)
              {
                std::ifstream state(directory + slot_names[s] + "/state");
                for (std::string line; std::getline(state, line);)
                  if (line.rfind("time stepping/steps = ", 0) == 0)
                    steps[s] = std::atoi(line.c_str() + 22);
              }
            preferred = steps[1] > steps[0] ? slot_names[1] : slot_names[0];
          }
        const std::string other = (preferred == slot_names[0] ? slot_names[1] : slot_names[0]);
        const std::string problem = verify(preferred);
        if (!fs::exists(directory + slot_names[0]) && !fs::exists(directory + slot_names[1]))
          report = "no checkpoint in " + directory;
        else if (problem.empty())
          chosen = preferred;
        else
          {
            const std::string other_problem = verify(other);
            if (other_problem.empty())
              {
                chosen = other;
                if (fs::exists(directory + preferred))
                  report = "checkpoint " + directory + preferred + " is not usable: " + problem + "; using the older " +
                           other + " instead";
              }
            else
              report = "no usable checkpoint in " + directory + " (" + preferred + ": " + problem + "; " + other +
                       ": " + other_problem + ")";
          }
      }
    chosen = Utilities::MPI::broadcast(communicator, chosen, 0);
    report = Utilities::MPI::broadcast(communicator, report, 0);
    if (chosen.empty() && resume == Resume::yes)
      throw_invalid_entry("checkpoint/resume",
                          "true",
                          "a usable checkpoint of an earlier run (found: " + report + "), or resume = auto|false");
    if (!report.empty() && Utilities::MPI::this_mpi_process(communicator) == 0)
      log << "-- " << report << (chosen.empty() ? "; starting a new run" : "") << std::endl;
    current_slot = chosen;
    return !chosen.empty();
  }

  CheckpointData
  Checkpoint::read() const
  {
    std::string       state, error;
    std::vector<char> bytes;
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        std::vector<char> text;
        if (!read_whole_file(directory + current_slot + "/state", text) ||
            !read_whole_file(directory + current_slot + "/fields", bytes))
          error = "cannot read the checkpoint " + directory + current_slot;
        state.assign(text.begin(), text.end());
      }
    error = Utilities::MPI::broadcast(communicator, error, 0);
    if (!error.empty())
      throw std::runtime_error(error);
    state = Utilities::MPI::broadcast(communicator, state, 0);
    std::uint64_t size = Utilities::MPI::broadcast(communicator, static_cast<std::uint64_t>(bytes.size()), 0);
    bytes.resize(size);
    // In pieces: an MPI count is an int.
    for (std::uint64_t offset = 0; offset < size; offset += (1u << 30))
      Utilities::MPI::broadcast(bytes.data() + offset, std::min<std::uint64_t>(size - offset, 1u << 30), 0, communicator);
    return CheckpointData::from_buffers(state, bytes);
  }

  void
  Checkpoint::clear()
  {
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        std::error_code ec;
        fs::remove(directory + "last", ec);
        for (const char *slot : slot_names)
          {
            fs::remove_all(directory + slot, ec);
            fs::remove_all(directory + slot + ".tmp", ec);
          }
      }
    current_slot = "";
    MPI_Barrier(communicator);
  }

  bool
  Checkpoint::due(const unsigned int step) const
  {
    unsigned int is_due = 0;
    if (steps_between > 0 && step % steps_between == 0)
      is_due = 1;
    // Rank 0's clock decides, so that all ranks agree.
    if (wall_time_between > 0 && Utilities::MPI::this_mpi_process(communicator) == 0 &&
        wall_seconds() - last_write_wall_time >= wall_time_between)
      is_due = 1;
    return Utilities::MPI::max(is_due, communicator) > 0;
  }

  bool
  Checkpoint::write(const CheckpointData &data, const unsigned int step, const double time, std::ostream &log)
  {
    const std::string target = (current_slot == slot_names[0] ? slot_names[1] : slot_names[0]);
    std::string       error;
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        const std::string       text  = data.state_text();
        const std::vector<char> state(text.begin(), text.end());
        const std::vector<char> fields = data.field_bytes();
        const std::string       tmp    = directory + target + ".tmp";
        const std::string       manifest =
          manifest_line("fields", fields) + manifest_line("state", state) + "end\n";
        std::error_code ec;
        const fs::space_info space = fs::space(directory, ec);
        const std::uintmax_t needed = fields.size() + state.size() + manifest.size() + 4096;
        fs::remove_all(tmp, ec);
        if (!ec && space.available < needed)
          error = "not enough disk space in " + directory + " (" + std::to_string(space.available) +
                  " bytes available, " + std::to_string(needed) + " needed)";
        else if (!fs::create_directories(tmp, ec) || ec)
          error = "cannot create " + tmp + ": " + (ec ? ec.message() : std::string("it exists"));
        if (error.empty())
          error = write_durably(tmp + "/fields", fields.data(), fields.size());
        if (error.empty())
          error = write_durably(tmp + "/state", state.data(), state.size());
        if (error.empty())
          error = write_durably(tmp + "/manifest", manifest.data(), manifest.size());
        if (error.empty())
          {
            sync_directory(tmp);
            // The target is not the last good slot: removing it first loses nothing.
            fs::remove_all(directory + target, ec);
            if (!ec)
              fs::rename(tmp, directory + target, ec);
            if (ec)
              error = "cannot rename " + tmp + " to " + target + ": " + ec.message();
          }
        if (error.empty())
          {
            sync_directory(directory);
            std::ostringstream last;
            last << target << "\nstep " << step << "\ntime " << std::setprecision(17) << time << '\n';
            error = write_durably(directory + "last.tmp", last.str().data(), last.str().size());
            if (error.empty())
              {
                fs::rename(directory + "last.tmp", directory + "last", ec);
                if (ec)
                  error = "cannot rename last.tmp to last: " + ec.message();
                sync_directory(directory);
              }
          }
        if (!error.empty())
          fs::remove_all(tmp, ec);
      }
    error = Utilities::MPI::broadcast(communicator, error, 0);
    last_write_wall_time = wall_seconds();
    if (!error.empty())
      {
        if (Utilities::MPI::this_mpi_process(communicator) == 0)
          log << "    warning: checkpoint at step " << step << " not written: " << error << "; "
            << (current_slot.empty() ? std::string("there is no earlier checkpoint") :
                                       "the previous one (" + directory + current_slot + ") is kept")
            << std::endl;
        return false;
      }
    current_slot = target;
    return true;
  }
} // namespace FluidSurface
