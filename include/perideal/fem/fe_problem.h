// ---------------------------------------------------------------------
// PeriDeal: a finite-element-only elasticity problem driven by a parameter file.
// ---------------------------------------------------------------------
#ifndef perideal_fem_fe_problem_h
#define perideal_fem_fe_problem_h

#include <deal.II/base/parameter_handler.h>

#include <perideal/base/statistics_file.h>
#include <perideal/fem/fe_solid.h>

#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace perideal
{
  /**
   * @brief A problem with an FE region only: a static solve in load steps or explicit dynamics
   * (velocity Verlet with the lumped mass), with statistics (energies, reactions) and HDF5 +
   * XDMF output of displacement, strain and stress.
   *
   * Entries: "Dimension", "Finite elements" (FESolid, plus "Planar assumption" and
   * "Thickness"), "Solver/Type" (static | explicit), "Solver/Load steps", "Time stepping"
   * ("End time", "Time step", "Safety factor"), "Output".
   */
  template <int dim>
  class FEProblem
  {
  public:
    FEProblem(const MPI_Comm comm, std::ostream &log);

    static void
    declare_parameters(dealii::ParameterHandler       &prm,
                       const std::vector<std::string> &condition_names);
    void
    parse_parameters(dealii::ParameterHandler &prm);
    void
    setup();
    void
    run();

    const FESolid<dim> &
    solid() const;

  private:
    void
    run_static();
    void
    run_explicit();
    /**
     * @brief A row of statistics.csv (energies, external work, reactions); the final row is
     * also printed as the run's summary.
     */
    void
    write_statistics(const double                                              time,
                     const dealii::LinearAlgebra::distributed::Vector<double> &u,
                     const dealii::LinearAlgebra::distributed::Vector<double> &v,
                     const bool                                                final_row);

    MPI_Comm      comm;
    std::ostream &log;
    bool          is_root;

    FESolid<dim> fe;
    bool         explicit_dynamics = false;
    unsigned int load_steps        = 1;
    double       end_time = 0., requested_time_step = 0., safety_factor = 0.8;
    std::string  output_directory;
    unsigned int output_interval = 0, statistics_interval = 1;
    bool         show_progress = true;

    dealii::LinearAlgebra::distributed::Vector<double> f_ext, previous_f_ext, previous_u;
    double                                             external_work = 0.;
    std::unique_ptr<StatisticsFile>                    statistics;
  };
} // namespace perideal

#endif
