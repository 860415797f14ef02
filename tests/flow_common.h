// SPDX-License-Identifier: LGPL-2.1-or-later
// Shared by the flow_* tests: runs one fixed-surface problem with prm overrides and prints numbers
// in the form "m.mm x 10^e" so that numdiff (abs 1e-6 / rel 1e-8) checks three significant digits
// of small quantities too.
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <fluid_surface/io/output_writer.h>
#include <fluid_surface/scenes/simulation.h>
#include <fluid_surface/io/statistics_file.h>
#include <fluid_surface/scenes/fixed_surface_scene.h>
#include <fluid_surface/geometry/surface_geometry.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "parameter_overrides.h"

namespace FlowTest
{
  using FluidSurface::Overrides;

  inline FluidSurface::FixedSurfaceScene::Results
  run(const Overrides &overrides)
  {
    using namespace FluidSurface;
    dealii::ParameterHandler prm;
    Simulation::declare_parameters(prm);
    Overrides all = {{"output/write vtu", "false"},
                     {"output/output directory", "flow_test_results"},
                     {"output/overwrite", "true"}};
    all.insert(all.end(), overrides.begin(), overrides.end());
    FluidSurface::set_overrides(prm, all);
    const MPI_Comm    comm = MPI_COMM_WORLD;
    SurfaceGeometry                  geometry(comm);
    OutputWriter                     output;
    StatisticsFile                   statistics;
    const dealii::ConditionalOStream silent(std::cout, false);
    FixedSurfaceScene                scene(geometry, output, statistics, silent);
    geometry.parse_parameters(prm);
    output.parse_parameters(prm);
    scene.parse_parameters(prm);
    output.prepare_directory(comm, false);
    geometry.create();
    statistics.open(output.directory() + "statistics", dealii::Utilities::MPI::this_mpi_process(comm));
    scene.run();
    return scene.results();
  }

  /// "6.02 x 10^-4": mantissa and exponent are compared separately by numdiff.
  inline std::string
  scientific(const double value)
  {
    if (value == 0)
      return "0";
    int    exponent = static_cast<int>(std::floor(std::log10(std::abs(value))));
    double mantissa = value / std::pow(10.0, exponent);
    if (std::abs(std::round(mantissa * 100) / 100) >= 10)
      mantissa /= 10, ++exponent;
    char buffer[64];
    std::snprintf(buffer, sizeof(buffer), "%.2f x 10^%d", mantissa, exponent);
    return buffer;
  }

  inline bool
  is_root()
  {
    return dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  }
} // namespace FlowTest
