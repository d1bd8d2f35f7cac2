// Test helpers shared by all unit tests, in the manner of deal.II's tests/tests.h.
#ifndef perideal_tests_h
#define perideal_tests_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/logstream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace perideal_tests
{
  inline std::ofstream &
  logfile()
  {
    static std::ofstream file;
    return file;
  }

  /**
   * The message of a deal.II exception (its "additional information"), trimmed: what a test
   * prints to show which entry a bad input names.
   */
  inline std::string
  exception_text(const dealii::ExceptionBase &exc)
  {
    std::ostringstream message;
    exc.print_info(message);
    std::string text = message.str();
    text.erase(0, text.find_first_not_of(" \n"));
    while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
      text.pop_back();
    return text;
  }

  /**
   * The columns of a statistics.csv by name. Not collective: a rank that did not write the file
   * must wait until it is complete (MPI_Barrier after the run).
   */
  inline std::map<std::string, std::vector<double>>
  read_statistics(const std::string &filename)
  {
    std::ifstream                              file(filename);
    std::string                                line;
    std::map<std::string, std::vector<double>> columns;
    AssertThrow(std::getline(file, line), dealii::ExcIO());
    const auto names = dealii::Utilities::split_string_list(line, ',');
    while (std::getline(file, line))
      {
        const auto values = dealii::Utilities::split_string_list(line, ',');
        AssertThrow(values.size() == names.size(), dealii::ExcIO());
        for (unsigned int c = 0; c < names.size(); ++c)
          columns[names[c]].push_back(dealii::Utilities::string_to_double(values[c]));
      }
    return columns;
  }
} // namespace perideal_tests

/**
 * Attach deallog to the file "output" that the deal.II test driver compares.
 */
inline void
initlog()
{
  perideal_tests::logfile().open("output");
  perideal_tests::logfile() << std::setprecision(6);
  dealii::deallog.attach(perideal_tests::logfile());
  dealii::deallog.depth_console(0);
}

/**
 * As initlog(), on MPI rank 0 only; the other ranks write nothing.
 */
inline void
mpi_initlog()
{
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    initlog();
  else
    dealii::deallog.depth_console(0);
}

#endif
