// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/exceptions.h>

#include <fluid_surface/linear_algebra/amesos_factorization.h>
#include <fluid_surface/linear_algebra/single_precision_lu.h>

#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Amesos_Mumps.h>
#include <Epetra_Comm.h>
#include <Epetra_CrsMatrix.h>
#include <Epetra_LinearProblem.h>
#include <Epetra_Map.h>
#include <Epetra_MpiComm.h>
#include <Teuchos_ParameterList.hpp>

#include <optional>

namespace FluidSurface
{
  using namespace dealii;

  namespace
  {
    /// Amesos_Mumps passes CNTL(1..5) only; the block-low-rank threshold CNTL(7) is set on MUMPS' own
    /// structure after the analysis (MUMPS reads it in the numeric factorization).
    class MumpsSolver : public Amesos_Mumps
    {
    public:
      using Amesos_Mumps::Amesos_Mumps;
      void
      set_cntl(const int position, const double value)
      {
        MDS.cntl[position - 1] = value;
      }

      /// Solves in place for the @p n_columns columns of @p columns (column-major, leading dimension
      /// @p n_rows) in one MUMPS solve phase; one process only. Returns MUMPS' INFO(1).
      int
      solve_columns(double *columns, const int n_rows, const int n_columns)
      {
        MDS.job  = 3;
        MDS.nrhs = n_columns;
        MDS.lrhs = n_rows;
        MDS.rhs  = columns;
        dmumps_c(&MDS);
        MDS.nrhs = 1;
        return MDS.info[0];
      }
    };

    /// A hash of the global (row, column) pairs of the locally owned rows of @p matrix.
    std::uint64_t
    hash_pattern(const Epetra_CrsMatrix &matrix)
    {
      std::uint64_t  hash = 1469598103934665603ull;
      const auto     mix  = [&hash](const long long value) {
        hash ^= static_cast<std::uint64_t>(value);
        hash *= 1099511628211ull;
      };
      const Epetra_BlockMap &rows = matrix.RowMap(), &columns = matrix.ColMap();
      for (int i = 0; i < matrix.NumMyRows(); ++i)
        {
          int  n       = 0;
          int *indices = nullptr;
          matrix.Graph().ExtractMyRowView(i, n, indices);
          mix(-1 - rows.GID64(i));
          for (int k = 0; k < n; ++k)
            mix(columns.GID64(indices[k]));
        }
      return hash;
    }
  } // namespace

  AmesosFactorization::AmesosFactorization(const Options &options)
    : options(options)
  {}

  AmesosFactorization::~AmesosFactorization()
  {
    destroy_solver();
  }

  void
  AmesosFactorization::destroy_solver()
  {
    single.reset();
    if (solver)
      {
        if (!placeholder)
          {
            empty_map   = std::make_unique<Epetra_Map>(0, 0, *comm);
            placeholder = std::make_unique<Epetra_CrsMatrix>(Copy, *empty_map, 0);
            placeholder->FillComplete();
          }
        problem->SetOperator(placeholder.get());
        solver.reset();
      }
    problem.reset();
    analysed   = nullptr;
    factorized = false;
  }

  bool
  AmesosFactorization::analysis_fits(const Epetra_CrsMatrix &matrix, const std::uint64_t pattern_hash) const
  {
    const bool fits_here = (solver || single) && analysed == &matrix && analysed_hash == pattern_hash;
    const auto &mpi_comm = dynamic_cast<const Epetra_MpiComm &>(matrix.Comm());
    return dealii::Utilities::MPI::min(fits_here ? 1 : 0, mpi_comm.GetMpiComm()) == 1;
  }

  void
  AmesosFactorization::analyse(const Epetra_CrsMatrix &epetra)
  {
    if (options.single_precision)
      {
        single = std::make_unique<SinglePrecisionLU>(epetra, options.mumps_ordering);
        single->analyse(epetra);
        return;
      }
    comm.reset(epetra.Comm().Clone());
    placeholder.reset();
    empty_map.reset();
    problem = std::make_unique<Epetra_LinearProblem>();
    problem->SetOperator(const_cast<Epetra_CrsMatrix *>(&epetra));
    Teuchos::ParameterList parameters;
    if (options.package == "Amesos_Mumps")
      {
        solver = std::make_unique<MumpsSolver>(*problem);
        Teuchos::ParameterList &mumps = parameters.sublist("mumps");
        mumps.set("ICNTL(7)", options.mumps_ordering);
        if (options.low_rank_tolerance > 0)
          mumps.set("ICNTL(35)", 2);
      }
    else
      {
        Amesos factory;
        AssertThrow(factory.Query(options.package.c_str()),
                    ExcMessage("The Amesos package " + options.package + " is not available."));
        solver.reset(factory.Create(options.package.c_str(), *problem));
      }
    solver->SetParameters(parameters);
    const int ierr = solver->SymbolicFactorization();
    if (ierr != 0)
      {
        destroy_solver();
        AssertThrow(false, ExcTrilinosError(ierr));
      }
    if (auto *mumps = dynamic_cast<MumpsSolver *>(solver.get()); mumps && options.low_rank_tolerance > 0)
      mumps->set_cntl(7, options.low_rank_tolerance);
  }

  void
  AmesosFactorization::factorize(const TrilinosWrappers::SparseMatrix &matrix, TimerOutput *timer)
  {
    const Epetra_CrsMatrix &epetra = matrix.trilinos_matrix();
    const std::uint64_t     hash   = hash_pattern(epetra);
    factorized                     = false;
    if (!analysis_fits(epetra, hash))
      {
        std::optional<TimerOutput::Scope> section;
        if (timer)
          section.emplace(*timer, "symbolic factorization");
        destroy_solver();
        analyse(epetra);
        analysed      = &epetra;
        analysed_hash = hash;
        ++symbolic_count;
      }
    if (single)
      single->factorize(epetra);
    else
      {
        const int ierr = solver->NumericFactorization();
        AssertThrow(ierr == 0, ExcTrilinosError(ierr));
      }
    factorized = true;
    ++numeric_count;
  }

  void
  AmesosFactorization::solve(TrilinosWrappers::MPI::Vector &dst, const TrilinosWrappers::MPI::Vector &src)
  {
    Assert(factorized, ExcNotInitialized());
    if (single)
      {
        dst = src;
        single->solve(dst.trilinos_vector());
        return;
      }
    problem->SetLHS(&dst.trilinos_vector());
    problem->SetRHS(const_cast<Epetra_MultiVector *>(static_cast<const Epetra_MultiVector *>(&src.trilinos_vector())));
    const int ierr = solver->Solve();
    AssertThrow(ierr == 0, ExcTrilinosError(ierr));
  }

  void
  AmesosFactorization::solve(std::vector<TrilinosWrappers::MPI::Vector>        &dst,
                             const std::vector<const TrilinosWrappers::MPI::Vector *> &src,
                             const ChangeOfVariables                          *change)
  {
    Assert(factorized, ExcNotInitialized());
    const unsigned int n_columns = src.size();
    dst.resize(n_columns);
    for (unsigned int k = 0; k < n_columns; ++k)
      {
        dst[k].reinit(*src[k], true);
        dst[k] = *src[k];
        if (change != nullptr)
          (*change)(dst[k], true);
      }
    auto *mumps = dynamic_cast<MumpsSolver *>(solver.get());
    if (single && n_columns > 0)
      {
        Epetra_MultiVector columns(dst[0].trilinos_vector().Map(), n_columns);
        for (unsigned int k = 0; k < n_columns; ++k)
          std::copy(dst[k].begin(), dst[k].end(), columns[k]);
        single->solve(columns);
        for (unsigned int k = 0; k < n_columns; ++k)
          std::copy(columns[k], columns[k] + columns.MyLength(), dst[k].begin());
      }
    else if (mumps == nullptr || comm->NumProc() != 1 || n_columns < 2)
      for (auto &column : dst)
        {
          const TrilinosWrappers::MPI::Vector right_hand_side(column);
          solve(column, right_hand_side);
        }
    else
      {
        // MUMPS' solve phase for all columns at once (Amesos_Mumps::Solve loops over them): the forward and
        // backward substitutions become matrix-matrix products.
        const int           n_rows = dst[0].locally_owned_size();
        std::vector<double> columns(static_cast<std::size_t>(n_rows) * n_columns);
        for (unsigned int k = 0; k < n_columns; ++k)
          std::copy(dst[k].begin(), dst[k].end(), columns.begin() + static_cast<std::size_t>(k) * n_rows);
        const int info = mumps->solve_columns(columns.data(), n_rows, n_columns);
        AssertThrow(info == 0, ExcMessage("MUMPS' solve phase failed with INFO(1) = " + std::to_string(info)));
        for (unsigned int k = 0; k < n_columns; ++k)
          std::copy(columns.begin() + static_cast<std::size_t>(k) * n_rows,
                    columns.begin() + static_cast<std::size_t>(k + 1) * n_rows,
                    dst[k].begin());
      }
    if (change != nullptr)
      for (auto &column : dst)
        (*change)(column, false);
  }

  void
  AmesosFactorization::solve(TrilinosWrappers::MPI::Vector       &dst,
                             const TrilinosWrappers::MPI::Vector &src,
                             const ChangeOfVariables             *change)
  {
    if (change == nullptr)
      {
        solve(dst, src);
        return;
      }
    TrilinosWrappers::MPI::Vector transformed(src);
    (*change)(transformed, true);
    solve(dst, transformed);
    (*change)(dst, false);
  }
} // namespace FluidSurface
