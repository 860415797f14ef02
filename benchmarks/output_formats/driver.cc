// SPDX-License-Identifier: LGPL-2.1-or-later
// Writes one surface N times through OutputWriter::write and prints the wall time of each write and the
// bytes on disk of each output step:
//   output_formats_driver WRITES [section/entry=value ...]
// The surface is the one `subsection geometry` describes (after the overrides); the fields stand in for those of
// scene full, component for component (14): H and ν (written by OutputWriter itself), a 3-vector "velocity"
// (the curvature vector), 3 scalars (the nodal H, H, H as "pressure", "curvature_kappa", "bending_scalar"), the
// position as "new_position" and the speed |velocity|, all on the Q_k position space.
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <fluid_surface/geometry/surface_geometry.h>
#include <fluid_surface/io/output_writer.h>
#include <fluid_surface/postprocess/speed_postprocessor.h>
#include <fluid_surface/scenes/simulation.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "parameter_overrides.h"

using namespace FluidSurface;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                           comm = MPI_COMM_WORLD;
  const bool                               root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
  dealii::ParameterHandler                 prm;
  Simulation::declare_parameters(prm);
  const unsigned int writes = std::stoul(argv[1]);
  Overrides          overrides;
  for (int a = 2; a < argc; ++a)
    {
      const std::string arg = argv[a];
      overrides.emplace_back(arg.substr(0, arg.find('=')), arg.substr(arg.find('=') + 1));
    }
  set_overrides(prm, overrides);
  SurfaceGeometry geometry(comm);
  OutputWriter    output;
  geometry.parse_parameters(prm);
  output.parse_parameters(prm);
  output.prepare_directory(comm, false);
  geometry.create();

  const SpeedPostprocessor speed;
  const auto               add_fields = [&](dealii::DataOut<2, 3> &data_out) {
    using Interpretation = dealii::DataComponentInterpretation::DataComponentInterpretation;
    const std::vector<Interpretation> vector3(3, dealii::DataComponentInterpretation::component_is_part_of_vector);
    data_out.add_data_vector(geometry.curvature_vector(), std::vector<std::string>(3, "velocity"),
                             dealii::DataOut<2, 3>::type_dof_data, vector3);
    data_out.add_data_vector(geometry.mean_curvature_nodes(),
                             std::vector<std::string>{"pressure", "curvature_kappa", "bending_scalar"},
                             dealii::DataOut<2, 3>::type_dof_data,
                             std::vector<Interpretation>(3, dealii::DataComponentInterpretation::component_is_scalar));
    data_out.add_data_vector(geometry.position(), std::vector<std::string>(3, "new_position"),
                             dealii::DataOut<2, 3>::type_dof_data, vector3);
    data_out.add_data_vector(geometry.curvature_vector(), speed);
  };

  if (root)
    std::printf("cells: %u\n", geometry.triangulation().n_global_active_cells());
  for (unsigned int i = 0; i < writes; ++i)
    {
      MPI_Barrier(comm);
      dealii::Timer timer;
      output.write(geometry, 0.1 * i, add_fields);
      MPI_Barrier(comm);
      timer.stop();
      if (root)
        std::printf("write %u: %.6f s\n", i, timer.wall_time());
    }
  if (root)
    for (const auto &file : std::filesystem::directory_iterator(output.directory()))
      if (file.is_regular_file())
        std::printf("file %s: %llu bytes\n", file.path().filename().c_str(),
                    static_cast<unsigned long long>(file.file_size()));
}
