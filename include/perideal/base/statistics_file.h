#ifndef perideal_base_statistics_file_h
#define perideal_base_statistics_file_h

#include <deal.II/base/mpi.h>

#include <cmath>
#include <fstream>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace perideal
{
  /**
   * A CSV table with one row per call of end_row(), e.g. one row per time
   * step with energies, reaction forces and the number of broken bonds.
   *
   * Columns are created by add_value(); their order in the file is the order
   * in which their names were first seen. The header line is written once,
   * right before the first row, so all columns must be known by the first
   * end_row(); a column first seen later is an error. A row in which a known
   * column received no value has an empty entry there. Values are written in
   * scientific notation with 10 significant digits.
   *
   * All ranks may call every function (values passed on ranks other than 0
   * are ignored); only rank 0 opens and writes the file. The file is opened
   * (and truncated) at the first end_row() and flushed after every row, so it
   * can be inspected while the simulation runs.
   */
  class StatisticsFile
  {
  public:
    /**
     * @brief Set up the table; the file @p filename is created at the first
     * end_row().
     */
    StatisticsFile(MPI_Comm comm, const std::string &filename);

    /**
     * @brief Set the value of column @p column in the current row, creating
     * the column if its name is new (only before the first end_row()).
     */
    void
    add_value(const std::string &column, const double value);

    /**
     * @brief Prefix the names of the columns that add_value() sets from now on with
     * @p prefix (the columns of a physics of <Physics/List>, e.g. "heat."); "" for none.
     */
    void
    set_column_prefix(const std::string &prefix);

    /**
     * @brief Finish the current row: rank 0 writes it (after the header, on
     * the first call) and flushes the file; then start a new, empty row.
     */
    void
    end_row();

    /**
     * @brief Continue a table of which @p contents (the header and the rows, as written) are
     * the part to keep: rank 0 rewrites the file with them (rows written after them are
     * dropped), and the next end_row() appends to it with the columns of its header. Used by
     * a restart, with the contents a checkpoint kept (contents()). Collective; every rank
     * passes the same @p contents.
     */
    void
    resume(const std::string &contents);

    /**
     * @brief What the file holds so far (rank 0; empty on the other ranks and before the
     * first end_row()).
     */
    std::string
    contents() const;

    /**
     * @brief The name of the file written.
     */
    const std::string &
    get_filename() const;

  private:
    std::string filename;
    bool        is_root;
    /// The prefix of set_column_prefix().
    std::string column_prefix;

    /**
     * Column names in first-seen order.
     */
    std::vector<std::string> columns;

    /**
     * Values of the current row, keyed by column name.
     */
    std::map<std::string, double> current_row;

    /**
     * Whether the header was written (and the columns are fixed).
     */
    bool header_written;

    std::ofstream file;
  };
  /**
   * @brief @p value as the nearest multiple of the power of ten at or above @p unit (unchanged
   * for @p unit <= 0): a printed number to the accuracy of the solution, free of the round-off
   * or solver residual that changes with the summation order. A power of ten, so that the
   * digits kept are the value's own (50 N to a unit of 2.6e-4 N prints as 50, not as the
   * nearest multiple of 2.6e-4, 50.00013).
   */
  inline double
  to_accuracy(const double value, const double unit)
  {
    if (!(unit > 0.))
      return value;
    const double decade = std::pow(10., std::ceil(std::log10(unit)));
    return decade * std::round(value / decade);
  }

  /**
   * @brief Print @p values separated by spaces (with the stream's format), the components
   * below 1e-10 of their Euclidean norm, or below @p accuracy (absolute), as 0, the others
   * to @p accuracy (to_accuracy(), if given): in printed
   * summaries, a component that vanishes by symmetry is then 0 on every number of ranks, build
   * and machine, not a round-off value, or a solver's residual, that changes with the summation
   * order.
   */
  void
  print_without_round_off(std::ostream              &out,
                          const std::vector<double> &values,
                          const double               accuracy = 0.);
} // namespace perideal

#endif
