// ---------------------------------------------------------------------
// PeriDeal: the particle and FE fields of a run, for ParaView.
// ---------------------------------------------------------------------
#ifndef perideal_coupling_postprocessors_field_output_h
#define perideal_coupling_postprocessors_field_output_h

#include <deal.II/base/data_out_base.h>

#include <perideal/base/particle_output.h>
#include <perideal/coupling/postprocessors/postprocessor.h>

#include <memory>
#include <string>
#include <vector>

namespace perideal
{
  /**
   * @brief The fields of both regions at the output steps, in <Output/Directory>: the particles
   * (<Output/Base name>.xdmf + .h5, and .pvd + .vtu with <Output/Write VTU>): displacement,
   * velocity (particles slaved to the FE field: its velocity), force density, damage and
   * strain-energy density; the FE region (solution.xdmf + .h5: the FE region's fields,
   * FERegion::write_output()) with <Output/Write HDF5>.
   *
   * The state of a quasi-static load step that did not converge (StepData::not_converged) goes
   * to files of its own, outside the series of the run: <Output/Base name>_not_converged.xdmf
   * (+ .h5, .pvd + .vtu) and solution_not_converged.xdmf (+ .h5), with the load step as their
   * index; the records of the run's series (its checkpoint's) are left as they were.
   */
  template <int dim>
  class FieldOutput : public Postprocessor<dim>
  {
  public:
    void
    execute(const CoupledState<dim> &state,
            const StepData          &data,
            StatisticsFile          &statistics) override;

    /// The records of the particle and FE files written so far.
    std::string
    save_state(const CoupledState<dim> &state) const override;

    void
    load_state(const CoupledState<dim> &state, const std::string &packed) override;

  private:
    /// A particle writer of files named @p base_name, if the run has particles and writes
    /// their fields (otherwise null).
    static std::unique_ptr<ParticleOutput<dim>>
    create_particle_output(const CoupledState<dim> &state, const std::string &base_name);

    /// The particle writer, created at the first output.
    std::unique_ptr<ParticleOutput<dim>> particle_output;
    /// The XDMF records of the FE files of the run's series written so far
    /// (FERegion::write_output()).
    std::vector<dealii::XDMFEntry> fe_records;
  };
} // namespace perideal

#endif
