// SPDX-License-Identifier: LGPL-2.1-or-later
// Runs one fixed-surface problem: `surface_stokes_driver [section/entry=value ...]` with the
// defaults of every component, prints one `key: value` line per result (for run.sh).
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <fluid_surface/io/output_writer.h>
#include <fluid_surface/scenes/simulation.h>
#include <fluid_surface/io/statistics_file.h>
#include <fluid_surface/scenes/fixed_surface_scene.h>
#include <fluid_surface/geometry/surface_geometry.h>

#include <cstdio>
#include <iostream>
#include <string>

using namespace FluidSurface;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv);
  const MPI_Comm                           comm = MPI_COMM_WORLD;
  dealii::ParameterHandler                 prm;
  Simulation::declare_parameters(prm); // every component's entries, each declared once
  bool verbose = false;
  for (int a = 1; a < argc; ++a)
    {
      const std::string arg = argv[a];
      if (arg == "-v")
        {
          verbose = true;
          continue;
        }
      const auto eq = arg.find('='), slash = arg.rfind('/', eq);
      prm.enter_subsection(arg.substr(0, slash));
      prm.set(arg.substr(slash + 1, eq - slash - 1), arg.substr(eq + 1));
      prm.leave_subsection();
    }
  SurfaceGeometry                  geometry(comm);
  OutputWriter                     output;
  StatisticsFile                   statistics;
  const dealii::ConditionalOStream pcout(std::cout, verbose && dealii::Utilities::MPI::this_mpi_process(comm) == 0);
  FixedSurfaceScene                scene(geometry, output, statistics, pcout);
  geometry.parse_parameters(prm);
  output.parse_parameters(prm);
  scene.parse_parameters(prm);
  output.prepare_directory(comm, false);
  geometry.create();
  statistics.open(output.directory() + "statistics", dealii::Utilities::MPI::this_mpi_process(comm));
  scene.run();
  const FixedSurfaceScene::Results &r = scene.results();
  const double area = geometry.measure().area;
  if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
    std::printf("area: %.15f\n", area);
  if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
    std::printf("dofs: %llu\nvelocity: %.6e\ntangential: %.6e\ngradient: %.6e\npressure: %.6e\nnormal: %.6e\n"
                "energy change: %.6e\nmeasured rate: %.10f\nexact rate: %.10f\nsteps: %u\ntotal iterations: %u\n"
                "max iterations: %u\nfactorizations: %u\nassemble time: %.4f\nsolve time: %.4f\nwall time: %.4f\n",
                (unsigned long long)r.n_dofs, r.errors.velocity, r.errors.tangential, r.errors.gradient,
                r.errors.pressure, r.errors.normal_velocity, r.energy_change, r.measured_decay_rate,
                r.exact_decay_rate, r.steps, r.total_iterations, r.max_iterations, r.factorizations,
                r.assemble_time, r.solve_time, r.wall_time);
  return 0;
}
