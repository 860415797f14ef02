// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/exceptions.h>

#include <fluid_surface/linear_algebra/single_precision_lu.h>

#include <Epetra_MpiComm.h>
#include <mpi.h>
#include <smumps_c.h>

#include <string>

namespace FluidSurface
{
  namespace
  {
    /// Calls @p f(global row, global column, value) for the locally owned entries of @p matrix, row by row.
    template <typename Function>
    void
    for_each_entry(const Epetra_CrsMatrix &matrix, const Function &f)
    {
      for (int i = 0; i < matrix.NumMyRows(); ++i)
        {
          int     n       = 0;
          double *entries = nullptr;
          int    *indices = nullptr;
          matrix.ExtractMyRowView(i, n, entries, indices);
          for (int k = 0; k < n; ++k)
            f(matrix.RowMap().GID(i), matrix.ColMap().GID(indices[k]), entries[k]);
        }
    }
  } // namespace

  struct SinglePrecisionLU::Instance
  {
    SMUMPS_STRUC_C data;
  };

  SinglePrecisionLU::SinglePrecisionLU(const Epetra_CrsMatrix &matrix, const int mumps_ordering)
    : mumps(std::make_unique<Instance>())
  {
    const auto &comm          = dynamic_cast<const Epetra_MpiComm &>(matrix.Comm());
    SMUMPS_STRUC_C &data      = mumps->data;
    data.comm_fortran         = static_cast<MUMPS_INT>(MPI_Comm_c2f(comm.GetMpiComm()));
    data.par                  = 1;
    data.sym                  = 0;
    call(-1, "initialization");
    data.icntl[0]  = -1; // no messages: failures are reported through INFOG
    data.icntl[1]  = -1;
    data.icntl[2]  = -1;
    data.icntl[3]  = 0;
    data.icntl[6]  = mumps_ordering; // ICNTL(7)
    data.icntl[13] = 50;             // ICNTL(14): working space +50 % over the analysis' estimate
    data.icntl[17] = 3;              // ICNTL(18): the entries distributed over the processes
    data.icntl[19] = 0;              // ICNTL(20): dense right-hand sides on the first process
    data.icntl[20] = 0;              // ICNTL(21): the solution there too

    const int n = matrix.NumGlobalRows();
    root_map    = std::make_unique<Epetra_Map>(n, comm.MyPID() == 0 ? n : 0, 0, comm);
    to_root     = std::make_unique<Epetra_Import>(*root_map, matrix.RowMap());
  }

  SinglePrecisionLU::~SinglePrecisionLU()
  {
    mumps->data.job = -2;
    smumps_c(&mumps->data);
  }

  void
  SinglePrecisionLU::call(const int job, const char *phase)
  {
    mumps->data.job = job;
    smumps_c(&mumps->data);
    check(phase);
  }

  void
  SinglePrecisionLU::check(const char *phase) const
  {
    const int error = mumps->data.infog[0];
    if (error >= 0)
      return;
    const char *meaning = error == -10                ? " (the matrix is numerically singular)" :
                          error == -8 || error == -9  ? " (working space too small)" :
                          error == -13 || error == -19 ? " (out of memory)" :
                                                        "";
    AssertThrow(false,
                dealii::ExcMessage(std::string("MUMPS (single precision) failed in its ") + phase +
                                   " with INFOG(1) = " + std::to_string(error) + meaning +
                                   ", INFOG(2) = " + std::to_string(mumps->data.infog[1])));
  }

  void
  SinglePrecisionLU::analyse(const Epetra_CrsMatrix &matrix)
  {
    rows.clear();
    cols.clear();
    for_each_entry(matrix, [&](const int row, const int column, const double) {
      rows.push_back(row + 1);
      cols.push_back(column + 1);
    });
    values.resize(rows.size());
    SMUMPS_STRUC_C &data = mumps->data;
    data.n               = matrix.NumGlobalRows();
    data.nnz_loc         = static_cast<MUMPS_INT8>(rows.size());
    data.irn_loc         = rows.data();
    data.jcn_loc         = cols.data();
    data.a_loc           = values.data();
    call(1, "analysis");
  }

  void
  SinglePrecisionLU::factorize(const Epetra_CrsMatrix &matrix)
  {
    std::size_t position = 0;
    for_each_entry(matrix, [&](const int, const int, const double value) {
      if (position < values.size())
        values[position] = static_cast<float>(value);
      ++position;
    });
    AssertThrow(position == values.size(), dealii::ExcMessage("The matrix is not of the analysed pattern."));
    SMUMPS_STRUC_C &data = mumps->data;
    data.a_loc           = values.data();
    // Working space short of the analysis' estimate (INFOG(1) = −8, −9): more, and again.
    for (int attempt = 0;; ++attempt)
      {
        data.job = 2;
        smumps_c(&data);
        if ((data.infog[0] == -8 || data.infog[0] == -9) && attempt < 3)
          data.icntl[13] *= 2;
        else
          break;
      }
    check("numeric factorization");
  }

  void
  SinglePrecisionLU::solve(Epetra_MultiVector &columns)
  {
    const int          n_columns = columns.NumVectors();
    Epetra_MultiVector root(*root_map, n_columns);
    root.Import(columns, *to_root, Insert);
    const int n_rows = root.MyLength();
    root_columns.resize(static_cast<std::size_t>(n_rows) * n_columns);
    for (int k = 0; k < n_columns; ++k)
      for (int i = 0; i < n_rows; ++i)
        root_columns[static_cast<std::size_t>(k) * n_rows + i] = static_cast<float>(root[k][i]);
    SMUMPS_STRUC_C &data = mumps->data;
    data.nrhs            = n_columns;
    data.lrhs            = mumps->data.n;
    data.rhs             = root_columns.data();
    call(3, "solve phase");
    for (int k = 0; k < n_columns; ++k)
      for (int i = 0; i < n_rows; ++i)
        root[k][i] = root_columns[static_cast<std::size_t>(k) * n_rows + i];
    columns.Export(root, *to_root, Insert);
  }
} // namespace FluidSurface
