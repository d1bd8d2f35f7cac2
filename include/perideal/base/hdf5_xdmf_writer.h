// ---------------------------------------------------------------------
// PeriDeal: one time step of parallel HDF5 output plus its XDMF record.
// ---------------------------------------------------------------------
#ifndef perideal_base_hdf5_xdmf_writer_h
#define perideal_base_hdf5_xdmf_writer_h

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>

#include <string>
#include <tuple>
#include <vector>

namespace perideal
{
  /**
   * @brief One rank's share of an output step, laid out as its HDF5 data sets: the nodes, the
   * cells over them and the point data.
   */
  template <int spacedim>
  struct HDF5StepData
  {
    /**
     * @brief A point data set.
     */
    struct DataSet
    {
      /**
       * @brief The data set's name in the file and the XDMF record.
       */
      std::string name;

      /**
       * @brief Values per node: 1 for a scalar, 3 for a vector (as XDMF wants them: a 2D
       * vector has a zero third component).
       */
      unsigned int width;

      /**
       * @brief The values, `width` per node.
       */
      std::vector<double> values;
    };

    /**
     * @brief The dimension of the cells: 0 for points (XDMF "Polyvertex", one node per cell),
     * 2 for quadrilaterals, 3 for hexahedra.
     */
    unsigned int cell_dim = 0;

    /**
     * @brief The coordinates, spacedim per node.
     */
    std::vector<double> nodes;

    /**
     * @brief The nodes of each cell (2^cell_dim per cell, in XDMF's order), numbered on this
     * rank from zero.
     */
    std::vector<unsigned int> cells;

    /**
     * @brief The point data, in the order of the file.
     */
    std::vector<DataSet> data_sets;

    /**
     * @brief The number of nodes on this rank.
     */
    unsigned int
    n_nodes() const
    {
      return nodes.size() / spacedim;
    }
  };

  /**
   * @brief The vector-valued ranges of the rows of a DataOut's point data (first row, last
   * row, name, interpretation), as DataOutInterface::get_nonscalar_data_ranges() gives them.
   */
  using NonscalarDataRanges =
    std::vector<std::tuple<unsigned int,
                           unsigned int,
                           std::string,
                           dealii::DataComponentInterpretation::DataComponentInterpretation>>;

  /**
   * @brief The step data of @p patches (one subdivision per patch, as DataOut::build_patches()
   * makes by default), with coincident vertices merged into one node;
   * a node takes its values from the last patch that has it (for fields that jump between
   * cells, such as a stress, one of the cells' values). The point data's rows are named by
   * @p names; the ranges of @p vectors become one data set each, every other row a scalar one
   * (the arguments of DataOutBase::write_filtered_data()).
   *
   * This is what DataOutBase::DataOutFilter does for the same patches, node for node, without
   * its ordered maps: deal.II 9.4's filter reads a `std::map` per point and data set, which took
   * 9 % of an adaptive 3D run.
   */
  template <int dim, int spacedim>
  HDF5StepData<spacedim>
  merged_step_data(const std::vector<dealii::DataOutBase::Patch<dim, spacedim>> &patches,
                   const std::vector<std::string>                               &names,
                   const NonscalarDataRanges                                    &vectors);

  /**
   * @brief Write @p data (consumed: its cells are renumbered in place) as
   * `<directory>/<base_name>_<step>.h5` (parallel HDF5, collective, one file for all ranks:
   * `nodes`, `cells` and one data set per name, doubles except the cells' unsigned node numbers)
   * and rewrite `<directory>/<base_name>.xdmf` (rank 0), which lists
   * @p entries plus this step (appended to @p entries on every rank). A rank without nodes takes
   * part in the collective writes without data. If no rank has nodes the step is left out.
   *
   * The layout is deal.II's (DataOutBase::write_hdf5_parallel() and XDMFEntry): ParaView opens
   * the `.xdmf` file with its XDMF reader. `<step>` is zero-padded to five digits. All ranks
   * must pass the same data set names and widths. Collective on @p comm.
   */
  template <int spacedim>
  void
  write_hdf5_xdmf_step(HDF5StepData<spacedim>        &&data,
                       const MPI_Comm                  comm,
                       const std::string              &directory,
                       const std::string              &base_name,
                       const unsigned int              step,
                       const double                    time,
                       std::vector<dealii::XDMFEntry> &entries);
} // namespace perideal

#endif
