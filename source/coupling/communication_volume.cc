// ---------------------------------------------------------------------
// PeriDeal: what the exchanges of an explicit step move between the ranks.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>

#include <perideal/coupling/communication_volume.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Import.h>
#ifdef DEAL_II_WITH_MPI
#  include <Epetra_MpiDistributor.h>
#endif

#include <set>
#include <sstream>

namespace perideal
{
  using namespace dealii;

  ExchangeVolume
  ghost_exchange(const std::string &name, const Utilities::MPI::Partitioner &partitioner)
  {
    ExchangeVolume volume;
    volume.name                = name;
    volume.values_received     = partitioner.n_ghost_indices();
    volume.values_sent         = partitioner.n_import_indices();
    volume.ranks_received_from = partitioner.ghost_targets().size();
    volume.ranks_sent_to       = partitioner.import_targets().size();
    return volume;
  }

  ExchangeVolume
  matrix_exchange(const std::string &name, const SparseMatrix &matrix, const bool transpose)
  {
    ExchangeVolume       volume;
    const Epetra_Import *importer = matrix.trilinos_matrix().Importer();
    volume.name                   = name;
    if (importer == nullptr)
      return volume;
    // The entries of other ranks' columns, and those of ours that other ranks need.
    std::uint64_t       received = importer->NumRemoteIDs(), sent = importer->NumExportIDs();
    const std::set<int> send_ranks(importer->ExportPIDs(),
                                   importer->ExportPIDs() + importer->NumExportIDs());
    unsigned int        from = 0, to = send_ranks.size();
#ifdef DEAL_II_WITH_MPI
    if (const auto *distributor =
          dynamic_cast<const Epetra_MpiDistributor *>(&importer->Distributor()))
      from = distributor->NumReceives();
#endif
    if (transpose)
      {
        std::swap(received, sent);
        std::swap(from, to);
      }
    volume.values_received     = received;
    volume.values_sent         = sent;
    volume.ranks_received_from = from;
    volume.ranks_sent_to       = to;
    return volume;
  }

  std::string
  communication_summary(const MPI_Comm                     comm,
                        const std::vector<ExchangeVolume> &exchanges,
                        const unsigned int                 particle_components,
                        const std::uint64_t                owned_particles)
  {
    std::ostringstream line;
    const auto         owned = Utilities::MPI::min_max_avg(double(owned_particles), comm);
    line << "Communication per exchange and rank (mean / largest over the "
         << Utilities::MPI::n_mpi_processes(comm) << " ranks, received; each once per step; "
         << "owned particles " << owned.avg << " / " << owned.max << "):";
    double total = 0.;
    for (std::size_t k = 0; k < exchanges.size(); ++k)
      {
        const auto  &e      = exchanges[k];
        const auto   values = Utilities::MPI::min_max_avg(double(e.values_received), comm);
        const double ranks  = Utilities::MPI::max(double(e.ranks_received_from), comm);
        line << (k > 0 ? ";" : "") << " " << e.name << " ";
        if (k == 0 && particle_components > 0)
          line << values.avg / particle_components << " / " << values.max / particle_components
               << " ghost particles, ";
        line << 8. * values.avg << " / " << 8. * values.max << " B from " << ranks << " ranks";
        total += 8. * e.values_received;
      }
    const auto all = Utilities::MPI::min_max_avg(total, comm);
    line << "; all " << all.avg << " / " << all.max << " B";
    return line.str();
  }
} // namespace perideal
