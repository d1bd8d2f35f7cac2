// Helpers shared by the tests in tests/coupling.
#ifndef perideal_coupling_tests_h
#define perideal_coupling_tests_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/base/region.h>
#include <perideal/coupling/coupled_problem.h>

#include <fstream>
#include <map>
#include <string>

namespace coupling_tests
{
  /**
   * Declare and read the parameters of the 2D coupled problem in @p file and hand them to
   * @p problem, as perideal-solid does: a first pass reads the names of the regions and of the
   * particle and FE boundary conditions, which decide the subsections.
   */
  /**
   * @p text with every occurrence of each key of @p values replaced by its value.
   */
  inline std::string
  substitute(std::string text, const std::map<std::string, std::string> &values)
  {
    for (const auto &[key, value] : values)
      for (auto at = text.find(key); at != std::string::npos;
           at      = text.find(key, at + value.size()))
        text.replace(at, key.size(), value);
    return text;
  }

  /**
   * Write @p text to @p file on rank 0; every rank returns once the file is there.
   */
  inline void
  write_file(const std::string &file, const std::string &text)
  {
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::ofstream(file) << text;
    MPI_Barrier(MPI_COMM_WORLD);
  }

  inline void
  parse(perideal::CoupledProblem<2> &problem, const std::string &file)
  {
    dealii::ParameterHandler first;
    first.declare_entry("Dimension", "2", dealii::Patterns::Integer(2, 3), "");
    perideal::RegionCollection<2>::declare_names(first);
    perideal::BoundaryConditions<2>::declare_names(first);
    perideal::FERegion<2>::declare_names(first);
    perideal::ParameterUtilities::parse_partially(first, file);
    dealii::ParameterHandler prm;
    perideal::CoupledProblem<2>::declare_parameters(
      prm,
      perideal::RegionCollection<2>::parse_names(first),
      perideal::BoundaryConditions<2>::parse_names(first),
      perideal::FERegion<2>::parse_names(first));
    perideal::ParameterUtilities::parse_file(prm, file);
    problem.parse_parameters(prm);
  }
} // namespace coupling_tests

#endif
