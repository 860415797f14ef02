// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef fluid_surface_model_local_system_h
#define fluid_surface_model_local_system_h

#include <deal.II/base/types.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <vector>

namespace FluidSurface
{
  /**
   * One cell's contribution to the step system of scene full: the matrix and right-hand side, the volume
   * column (ñ, v), and the six rigid-motion columns and constraint rows (when the momentum constraints are
   * active), in the cell's local DoF numbering.
   */
  struct LocalSystem
  {
    /// Zeroes everything for a cell with @p dofs_per_cell DoFs (the rigid motions only if @p rigid_motions).
    void
    reinit(const unsigned int dofs_per_cell, const bool rigid_motions)
    {
      matrix.reinit(dofs_per_cell, dofs_per_cell);
      rhs.reinit(dofs_per_cell);
      volume_column.reinit(dofs_per_cell);
      if (rigid_motions)
        for (unsigned int k = 0; k < 6; ++k)
          {
            rigid_columns[k].reinit(dofs_per_cell);
            rigid_rows[k].reinit(dofs_per_cell);
          }
      indices.resize(dofs_per_cell);
    }

    dealii::FullMatrix<double>                   matrix;
    dealii::Vector<double>                       rhs;
    dealii::Vector<double>                       volume_column; ///< (ñ, v)
    std::array<dealii::Vector<double>, 6>        rigid_columns; ///< (r_k, v), r = e_d, e_d × x
    std::array<dealii::Vector<double>, 6>        rigid_rows;    ///< the constraint rows of the momenta
    std::vector<dealii::types::global_dof_index> indices;
  };
} // namespace FluidSurface

#endif
