#ifndef perideal_base_particle_output_h
#define perideal_base_particle_output_h

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>

#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace perideal
{
  /**
   * Writes point (particle) data that ParaView can open.
   *
   * Every locally owned particle becomes one node (HDF5) or one vertex patch
   * (dealii::DataOutBase::Patch<0,dim>, VTU) that carries the values of all fields
   * added since the last write(). write() produces, depending on the
   * flags given to the constructor,
   *
   * - HDF5 + XDMF: `<directory>/<base_name>_<step>.h5` (one file per step,
   *   written collectively with parallel HDF5) and `<directory>/<base_name>.xdmf`
   *   which is rewritten at every step and lists all steps written so far.
   *   ParaView opens the `.xdmf` file ("XDMF Reader", Polyvertex topology).
   *   A rank without particles takes part without data; if no rank owns a
   *   particle, the step is left out of the HDF5/XDMF output. The values are
   *   the fields' doubles.
   * - VTU: `<directory>/<base_name>_<step>.0.vtu` (one file per step, written
   *   with MPI I/O, one piece per rank that owns particles), a `.pvtu` record
   *   per step and `<directory>/<base_name>.pvd` listing all steps written so
   *   far. ParaView opens the `.pvd` file.
   *
   * `<step>` is zero-padded to five digits.
   *
   * Fields with exactly `dim` components are declared as vectors (ParaView
   * shows them as one vector with glyphs); fields with another number of
   * components are written as the scalars `name_0`, `name_1`, ...
   *
   * All functions except the accessors are collective on the communicator in
   * the sense that every rank must add the same fields (same names, same
   * number of components, same order) before calling write(), also ranks that
   * own no particle. The VTU files store single-precision floats
   * (dealii::DataOutBase::Patch uses `float` data).
   *
   * write() consumes the points and the fields (they move into the HDF5 data
   * sets) and keeps no patches: between two outputs the writer holds only its
   * records, and each step sets its points and adds its fields again.
   */
  template <int dim>
  class ParticleOutput : public dealii::DataOutInterface<0, dim>
  {
  public:
    /**
     * @brief Set up the writer; rank 0 creates @p directory if it is missing.
     *
     * @param comm Communicator of all ranks that own particles.
     * @param directory Output directory (created with all parents if missing).
     * @param base_name File name stem of all files written.
     * @param write_hdf5_xdmf Write `.h5` files plus an `.xdmf` record.
     * @param write_vtu Write `.vtu` files plus `.pvtu` and `.pvd` records.
     */
    ParticleOutput(MPI_Comm           comm,
                   const std::string &directory,
                   const std::string &base_name,
                   bool               write_hdf5_xdmf,
                   bool               write_vtu);

    /**
     * @brief Set the reference positions of this rank's locally owned
     * particles; may be empty.
     */
    void
    set_points(const std::vector<dealii::Point<dim>> &points);

    /**
     * @brief Add a scalar field with one value per point of set_points().
     */
    void
    add_scalar_field(const std::string &name, std::vector<double> values);

    /**
     * @brief Add a field with @p n_components values per point, stored
     * point-major: `values[p * n_components + c]`.
     *
     * @p n_components must lie in [1, dim+3]. If it equals `dim` the field is
     * written as a vector, otherwise as the scalars `name_0`, `name_1`, ...
     * (a one-component field keeps its plain name).
     */
    void
    add_vector_field(const std::string  &name,
                     const unsigned int  n_components,
                     std::vector<double> values);

    /**
     * @brief Write the points and the fields added since the last write() as
     * output step @p step at time @p time, and update the `.xdmf` and `.pvd`
     * records; then forget the points and fields. Collective.
     */
    void
    write(const unsigned int step, const double time);

    /**
     * @brief The XDMF and PVD records of the steps written so far, packed: a checkpoint keeps
     * them, so that a restarted run continues the records (load_records()).
     */
    std::string
    save_records() const;

    /**
     * @brief Continue the records of save_records(): the steps a restarted run does not write
     * again; the next write() rewrites the `.xdmf` and `.pvd` files from them.
     */
    void
    load_records(const std::string &packed);

    /**
     * @brief The name of the `.xdmf` record (whether or not it was written).
     */
    std::string
    xdmf_filename() const;

    /**
     * @brief The name of the `.h5` file of step @p step.
     */
    std::string
    hdf5_filename(const unsigned int step) const;

    /**
     * @brief The name of the `.pvd` record (whether or not it was written).
     */
    std::string
    pvd_filename() const;

  protected:
    /**
     * @brief The patches (one vertex per point) of the VTU file being written (empty
     * otherwise).
     */
    const std::vector<dealii::DataOutBase::Patch<0, dim>> &
    get_patches() const override;

    /**
     * @brief Names of all scalar components, in the row order of the patch
     * data.
     */
    std::vector<std::string>
    get_dataset_names() const override;

    /**
     * @brief The component ranges that form `dim`-vectors.
     */
    std::vector<std::tuple<unsigned int,
                           unsigned int,
                           std::string,
                           dealii::DataComponentInterpretation::DataComponentInterpretation>>
    get_nonscalar_data_ranges() const override;

  private:
    /**
     * A field added through add_scalar_field() or add_vector_field().
     */
    struct Field
    {
      std::string         name;
      unsigned int        n_components;
      std::vector<double> values;
    };

    /**
     * @brief Check the sizes of #fields against #coordinates and fill #dataset_names and
     * #vector_ranges.
     */
    void
    name_data_sets();

    /**
     * @brief Fill #patches from #coordinates and #fields (for the VTU output).
     */
    void
    build_patches();

    /**
     * @brief Write the HDF5 file of this step and rewrite the XDMF record.
     */
    void
    write_hdf5_xdmf(const unsigned int step, const double time);

    /**
     * @brief Write the VTU file and `.pvtu` record of this step and rewrite
     * the PVD record.
     */
    void
    write_vtu_files(const unsigned int step, const double time);

    MPI_Comm    comm;
    std::string directory;
    std::string base_name;
    bool        hdf5_xdmf_enabled;
    bool        vtu_enabled;

    /**
     * The points of set_points(), dim coordinates each.
     */
    std::vector<double> coordinates;
    std::vector<Field>  fields;

    std::vector<dealii::DataOutBase::Patch<0, dim>> patches;
    std::vector<std::string>                        dataset_names;
    std::vector<std::tuple<unsigned int,
                           unsigned int,
                           std::string,
                           dealii::DataComponentInterpretation::DataComponentInterpretation>>
      vector_ranges;

    /**
     * All XDMF entries written so far (used on rank 0 only).
     */
    std::vector<dealii::XDMFEntry> xdmf_entries;

    /**
     * All (time, pvtu file name) pairs written so far (used on rank 0 only).
     */
    std::vector<std::pair<double, std::string>> pvd_records;
  };
} // namespace perideal

#endif
