#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <fluid_surface/io/checkpoint.h>
#include <fluid_surface/io/output_writer.h>
#include <fluid_surface/io/parameter_file.h>

#include <filesystem>
#include <fstream>

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
  } // namespace

  void
  OutputWriter::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("output");
    prm.declare_entry("output directory",
                      "results",
                      Patterns::DirectoryName(),
                      "Directory for solution-NNNNN.vtu, solution.pvd, statistics, summary, "
                      "used_parameters.prm and checkpoints. Never name it `output`.");
    prm.declare_entry("output interval",
                      "0",
                      RealRange::at_least(0),
                      "Time Δt_out ≥ 0 between two VTU files; 0 writes every step.");
    prm.declare_entry("write vtu", "true", Patterns::Bool(), "Write solution-NNNNN.vtu and solution.pvd.");
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
          error = parameter_file_name() + ": entry 'output/output directory' = '" + parameters.output_directory +
                  "' holds the results of another run (statistics); expected a new directory, "
                  "or 'overwrite = true' in subsection output, or a resumed run.";
        else
          {
            fs::create_directories(directory() + "checkpoint", ec);
            if (ec)
              error = parameter_file_name() + ": entry 'output/output directory' = '" + parameters.output_directory +
                      "': cannot create it (" + ec.message() + ").";
          }
      }
    error = Utilities::MPI::broadcast(communicator, error, 0);
    if (!error.empty())
      throw InputError(error);
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

    const std::string name = "solution-" + Utilities::int_to_string(times_and_names.size(), 5) + ".vtu";
    data_out.write_vtu_in_parallel(directory() + name, geometry.get_communicator());
    times_and_names.emplace_back(time, name);
    last_output_time = time;
    if (Utilities::MPI::this_mpi_process(geometry.get_communicator()) == 0)
      write_pvd_file();
  }

  void
  OutputWriter::write_pvd_file() const
  {
    // Written beside and renamed, so that a killed run never leaves a truncated solution.pvd.
    const std::string pvd = directory() + "solution.pvd";
    {
      std::ofstream out(pvd + ".tmp");
      DataOutBase::write_pvd_record(out, times_and_names);
    }
    std::filesystem::rename(pvd + ".tmp", pvd);
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
    if (parameters.write_vtu && Utilities::MPI::this_mpi_process(communicator) == 0)
      write_pvd_file();
  }
} // namespace FluidSurface
