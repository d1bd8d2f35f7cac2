// Helpers shared by the tests in tests/coupling.
#ifndef perideal_coupling_tests_h
#define perideal_coupling_tests_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/base/region.h>
#include <perideal/coupling/coupled_problem.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <tests.h>

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
  /**
   * Write @p text to @p file, run the 2D coupled problem it describes and return its log;
   * @p inspect sees the problem after the run.
   */
  inline std::string
  run(const std::string                                              &file,
      const std::string                                              &text,
      const std::function<void(const perideal::CoupledProblem<2> &)> &inspect = {})
  {
    write_file(file, text);
    std::ostringstream          log;
    perideal::CoupledProblem<2> problem(MPI_COMM_WORLD, log);
    parse(problem, file);
    problem.setup();
    problem.run();
    if (inspect)
      inspect(problem);
    MPI_Barrier(MPI_COMM_WORLD);
    return log.str();
  }

  /// The torque and the strain energy per unit length of a torsion run (the last row of the
  /// fe_ or pd_ section integrals).
  struct SectionIntegrals
  {
    bool   fe;
    double torque;
    double energy;
  };

  /**
   * Run the benchmark file @p benchmark (a path below doc/benchmarks/) with @p overrides and the
   * output in results/ (no HDF5, no progress) and return its section integrals.
   */
  inline SectionIntegrals
  run_torsion(const std::string &benchmark, const std::string &overrides)
  {
    run("torsion.prm",
        "include " SOURCE_DIR "/../../doc/benchmarks/" + benchmark + "\n" + overrides +
          "subsection Output\n"
          "  set Directory  = results\n"
          "  set Write HDF5 = false\n"
          "  set Progress   = false\n"
          "end\n");
    const auto columns = perideal_tests::read_statistics("results/statistics.csv");
    const bool fe      = columns.count("fe_torque") > 0;
    return {fe,
            columns.at(fe ? "fe_torque" : "pd_torque").back(),
            columns.at(fe ? "fe_torsion_energy" : "pd_torsion_energy").back()};
  }

  /// "ok" if @p condition holds, "FAILED" otherwise.
  inline const char *
  ok(const bool condition)
  {
    return condition ? "ok" : "FAILED";
  }

  // The numbers in the line of @p log that starts with @p key (after the key).
  inline std::vector<double>
  numbers_of(const std::string &log, const std::string &key)
  {
    std::istringstream lines(log);
    for (std::string line; std::getline(lines, line);)
      if (line.rfind(key, 0) == 0)
        {
          std::vector<double> numbers;
          const std::string   rest = line.substr(key.size());
          for (std::size_t at = 0; at < rest.size();)
            {
              const std::size_t start = rest.find_first_of("0123456789", at);
              if (start == std::string::npos)
                break;
              std::size_t length = 0;
              numbers.push_back(std::stod(rest.substr(start), &length));
              at = start + length;
            }
          return numbers;
        }
    std::cout << "line '" << key << "' missing (FAILED)" << std::endl;
    return {std::nan(""), std::nan(""), std::nan("")};
  }

} // namespace coupling_tests

#endif
