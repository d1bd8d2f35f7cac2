// ---------------------------------------------------------------------
// PeriDeal: one time step of parallel HDF5 output plus its XDMF record.
// ---------------------------------------------------------------------
#ifndef perideal_base_hdf5_xdmf_writer_h
#define perideal_base_hdf5_xdmf_writer_h

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>

#include <functional>
#include <string>
#include <vector>

namespace perideal
{
  /**
   * @brief Write the patches of @p data as `<directory>/<base_name>_<step>.h5` (parallel HDF5,
   * collective) and rewrite `<directory>/<base_name>.xdmf`, which lists @p entries plus this
   * step (appended to @p entries).
   *
   * deal.II 9.4 cannot write parallel HDF5 if a rank has no patches:
   * DataOutBase::write_hdf5_parallel() asserts patches.size() > 0 in debug mode, and in release
   * mode H5Dwrite() fails on that rank ("no output buffer") because write_filtered_data() leaves
   * its filter empty, so the collective data set calls do not match either. Only the ranks with
   * patches (@p has_patches) therefore write, on a sub-communicator, and the XDMF entry is
   * broadcast to all ranks so that the record stays complete whichever rank writes first. If no
   * rank has patches the step is left out.
   *
   * @p merge_vertices merges coincident vertices (right for a mesh, wrong for particles).
   * `<step>` is zero-padded to five digits. Collective on @p comm.
   *
   * @p fill_filter, if given, fills the filter instead of
   * DataOutInterface::write_filtered_data() (which takes the values from the patches, stored
   * in single precision by deal.II 9.4): ParticleOutput passes its values in double precision.
   * The data sets are written as doubles either way (XDMF Precision="8").
   */
  template <int dim, int spacedim>
  void
  write_hdf5_xdmf_step(
    const dealii::DataOutInterface<dim, spacedim>                   &data,
    const bool                                                       has_patches,
    const bool                                                       merge_vertices,
    const MPI_Comm                                                   comm,
    const std::string                                               &directory,
    const std::string                                               &base_name,
    const unsigned int                                               step,
    const double                                                     time,
    std::vector<dealii::XDMFEntry>                                  &entries,
    const std::function<void(dealii::DataOutBase::DataOutFilter &)> &fill_filter = {});
} // namespace perideal

#endif
