// ExactSum adds doubles exactly: the same sum in any order and on any number of ranks, where the
// order of a floating-point sum changes its last bits; cancellation to the smallest subnormal.

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <perideal/base/exact_sum.h>

#include "../tests.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>


namespace
{
  /// The value in C99 hexadecimal notation: equal strings are equal bits.
  std::string
  hex(const double x)
  {
    char buffer[64];
    std::snprintf(buffer, sizeof(buffer), "%a", x);
    return buffer;
  }
} // namespace


int
main(int argc, char **argv)
{
  using dealii::deallog;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  const MPI_Comm     comm    = MPI_COMM_WORLD;
  const unsigned int rank    = dealii::Utilities::MPI::this_mpi_process(comm);
  const unsigned int n_ranks = dealii::Utilities::MPI::n_mpi_processes(comm);

  // 1. Cancellation: 1e100 + 1 - 1e100 is 1 exactly (a double sum gives 0), and the smallest
  // subnormal survives beside the largest double.
  {
    perideal::ExactSum sum;
    for (const double x : {1e100, 1., -1e100})
      sum.add(x);
    deallog << "1e100 + 1 - 1e100 = " << sum.value() << std::endl;
    perideal::ExactSum tiny;
    const double       smallest = std::numeric_limits<double>::denorm_min();
    const double       largest  = std::numeric_limits<double>::max();
    for (const double x : {largest, smallest, -largest})
      tiny.add(x);
    deallog << "max + denorm_min - max = denorm_min: " << (tiny.value() == smallest) << std::endl;
    perideal::ExactSum negative;
    for (const double x : {-0.1, -0.2, 0.3})
      negative.add(x);
    // The three doubles sum exactly to -2^-55 (their representation errors); the double sum
    // rounds -0.1 - 0.2 first and gives -2^-54.
    deallog << "-0.1 - 0.2 + 0.3 = -2^-55: " << (negative.value() == -std::ldexp(1., -55))
            << ", double sum " << hex(-0.1 - 0.2 + 0.3) << std::endl;
  }

  // 2. Ten thousand terms of mixed signs and magnitudes, in three orders and split among the
  // ranks: one sum, bit for bit, where the double sums of the orders differ.
  {
    std::mt19937                     generator(7);
    std::uniform_real_distribution<> mantissa(-1., 1.);
    std::uniform_int_distribution<>  exponent(-40, 40);
    std::vector<double>              terms(10000);
    for (double &x : terms)
      x = std::ldexp(mantissa(generator), exponent(generator));
    std::vector<std::string> exact, naive;
    for (unsigned int order = 0; order < 3; ++order)
      {
        if (order == 1)
          std::reverse(terms.begin(), terms.end());
        if (order == 2)
          std::sort(terms.begin(), terms.end());
        perideal::ExactSum local;
        double             plain = 0.;
        for (std::size_t k = rank; k < terms.size(); k += n_ranks)
          local.add(terms[k]);
        for (const double x : terms)
          plain += x;
        exact.push_back(hex(perideal::ExactSum::global_sums({local}, comm)[0]));
        naive.push_back(hex(plain));
      }
    deallog << "exact sum, three orders: " << exact[0] << " " << exact[1] << " " << exact[2]
            << std::endl;
    deallog << "double sums differ between the orders: "
            << (naive[0] != naive[1] || naive[1] != naive[2]) << std::endl;
  }

  // 3. The l2 norm of a distributed vector (3, 4, 12 spread over the ranks) is 13.
  {
    const dealii::IndexSet owned =
      dealii::Utilities::create_evenly_distributed_partitioning(rank, n_ranks, 3);
    perideal::ParticleVector v(owned, comm);
    const double             values[3] = {3., 4., 12.};
    for (const auto k : owned)
      v(k) = values[k];
    deallog << "|(3, 4, 12)| = " << perideal::exact_l2_norm(v) << std::endl;
  }
  return 0;
}
