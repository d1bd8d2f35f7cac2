// ---------------------------------------------------------------------
// PeriDeal: sums of doubles over the ranks that do not depend on the order of the terms.
// ---------------------------------------------------------------------
#ifndef perideal_base_exact_sum_h
#define perideal_base_exact_sum_h

#include <perideal/base/linear_algebra.h>

#include <array>
#include <cstdint>
#include <vector>

#include <mpi.h>

namespace perideal
{
  /**
   * @brief An exact sum of doubles: a fixed-point accumulator (a Kulisch accumulator) of 70
   * signed 64-bit words holding 32-bit digits, which covers every finite double from the
   * smallest subnormal 2^-1074 to the largest, 2^1024 (2240 bits). Adding a term is exact, so the
   * sum does not depend on the order of the terms nor on how they are split among the ranks;
   * value() rounds it once, deterministically. Used where a global sum decides what an
   * iteration does next (adaptive dynamic relaxation's damping, its residual norms and stop):
   * a sum reduced in another order on another number of ranks differs in its last bits, and
   * the relaxation's adaptive damping amplifies that difference until the iterations stop
   * elsewhere (doc/architecture/02_conventions.md, "The same numbers on any number of ranks").
   *
   * Cost: no branch on the data; callgrind counts 47 instructions per term against 4 for a
   * plain sum of squares (doc/architecture/02_conventions.md); the reduction is one
   * MPI_Allreduce of 71 words per sum. Not meant for the force kernels. Non-finite terms
   * make value() return NaN.
   */
  class ExactSum
  {
  public:
    /// The number of 64-bit words of the accumulator.
    static constexpr unsigned int n_words = 70;

    /// Add @p x exactly.
    void
    add(const double x)
    {
      std::uint64_t bits;
      __builtin_memcpy(&bits, &x, sizeof(bits));
      const unsigned int biased = (bits >> 52) & 0x7ff;
      if (biased == 0x7ff)
        {
          non_finite = true;
          return;
        }
      // x = sign mantissa 2^(position - 1074): a normal number has the hidden bit and position
      // biased - 1, a subnormal (biased 0) neither.
      const bool          normal = biased != 0;
      const std::uint64_t mantissa =
        (bits & ((std::uint64_t(1) << 52) - 1)) | (std::uint64_t(normal) << 52);
      const unsigned int position = biased - normal;
      const unsigned int word = position / 32, shift = position % 32;
      const std::int64_t sign = 1 - 2 * static_cast<std::int64_t>(bits >> 63);
      // The mantissa shifted by shift in three 32-bit digits (bits 64 and up: shifted twice, so
      // that a shift of 0 never shifts by 64).
      const std::uint64_t low  = mantissa << shift;
      const std::uint64_t high = (mantissa >> 1) >> (63 - shift);
      words[word] += sign * static_cast<std::int64_t>(low & 0xffffffffu);
      words[word + 1] += sign * static_cast<std::int64_t>(low >> 32);
      words[word + 2] += sign * static_cast<std::int64_t>(high);
      // Each add changes a word by less than 2^32: carry before 2^30 adds can overflow it.
      if (++n_added == (1u << 30))
        normalize();
    }

    /// Add the terms of @p other exactly.
    void
    add(const ExactSum &other);

    /// The sum, rounded once (to within one unit in the last place; the same for the same sum).
    double
    value() const;

    /**
     * @brief Sum @p sums over the ranks of @p comm in place, exactly (one MPI_Allreduce of all
     * their words): afterwards every rank holds the global sums.
     */
    static void
    sum_over_ranks(std::vector<ExactSum> &sums, const MPI_Comm comm);

    /// sum_over_ranks() of one local value per sum, and the rounded global sums.
    static std::vector<double>
    global_sums(std::vector<ExactSum> sums, const MPI_Comm comm);

  private:
    /// Propagate the carries: every word but the last in [0, 2^32), the last signed.
    void
    normalize();

    /// The digits: words[w] counts units of 2^(32 w - 1074).
    std::array<std::int64_t, n_words> words{};
    /// Terms added since the last normalize().
    unsigned int n_added = 0;
    /// A term was infinite or NaN.
    bool non_finite = false;
  };

  /**
   * @brief The l2 norm of the owned entries of @p x over its communicator, from the exact sum
   * of their squares (ExactSum): the same on any number of ranks and in any order of the
   * entries, unlike ParticleVector::l2_norm().
   */
  double
  exact_l2_norm(const ParticleVector &x);
} // namespace perideal

#endif
