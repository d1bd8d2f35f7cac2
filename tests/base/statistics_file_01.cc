// StatisticsFile writes a CSV table on rank 0: header once, columns in first-seen order, 10
// significant digits, empty entries for missing values, no new columns after the header.

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <perideal/base/statistics_file.h>

#include "../tests.h"

#include <cmath>
#include <fstream>
#include <string>


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();

  const std::string filename = "statistics_file_01.csv";
  {
    perideal::StatisticsFile statistics(MPI_COMM_WORLD, filename);

    // Step k at time k * 1e-6 s of a mass m = 2 moving with v = k: kinetic energy m v^2 / 2 = k^2;
    // broken bonds k (k + 1) / 2; pi / 3 checks the 10 significant digits (1.047197551e+00).
    for (unsigned int k = 0; k < 4; ++k)
      {
        statistics.add_value("time", 1e-6 * k);
        statistics.add_value("kinetic energy", 0.5 * 2. * k * k);
        if (k != 2) // row 2 leaves this column empty
          statistics.add_value("broken bonds", k * (k + 1) / 2);
        statistics.add_value("pi/3", std::acos(-1.) / 3.);
        statistics.end_row();
      }

    try
      {
        statistics.add_value("late column", 1.);
      }
    catch (const dealii::ExceptionBase &)
      {
        dealii::deallog << "a column first seen after the header is rejected" << std::endl;
      }
  }

  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    {
      std::ifstream in(filename);
      std::string   line;
      while (std::getline(in, line))
        dealii::deallog << line << std::endl;
    }
}
