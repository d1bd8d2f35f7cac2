// ---------------------------------------------------------------------
// PeriDeal: one time step of parallel HDF5 output plus its XDMF record.
// ---------------------------------------------------------------------
#include <deal.II/base/utilities.h>

#include <perideal/base/hdf5_xdmf_writer.h>

#include <memory>

namespace perideal
{
  template <int dim, int spacedim>
  void
  write_hdf5_xdmf_step(const dealii::DataOutInterface<dim, spacedim> &data,
                       const bool                                     has_patches,
                       const bool                                     merge_vertices,
                       const MPI_Comm                                 comm,
                       const std::string                             &directory,
                       const std::string                             &base_name,
                       const unsigned int                             step,
                       const double                                   time,
                       std::vector<dealii::XDMFEntry>                &entries,
                       const std::function<void(dealii::DataOutBase::DataOutFilter &)> &fill_filter)
  {
    const unsigned int my_rank = dealii::Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
    const unsigned int root    = dealii::Utilities::MPI::min(has_patches ? my_rank : n_ranks, comm);
    if (root == n_ranks)
      return; // nothing to write anywhere

    MPI_Comm  writers = MPI_COMM_NULL;
    const int ierr    = MPI_Comm_split(comm, has_patches ? 0 : MPI_UNDEFINED, my_rank, &writers);
    AssertThrowMPI(ierr);
    // Free the sub-communicator also if writing throws.
    const std::unique_ptr<MPI_Comm, void (*)(MPI_Comm *)> writers_guard(&writers, [](MPI_Comm *c) {
      if (*c != MPI_COMM_NULL)
        MPI_Comm_free(c);
    });

    // The XDMF record refers to the .h5 file relative to its own location.
    const std::string h5_name = base_name + "_" + dealii::Utilities::int_to_string(step, 5) + ".h5";
    dealii::XDMFEntry entry;
    if (has_patches)
      {
        dealii::DataOutBase::DataOutFilter filter(
          dealii::DataOutBase::DataOutFilterFlags(merge_vertices, true));
        if (fill_filter)
          fill_filter(filter);
        else
          data.write_filtered_data(filter);
        data.write_hdf5_parallel(filter, directory + "/" + h5_name, writers);
        entry = data.create_xdmf_entry(filter, h5_name, time, writers);
      }
    entries.push_back(dealii::Utilities::MPI::broadcast(comm, entry, root));
    if (has_patches)
      data.write_xdmf_file(entries, directory + "/" + base_name + ".xdmf", writers);
  }

  template void
  write_hdf5_xdmf_step<0, 2>(const dealii::DataOutInterface<0, 2> &,
                             const bool,
                             const bool,
                             const MPI_Comm,
                             const std::string &,
                             const std::string &,
                             const unsigned int,
                             const double,
                             std::vector<dealii::XDMFEntry> &,
                             const std::function<void(dealii::DataOutBase::DataOutFilter &)> &);
  template void
  write_hdf5_xdmf_step<0, 3>(const dealii::DataOutInterface<0, 3> &,
                             const bool,
                             const bool,
                             const MPI_Comm,
                             const std::string &,
                             const std::string &,
                             const unsigned int,
                             const double,
                             std::vector<dealii::XDMFEntry> &,
                             const std::function<void(dealii::DataOutBase::DataOutFilter &)> &);
  template void
  write_hdf5_xdmf_step<2, 2>(const dealii::DataOutInterface<2, 2> &,
                             const bool,
                             const bool,
                             const MPI_Comm,
                             const std::string &,
                             const std::string &,
                             const unsigned int,
                             const double,
                             std::vector<dealii::XDMFEntry> &,
                             const std::function<void(dealii::DataOutBase::DataOutFilter &)> &);
  template void
  write_hdf5_xdmf_step<3, 3>(const dealii::DataOutInterface<3, 3> &,
                             const bool,
                             const bool,
                             const MPI_Comm,
                             const std::string &,
                             const std::string &,
                             const unsigned int,
                             const double,
                             std::vector<dealii::XDMFEntry> &,
                             const std::function<void(dealii::DataOutBase::DataOutFilter &)> &);
} // namespace perideal
