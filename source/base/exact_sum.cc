// ---------------------------------------------------------------------
// PeriDeal: sums of doubles over the ranks that do not depend on the order of the terms.
// ---------------------------------------------------------------------
#include <perideal/base/exact_sum.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace perideal
{
  void
  ExactSum::add(const ExactSum &other)
  {
    ExactSum normalized = other;
    normalized.normalize();
    normalize();
    for (unsigned int w = 0; w < n_words; ++w)
      words[w] += normalized.words[w];
    non_finite = non_finite || other.non_finite;
    normalize();
  }

  void
  ExactSum::normalize()
  {
    // Arithmetic shift: the floor of a signed word over 2^32, so the remainder is in [0, 2^32).
    for (unsigned int w = 0; w + 1 < n_words; ++w)
      {
        const std::int64_t carry = words[w] >> 32;
        words[w] -= carry * (std::int64_t(1) << 32);
        words[w + 1] += carry;
      }
    n_added = 0;
  }

  double
  ExactSum::value() const
  {
    if (non_finite)
      return std::numeric_limits<double>::quiet_NaN();
    ExactSum magnitude = *this;
    magnitude.normalize();
    // A negative sum: negate every word and carry again, so that the digits are those of |sum|
    // and the conversion below adds terms of one sign (no cancellation).
    const bool negative = magnitude.words[n_words - 1] < 0;
    if (negative)
      {
        for (auto &w : magnitude.words)
          w = -w;
        magnitude.normalize();
      }
    // The highest nonzero word and the two below it hold the leading 64 or more bits: summed in
    // long double (64-bit mantissa on x86-64) from the lowest up, then rounded to double once.
    int top = n_words - 1;
    while (top >= 0 && magnitude.words[top] == 0)
      --top;
    if (top < 0)
      return 0.;
    long double sum = 0.;
    for (int w = std::max(0, top - 3); w <= top; ++w)
      sum += std::ldexp(static_cast<long double>(magnitude.words[w]), 32 * w - 1074);
    const double result = static_cast<double>(sum);
    return negative ? -result : result;
  }

  void
  ExactSum::sum_over_ranks(std::vector<ExactSum> &sums, const MPI_Comm comm)
  {
    std::vector<std::int64_t> local(sums.size() * (n_words + 1)), global(local.size());
    for (std::size_t s = 0; s < sums.size(); ++s)
      {
        sums[s].normalize();
        for (unsigned int w = 0; w < n_words; ++w)
          local[s * (n_words + 1) + w] = sums[s].words[w];
        local[s * (n_words + 1) + n_words] = sums[s].non_finite ? 1 : 0;
      }
    // Normalized words are below 2^32 in magnitude: a sum over fewer than 2^31 ranks fits.
    MPI_Allreduce(local.data(), global.data(), local.size(), MPI_INT64_T, MPI_SUM, comm);
    for (std::size_t s = 0; s < sums.size(); ++s)
      {
        for (unsigned int w = 0; w < n_words; ++w)
          sums[s].words[w] = global[s * (n_words + 1) + w];
        sums[s].non_finite = global[s * (n_words + 1) + n_words] != 0;
        sums[s].normalize();
      }
  }

  std::vector<double>
  ExactSum::global_sums(std::vector<ExactSum> sums, const MPI_Comm comm)
  {
    sum_over_ranks(sums, comm);
    std::vector<double> values(sums.size());
    for (std::size_t s = 0; s < sums.size(); ++s)
      values[s] = sums[s].value();
    return values;
  }

  double
  exact_l2_norm(const ParticleVector &x)
  {
    ExactSum squares;
    for (std::size_t k = 0; k < x.locally_owned_size(); ++k)
      squares.add(x.local_element(k) * x.local_element(k));
    return std::sqrt(ExactSum::global_sums({squares}, x.get_mpi_communicator())[0]);
  }
} // namespace perideal
