// SPDX-License-Identifier: LGPL-2.1-or-later
// StepSystem::distribute_local_to_global() adds a cell's couplings in place, at positions listed once per mesh in
// the matrix's compressed rows, instead of through AffineConstraints and Epetra's global-index lookups (issue 50).
// The same local systems (every coupled entry nonzero, values from the cell's centre and the local indices, the
// right-hand side, the volume column and the twelve rigid-motion vectors) are added once through the
// AffineConstraints path and once in place (every third cell still through the old path, so that the two mix as
// they do for cells with constrained DoFs); the two matrices and all vectors must agree bit for bit. On two ranks
// the rows of the other rank go through the matrix's and vectors' add(). The spheroid 1 : 1 : 2, refinement 2.
#include <deal.II/base/mpi.h>

#include <fluid_surface/geometry/surface_geometry.h>
#include <fluid_surface/model/local_system.h>
#include <fluid_surface/model/step_system.h>
#include <fluid_surface/scenes/simulation.h>

#include "parameter_overrides.h"

#include <cmath>
#include <cstdio>

using namespace FluidSurface;
using namespace dealii;

namespace
{
  /// Adds every locally owned cell's local system; the cells with @p old_path(n) true (n counts the owned cells)
  /// through AffineConstraints (no cell index).
  template <typename Predicate>
  void
  add_cells(StepSystem &system, const Predicate &old_path)
  {
    const auto  &fe      = system.fe();
    const auto   n_local = fe.n_dofs_per_cell();
    LocalSystem  local;
    unsigned int n = 0;
    system.zero();
    for (const auto &cell : system.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          local.reinit(n_local, true);
          cell->get_dof_indices(local.indices);
          local.cell_index = old_path(n++) ? numbers::invalid_unsigned_int : cell->active_cell_index();
          const Point<3> c = cell->center();
          const double   s = 3 * c[0] + 5 * c[1] + 7 * c[2];
          for (unsigned int i = 0; i < n_local; ++i)
            {
              for (unsigned int j = 0; j < n_local; ++j)
                if (StepSystem::couples(fe.system_to_component_index(i).first, fe.system_to_component_index(j).first))
                  local.matrix(i, j) = 2 + std::sin(1 + 0.37 * i + 1.1 * j + s);
              local.rhs(i)           = std::cos(0.3 * i + s);
              local.volume_column(i) = std::sin(0.7 * i - s);
              for (unsigned int k = 0; k < 6; ++k)
                {
                  local.rigid_columns[k](i) = std::cos(k + 0.11 * i + s);
                  local.rigid_rows[k](i)    = std::sin(k - 0.13 * i + s);
                }
            }
          system.distribute_local_to_global(local, true);
        }
    system.compress(true);
  }

  /// The number of entries of @p a and @p b (same pattern) that differ, over all ranks.
  unsigned int
  differing_entries(const TrilinosWrappers::SparseMatrix &a, const TrilinosWrappers::SparseMatrix &b)
  {
    unsigned int n = 0;
    for (const auto row : a.locally_owned_range_indices())
      for (auto entry = a.begin(row); entry != a.end(row); ++entry)
        n += entry->value() != b.el(row, entry->column());
    return Utilities::MPI::sum(n, MPI_COMM_WORLD);
  }

  /// The number of entries of @p a and @p b that differ, over all ranks.
  unsigned int
  differing_entries(const VectorType &a, const VectorType &b)
  {
    unsigned int n = 0;
    for (const auto i : a.locally_owned_elements())
      n += a[i] != b[i];
    return Utilities::MPI::sum(n, MPI_COMM_WORLD);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                       root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  ParameterHandler                 prm;
  Simulation::declare_parameters(prm);
  set_overrides(prm, {{"geometry/shape", "ellipsoid"}, {"geometry/semi-axes", "1, 1, 2"}, {"geometry/refinement", "2"}});
  SurfaceGeometry geometry(MPI_COMM_WORLD);
  geometry.parse_parameters(prm);
  geometry.create();
  StepSystem system(geometry);
  system.setup_system();

  add_cells(system, [](const unsigned int) { return true; });
  TrilinosWrappers::SparseMatrix matrix;
  matrix.copy_from(system.matrix());
  std::vector<VectorType> vectors{system.rhs(), system.volume_column()};
  for (unsigned int k = 0; k < 6; ++k)
    {
      vectors.push_back(system.rigid_columns()[k]);
      vectors.push_back(system.rigid_rows()[k]);
    }

  add_cells(system, [](const unsigned int n) { return n % 3 == 0; });
  std::vector<const VectorType *> in_place{&system.rhs(), &system.volume_column()};
  for (unsigned int k = 0; k < 6; ++k)
    {
      in_place.push_back(&system.rigid_columns()[k]);
      in_place.push_back(&system.rigid_rows()[k]);
    }
  unsigned int differing_vector_entries = 0;
  for (unsigned int v = 0; v < vectors.size(); ++v)
    differing_vector_entries += differing_entries(vectors[v], *in_place[v]);
  const unsigned int differing_matrix_entries = differing_entries(matrix, system.matrix());
  const double       frobenius                = system.matrix().frobenius_norm();
  const double       rhs_norm                 = system.rhs().l2_norm();
  if (root)
    {
      std::printf("unknowns %u, stored matrix entries %u\n",
                  static_cast<unsigned int>(system.dof_handler().n_dofs()),
                  static_cast<unsigned int>(system.matrix().n_nonzero_elements()));
      std::printf("cells added in place: %s\n", system.inserts_in_place() ? "yes" : "no");
      std::printf("matrix entries differing from the AffineConstraints path: %u\n", differing_matrix_entries);
      std::printf("vector entries differing (right-hand side, volume column, rigid columns and rows): %u\n",
                  differing_vector_entries);
      std::printf("|A|_F %.8e, |b| %.8e\n", frobenius, rhs_norm);
    }
}
