// ---------------------------------------------------------------------
// PeriDeal: what the exchanges of an explicit step move between the ranks.
// ---------------------------------------------------------------------
#ifndef perideal_coupling_communication_volume_h
#define perideal_coupling_communication_volume_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/partitioner.h>

#include <perideal/base/linear_algebra.h>

#include <cstdint>
#include <string>
#include <vector>

namespace perideal
{
  /**
   * @brief One exchange of values between the ranks, seen from one rank: how many 8-byte values
   * it receives and sends, and from and to how many other ranks. Read from the communication
   * patterns that the exchanges use (a deal.II Partitioner, a Trilinos matrix's Epetra_Import),
   * once, after the run: counting costs the time steps nothing. The numbers are those of one
   * exchange; ExplicitDynamics makes each of its exchanges once per step
   * (`doc/benchmarks/performance/README.md`, "Many ranks").
   */
  struct ExchangeVolume
  {
    /// What is exchanged, for the log.
    std::string name;
    /// Values (8 bytes each) this rank receives.
    std::uint64_t values_received = 0;
    /// Values this rank sends.
    std::uint64_t values_sent = 0;
    /// The ranks this rank receives from.
    unsigned int ranks_received_from = 0;
    /// The ranks this rank sends to.
    unsigned int ranks_sent_to = 0;
  };

  /**
   * @brief The ghost update (`update_ghost_values()`) of a distributed vector with the
   * partitioner @p partitioner: the ghost entries are received from their owners.
   */
  ExchangeVolume
  ghost_exchange(const std::string &name, const dealii::Utilities::MPI::Partitioner &partitioner);

  /**
   * @brief The product `matrix.vmult(y, x)` of a Trilinos matrix: Epetra imports the entries of
   * x of the columns that other ranks own (none if the matrix has no importer). With @p
   * transpose, `Tvmult`: the same pattern the other way (the contributions to other ranks'
   * entries are sent back).
   */
  ExchangeVolume
  matrix_exchange(const std::string &name, const SparseMatrix &matrix, const bool transpose);

  /**
   * @brief One line for the log: for each exchange of @p exchanges (the same list on every
   * rank), the values received per rank (mean and largest over the ranks), in bytes, and the
   * ranks received from (largest); @p particle_components converts the first exchange's values
   * to ghost particles when it is the particles' ghost update (0: it is not); the line starts
   * with the @p owned_particles of the ranks (mean and largest: the balance of the particles).
   * Collective.
   */
  std::string
  communication_summary(const MPI_Comm                     comm,
                        const std::vector<ExchangeVolume> &exchanges,
                        const unsigned int                 particle_components,
                        const std::uint64_t                owned_particles);
} // namespace perideal

#endif
