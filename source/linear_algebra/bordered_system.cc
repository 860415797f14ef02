// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/array_view.h>

#include <fluid_surface/linear_algebra/bordered_system.h>

namespace FluidSurface
{
  using namespace dealii;

  BorderedSystem::BorderedSystem(const TrilinosWrappers::SparseMatrix &matrix,
                                 const std::vector<const Vector *>     &columns,
                                 const std::vector<const Vector *>     &rows)
    : matrix(matrix)
    , columns(columns)
    , rows(rows)
  {
    AssertDimension(matrix.m(), matrix.n());
    AssertDimension(columns.size(), rows.size());
    Assert(columns.size() < matrix.m(), ExcMessage("more constraints than unknowns"));
    for (unsigned int k = 0; k < columns.size(); ++k)
      {
        Assert(columns[k] != nullptr && rows[k] != nullptr, ExcInternalError());
        AssertDimension(columns[k]->size(), matrix.m());
        AssertDimension(rows[k]->size(), matrix.n());
        Assert(columns[k]->locally_owned_elements() == matrix.locally_owned_range_indices(),
               ExcMessage("a column of the bordered system is not partitioned like the rows of the matrix"));
        Assert(rows[k]->locally_owned_elements() == matrix.locally_owned_range_indices(),
               ExcMessage("a row of the bordered system is not partitioned like the rows of the matrix"));
      }
  }

  BorderedSystem::BlockVector
  BorderedSystem::make_vector(const Vector &state) const
  {
    AssertDimension(state.size(), matrix.n());
    const MPI_Comm comm = state.get_mpi_communicator();
    IndexSet       owned_multipliers(columns.size());
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      owned_multipliers.add_range(0, columns.size());
    BlockVector v;
    v.reinit(std::vector<IndexSet>{state.locally_owned_elements(), owned_multipliers}, comm);
    return v;
  }

  std::vector<double>
  BorderedSystem::multipliers(const BlockVector &v)
  {
    AssertDimension(v.n_blocks(), 2);
    std::vector<double> values(v.block(1).size(), 0.0);
    for (const auto i : v.block(1).locally_owned_elements())
      values[i] = v.block(1)(i);
    std::vector<double> sums(values.size());
    Utilities::MPI::sum(ArrayView<const double>(values), v.block(1).get_mpi_communicator(), ArrayView<double>(sums));
    return sums;
  }

  void
  BorderedSystem::set_multipliers(BlockVector &v, const std::vector<double> &values)
  {
    AssertDimension(v.n_blocks(), 2);
    AssertDimension(values.size(), v.block(1).size());
    for (const auto i : v.block(1).locally_owned_elements())
      v.block(1)(i) = values[i];
    v.block(1).compress(VectorOperation::insert);
  }

  std::vector<double>
  BorderedSystem::constraint_values(const Vector &x) const
  {
    AssertDimension(x.size(), matrix.n());
    std::vector<double> values(rows.size());
    for (unsigned int j = 0; j < rows.size(); ++j)
      values[j] = (*rows[j]) * x;
    return values;
  }

  void
  BorderedSystem::vmult(BlockVector &dst, const BlockVector &src) const
  {
    AssertDimension(src.n_blocks(), 2);
    AssertDimension(src.block(1).size(), columns.size());
    AssertDimension(dst.block(1).size(), rows.size());
    matrix.vmult(dst.block(0), src.block(0));
    const std::vector<double> mu = multipliers(src);
    for (unsigned int k = 0; k < columns.size(); ++k)
      dst.block(0).add(mu[k], *columns[k]);
    set_multipliers(dst, constraint_values(src.block(0)));
  }

  BorderedFactorizationPreconditioner::BorderedFactorizationPreconditioner(const BorderedSystem &system,
                                                                           KeptColumns          *kept)
    : system(system)
    , kept(kept)
  {}

  void
  BorderedFactorizationPreconditioner::initialize(AmesosFactorization                          &factors,
                                                  const AmesosFactorization::ChangeOfVariables *change_of_variables)
  {
    factorization      = &factors;
    change             = change_of_variables;
    const unsigned int n = system.columns.size();
    schur_inverse.reinit(n, n);
    if (kept != nullptr && kept->valid && kept->factors == factors.n_numeric_factorizations() && kept->z.size() == n)
      z = kept->z;
    else
      {
        factorization->solve(z, system.columns, change);
        if (kept != nullptr)
          *kept = {z, factors.n_numeric_factorizations(), true};
      }
    for (unsigned int j = 0; j < n; ++j)
      for (unsigned int k = 0; k < n; ++k)
        schur_inverse(j, k) = (*system.rows[j]) * z[k];
    if (n > 0)
      schur_inverse.gauss_jordan();
  }

  std::vector<double>
  BorderedFactorizationPreconditioner::schur_solve(const BorderedSystem::Vector &x,
                                                   const std::vector<double>    &g) const
  {
    const unsigned int n = z.size();
    Assert(factorization != nullptr, ExcNotInitialized());
    AssertDimension(g.size(), n);
    std::vector<double> residual = system.constraint_values(x), mu(n, 0.0);
    for (unsigned int j = 0; j < n; ++j)
      residual[j] -= g[j];
    for (unsigned int j = 0; j < n; ++j)
      for (unsigned int k = 0; k < n; ++k)
        mu[j] += schur_inverse(j, k) * residual[k];
    return mu;
  }

  void
  BorderedFactorizationPreconditioner::vmult(BorderedSystem::BlockVector       &dst,
                                             const BorderedSystem::BlockVector &src) const
  {
    Assert(factorization != nullptr, ExcNotInitialized());
    factorization->solve(dst.block(0), src.block(0), change);
    const std::vector<double> mu = schur_solve(dst.block(0), BorderedSystem::multipliers(src));
    for (unsigned int k = 0; k < z.size(); ++k)
      dst.block(0).add(-mu[k], z[k]);
    BorderedSystem::set_multipliers(dst, mu);
  }

  void
  BorderedFactorizationPreconditioner::enforce_constraints(BorderedSystem::BlockVector &v,
                                                           const std::vector<double>   &g) const
  {
    const std::vector<double> correction = schur_solve(v.block(0), g);
    std::vector<double>       mu         = BorderedSystem::multipliers(v);
    for (unsigned int k = 0; k < z.size(); ++k)
      {
        v.block(0).add(-correction[k], z[k]);
        mu[k] += correction[k];
      }
    BorderedSystem::set_multipliers(v, mu);
  }
} // namespace FluidSurface
