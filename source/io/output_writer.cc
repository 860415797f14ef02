// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <fluid_surface/io/checkpoint.h>
#include <fluid_surface/io/output_writer.h>
#include <fluid_surface/io/parameter_file.h>

#include <boost/archive/text_iarchive.hpp>
#include <boost/archive/text_oarchive.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

namespace FluidSurface
{
  using namespace dealii;

  namespace
  {
    /// The mean curvature H (H = −2/R on a sphere with outward ν) from its nodal field (H, H, H).
    class MeanCurvaturePostprocessor : public DataPostprocessorScalar<3>
    {
    public:
      MeanCurvaturePostprocessor()
        : DataPostprocessorScalar<3>("H", update_values)
      {}
      void
      evaluate_vector_field(const DataPostprocessorInputs::Vector<3> &inputs,
                            std::vector<Vector<double>>              &computed) const override
      {
        for (unsigned int q = 0; q < inputs.solution_values.size(); ++q)
          computed[q](0) = inputs.solution_values[q][0];
      }
    };

    /// Whether @p file (a name in the record of solution files) is a VTU file.
    bool
    is_vtu(const std::pair<double, std::string> &file)
    {
      const std::string &name = file.second;
      return name.size() > 4 && name.compare(name.size() - 4, 4, ".vtu") == 0;
    }
  } // namespace

  void
  OutputWriter::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("output");
    prm.declare_entry("output directory",
                      "results",
                      Patterns::DirectoryName(),
                      "Directory for the solution files (solution-NNNNN.vtu and solution.pvd, or "
                      "solution-NNNNN.h5 and solution.xdmf), statistics, summary, "
                      "used_parameters.prm and checkpoints. Never name it `output`.");
    prm.declare_entry("output interval",
                      "0",
                      RealRange::at_least(0),
                      "Time Δt_out ≥ 0 between two output steps; 0 writes every step.");
    prm.declare_entry("write vtu",
                      "true",
                      Patterns::Bool(),
                      "Write the solution files at all, in the chosen `format` (VTU or HDF5); false writes "
                      "none of them (statistics and summary are written anyway).");
    prm.declare_entry("format",
                      "vtu",
                      Patterns::Selection("vtu|hdf5"),
                      "File format of the output steps: vtu writes solution-NNNNN.vtu (single precision) and "
                      "the time series solution.pvd; hdf5 writes solution-NNNNN.h5 (parallel HDF5, double "
                      "precision, the same fields and curved sub-cells, a vertex shared by cells of one MPI rank "
                      "stored once) and the time series solution.xdmf. ParaView opens either series "
                      "(solution.xdmf with its XDMF reader).");
    prm.declare_entry("subdivisions",
                      "2",
                      Patterns::Integer(1, 8),
                      "Each cell is written as n×n curved sub-cells (n = subdivisions, 1 to 8).");
    prm.declare_entry("screen interval",
                      "10",
                      Patterns::Integer(1),
                      "Report a step on the screen every N ≥ 1 steps (and the last one).");
    prm.declare_entry("report wall time",
                      "true",
                      Patterns::Bool(),
                      "Show wall time per step and ETA on the screen (off in tests: timings are not stable).");
    prm.declare_entry("overwrite",
                      "false",
                      Patterns::Bool(),
                      "Allow a new run to replace the results of another run in the output directory.");
    prm.leave_subsection();
  }

  void
  OutputWriter::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("output");
    parameters.output_directory = prm.get("output directory");
    const std::string &name     = parameters.output_directory;
    if (name.empty() || name == "output" || name == "output/")
      throw_invalid_entry("output/output directory",
                          name,
                          "a directory name other than '' and 'output' (the test harness owns 'output')");
    parameters.output_interval  = prm.get_double("output interval");
    parameters.write_vtu        = prm.get_bool("write vtu");
    parameters.format           = prm.get("format") == "hdf5" ? Format::hdf5 : Format::vtu;
    parameters.subdivisions     = prm.get_integer("subdivisions");
    parameters.overwrite        = prm.get_bool("overwrite");
    parameters.screen_interval  = prm.get_integer("screen interval");
    parameters.report_wall_time = prm.get_bool("report wall time");
    prm.leave_subsection();
  }

  std::string
  OutputWriter::directory() const
  {
    const std::string &name = parameters.output_directory;
    return name.back() == '/' ? name : name + "/";
  }

  void
  OutputWriter::prepare_directory(const MPI_Comm communicator, const bool resuming) const
  {
    std::string error;
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        namespace fs = std::filesystem;
        std::error_code ec;
        if (fs::exists(directory() + "statistics") && !parameters.overwrite && !resuming)
          error = "entry 'output/output directory' = '" + parameters.output_directory +
                  "' holds the results of another run (statistics); expected a new directory, "
                  "or 'overwrite = true' in subsection output, or a resumed run.";
        else
          {
            fs::create_directories(directory() + "checkpoint", ec);
            if (ec)
              error = "entry 'output/output directory' = '" + parameters.output_directory +
                      "': cannot create it (" + ec.message() + ").";
          }
      }
    error = Utilities::MPI::broadcast(communicator, error, 0);
    if (!error.empty())
      throw EntryError(error);
  }

  bool
  OutputWriter::due(const double time) const
  {
    return parameters.write_vtu &&
           (times_and_names.empty() || time >= last_output_time + parameters.output_interval * (1 - 1e-10));
  }

  void
  OutputWriter::write(const SurfaceGeometry                     &geometry,
                      const double                               time,
                      const std::function<void(DataOut<2, 3> &)> &add_fields)
  {
    if (!parameters.write_vtu)
      return;
    DataOut<2, 3> data_out;
    data_out.attach_dof_handler(geometry.dof_handler());
    const MeanCurvaturePostprocessor mean_curvature;
    data_out.add_data_vector(geometry.mean_curvature_nodes(), mean_curvature);
    const std::vector<DataComponentInterpretation::DataComponentInterpretation> vector3(
      3, DataComponentInterpretation::component_is_part_of_vector);
    data_out.add_data_vector(geometry.normal_field(),
                             std::vector<std::string>(3, "normal"),
                             DataOut<2, 3>::type_dof_data,
                             vector3);
    if (add_fields)
      add_fields(data_out);
    data_out.build_patches(geometry.mapping(), parameters.subdivisions, DataOut<2, 3>::curved_inner_cells);

    const MPI_Comm     communicator = geometry.get_communicator();
    const std::string  stem         = "solution-" + Utilities::int_to_string(times_and_names.size(), 5);
    const bool         root         = Utilities::MPI::this_mpi_process(communicator) == 0;
    if (parameters.format == Format::vtu)
      {
        data_out.write_vtu_in_parallel(directory() + stem + ".vtu", communicator);
        times_and_names.emplace_back(time, stem + ".vtu");
        if (root)
          write_pvd_file();
      }
    else
      {
        write_hdf5_file(data_out, stem + ".h5", time, communicator);
        times_and_names.emplace_back(time, stem + ".h5");
        if (root)
          write_xdmf_file();
      }
    last_output_time = time;
  }

  void
  OutputWriter::write_hdf5_file(const DataOut<2, 3> &data_out,
                                const std::string   &name,
                                const double         time,
                                const MPI_Comm       communicator)
  {
    // Merging the vertices that neighbouring patches share is exact here: every field written is continuous
    // (nodal FE fields and postprocessed values of them), so the merged vertices carry equal values.
    DataOutBase::DataOutFilter filter(
      DataOutBase::DataOutFilterFlags(/*filter_duplicate_vertices*/ true, /*xdmf_hdf5_output*/ true));
    data_out.write_filtered_data(filter);
    data_out.write_hdf5_parallel(filter, directory() + name, communicator);
    // The entry names the file relative to the XDMF file beside it, so that the directory can be moved.
    xdmf_entries.push_back(data_out.create_xdmf_entry(filter, name, time, communicator));
  }

  void
  OutputWriter::write_pvd_file() const
  {
    // Written beside and renamed, so that a killed run never leaves a truncated solution.pvd.
    const std::string pvd = directory() + "solution.pvd";
    {
      std::vector<std::pair<double, std::string>> vtu_files;
      std::copy_if(times_and_names.begin(), times_and_names.end(), std::back_inserter(vtu_files), is_vtu);
      std::ofstream out(pvd + ".tmp");
      DataOutBase::write_pvd_record(out, vtu_files);
    }
    std::filesystem::rename(pvd + ".tmp", pvd);
  }

  void
  OutputWriter::write_xdmf_file() const
  {
    // What DataOutInterface::write_xdmf_file() writes, but beside and renamed like solution.pvd, and without
    // the patches it needs for the cell type (all cells here are quadrilaterals), so that load() can call it.
    const std::string xdmf = directory() + "solution.xdmf";
    {
      std::ofstream out(xdmf + ".tmp");
      out << "<?xml version=\"1.0\" ?>\n"
          << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
          << "<Xdmf Version=\"2.0\">\n"
          << "  <Domain>\n"
          << "    <Grid Name=\"CellTime\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
      for (const XDMFEntry &entry : xdmf_entries)
        out << entry.get_xdmf_content(3, ReferenceCells::Quadrilateral);
      out << "    </Grid>\n"
          << "  </Domain>\n"
          << "</Xdmf>\n";
    }
    std::filesystem::rename(xdmf + ".tmp", xdmf);
  }

  void
  OutputWriter::save(CheckpointData &data) const
  {
    data.set("output/last output time", last_output_time);
    data.set("output/files", static_cast<unsigned int>(times_and_names.size()));
    for (unsigned int i = 0; i < times_and_names.size(); ++i)
      {
        data.set("output/file " + std::to_string(i) + " time", times_and_names[i].first);
        data.set("output/file " + std::to_string(i) + " name", times_and_names[i].second);
      }
    for (unsigned int i = 0; i < xdmf_entries.size(); ++i)
      {
        std::ostringstream                 text;
        boost::archive::text_oarchive archive(text, boost::archive::no_header);
        archive << xdmf_entries[i];
        data.set("output/xdmf entry " + std::to_string(i), text.str());
      }
  }

  void
  OutputWriter::load(const CheckpointData &data, const MPI_Comm communicator)
  {
    last_output_time = data.get_double("output/last output time");
    times_and_names.clear();
    const unsigned int n = data.get_unsigned("output/files");
    for (unsigned int i = 0; i < n; ++i)
      times_and_names.emplace_back(data.get_double("output/file " + std::to_string(i) + " time"),
                                   data.get_string("output/file " + std::to_string(i) + " name"));
    xdmf_entries.clear();
    for (unsigned int i = 0; data.has("output/xdmf entry " + std::to_string(i)); ++i)
      {
        std::istringstream            text(data.get_string("output/xdmf entry " + std::to_string(i)));
        boost::archive::text_iarchive archive(text, boost::archive::no_header);
        xdmf_entries.emplace_back();
        archive >> xdmf_entries.back();
      }
    // Each series is cut back to the checkpoint if this run writes it or the checkpointed run wrote into it.
    if (!parameters.write_vtu || Utilities::MPI::this_mpi_process(communicator) != 0)
      return;
    if (parameters.format == Format::vtu || std::any_of(times_and_names.begin(), times_and_names.end(), is_vtu))
      write_pvd_file();
    if (!xdmf_entries.empty() || parameters.format == Format::hdf5)
      write_xdmf_file();
  }
} // namespace FluidSurface
