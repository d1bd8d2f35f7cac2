// ---------------------------------------------------------------------
// PeriDeal: a visit of the locally owned rows of a Trilinos matrix.
// ---------------------------------------------------------------------
#ifndef perideal_coupling_matrix_rows_h
#define perideal_coupling_matrix_rows_h

#include <deal.II/base/types.h>
#include <deal.II/lac/trilinos_index_access.h>

#include <perideal/base/linear_algebra.h>

#include <vector>

namespace perideal
{
  /**
   * @brief Visit the locally owned rows of @p matrix: @p f(row, columns, values) with the
   * global row index, the global column indices and the row's values (Epetra's storage order).
   */
  template <typename Function>
  void
  for_each_local_row(const SparseMatrix &matrix, const Function &f)
  {
    const auto                                  &A = matrix.trilinos_matrix();
    std::vector<dealii::types::global_dof_index> columns;
    for (int row = 0; row < A.NumMyRows(); ++row)
      {
        int     n_entries = 0;
        double *values    = nullptr;
        int    *local     = nullptr;
        A.ExtractMyRowView(row, n_entries, values, local);
        columns.resize(n_entries);
        for (int k = 0; k < n_entries; ++k)
          columns[k] = dealii::TrilinosWrappers::global_column_index(A, local[k]);
        f(static_cast<dealii::types::global_dof_index>(
            dealii::TrilinosWrappers::global_row_index(A, row)),
          columns,
          values);
      }
  }
} // namespace perideal

#endif
