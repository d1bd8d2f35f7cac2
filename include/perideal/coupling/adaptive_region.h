// ---------------------------------------------------------------------
// PeriDeal: the PD region follows the crack (where FE cells become particles during a run).
// ---------------------------------------------------------------------
#ifndef perideal_coupling_adaptive_region_h
#define perideal_coupling_adaptive_region_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <perideal/base/cell_list.h>
#include <perideal/coupling/coupled_state.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace perideal
{
  /**
   * @brief <Coupling/Adaptive region>: where the PD region of a blended explicit run grows
   * during the run, so that it need not be placed on the crack path beforehand.
   *
   * The grown part of the PD region is a union of disks (balls in 3D) around *seeds*: beta(x)
   * is the larger of the file's <Coupling/Blending function> and
   * max_s clamp((R + w - |x - s|) / w, 0, 1), with R the <Core radius> (beta = 1 inside, the
   * buffer ahead of a crack tip) and w the <Ramp width> of the overlap. Every <Check interval>
   * steps the criterion proposes seeds (collective, the same on every rank):
   * - principal strain: the centre of each FE cell with unknowns whose largest principal strain
   *   at the centre (the slope |grad w| of a scalar field) exceeds <Strain fraction> times the
   *   critical stretch of the particles' damage model (the bonds' elastic limit: where a brittle
   *   bond breaks, where a softening bond starts to soften), where <Strain region> > 0;
   * - damage: each particle whose damage from the bonds broken during the run (its damage
   *   index less that of the pre-cracks) is >= <Damage threshold> and that lies within <Damage
   *   distance> of the edge of the PD-only zone (a point of the body at that distance or half of
   *   it, in 16 directions in 2D and 26 in 3D, has beta < 1); the seed lies <Lead distance>
   *   beyond the particle, away from the nearest seed (the way the crack runs).
   * Cell centres where beta is already 1 are not proposed (a damaged particle far enough inside
   * the PD-only zone is not near its edge); the proposals are thinned to one per R/2 (in
   * the lexicographic order of their coordinates, so that the seeds do not depend on the number
   * of ranks). The zone only grows. CoupledProblem carries the state over (its conversion).
   *
   * <Seed shape> = cylinder (3D only) makes every seed a cylinder whose axis is parallel to z
   * (the thickness of a plate): |x - s| is then the distance in the x-y plane, so beta does not
   * depend on z, and the proposals are thinned by that distance too (one cylinder per R/2 of
   * the plane, whatever the depth of the particles that flag it).
   */
  template <int dim>
  class AdaptiveRegion
  {
  public:
    /// What may propose seeds.
    enum class Criterion
    {
      none,
      principal_strain,
      damage,
      principal_strain_and_damage
    };

    /// The shape of the PD-only zone around a seed (<Seed shape>).
    enum class SeedShape
    {
      /// A disk in 2D, a ball in 3D.
      ball,
      /// 3D: a cylinder parallel to z through the whole body.
      cylinder
    };

    /// Declare the subsection <Coupling/Adaptive region> (entered by the caller's caller).
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /**
     * @brief Read and check the subsection (inside <Coupling>); the ramp must be at least
     * @p horizon wide.
     */
    void
    parse_parameters(dealii::ParameterHandler &prm, const double horizon);

    /// Whether the region grows during the run (<Criterion> is not none).
    bool
    enabled() const;

    /// <Check interval> [steps].
    unsigned int
    check_interval() const;

    /// beta of the seeds at @p x (0 without seeds).
    double
    blending(const dealii::Point<dim> &x) const;

    /**
     * @brief The seeds the criterion proposes in @p state, whose overlap is @p beta and whose
     * body is @p in_body; @p precrack_damage is the damage index of each owned particle with
     * only the pre-cracks' bonds broken (collective; the same list on every rank, empty if
     * none). With the damage criterion, stops the run (check_crack_inside(); @p when begins
     * the message) if a particle damaged by the run lies outside the PD-only zone.
     */
    std::vector<dealii::Point<dim>>
    propose_seeds(const CoupledState<dim>                                 &state,
                  const std::function<double(const dealii::Point<dim> &)> &beta,
                  const std::function<bool(const dealii::Point<dim> &)>   &in_body,
                  const std::vector<double>                               &precrack_damage,
                  const std::string                                       &when) const;

    /**
     * @brief Stop the run, naming the entries to change, if the least beta of a particle
     * damaged by the run on any rank (@p least_beta on this one, at @p where) is below 1: the
     * crack has reached the overlap, where the FE field bridges it, before a check grew the
     * zone around it (collective).
     */
    void
    check_crack_inside(const double              least_beta,
                       const dealii::Point<dim> &where,
                       const MPI_Comm            comm,
                       const std::string        &when) const;

    /**
     * @brief Whether @p x lies within @p reach of the support of the seeds' beta (closer than
     * R + w + @p reach to a seed; @p reach at most twice the horizon).
     */
    bool
    within_reach(const dealii::Point<dim> &x, const double reach) const;

    /// Add @p seeds to the region (beta grows).
    void
    add_seeds(const std::vector<dealii::Point<dim>> &seeds);

    /// The seeds so far.
    const std::vector<dealii::Point<dim>> &
    seed_points() const;

    /// <Seed shape>.
    SeedShape
    seed_shape() const;

    /**
     * @brief The distance of @p x to the seed @p s that beta uses: |x - s| for balls, the
     * distance in the x-y plane for cylinders.
     */
    double
    seed_distance(const dealii::Point<dim> &x, const dealii::Point<dim> &s) const;

    /**
     * @brief Stop, naming the condition and <Core radius>, if the disks of @p new_seeds would
     * give beta > 0 at a vertex of a face of an FE boundary condition (the conditions act on the
     * FE field only: a face in the PD zone would lose its condition). @p when starts the
     * message; @p section names the physics' subsection of the conditions ("" for the first
     * physics, e.g. "Heat/"). Collective; call before anything changes.
     */
    void
    check_conditions_outside(const FERegion<dim>                   &fe,
                             const std::vector<dealii::Point<dim>> &new_seeds,
                             const std::string                     &when,
                             const std::string                     &section = "") const;

  private:
    /// beta of a disk at distance @p distance from its seed.
    double
    disk_blending(const double distance) const;

    /// Core radius R and ramp width w [m].
    double       core_radius = 0., ramp_width = 0.;
    Criterion    criterion       = Criterion::none;
    unsigned int interval        = 10;
    double       strain_fraction = 0.5, damage_threshold = 0.5, damage_distance = 0.;
    /// <Strain region>: the criterion 'principal strain' flags cells only where it is > 0.
    std::shared_ptr<dealii::FunctionParser<dim>> strain_region;
    /// <Lead distance> [m].
    double                          lead_distance = 0.;
    SeedShape                       shape         = SeedShape::ball;
    std::vector<dealii::Point<dim>> seeds;
    /// The seeds as beta sees them (projected onto z = 0 for cylinders), binned in seed_cells.
    std::vector<dealii::Point<dim>> projected_seeds;
    /// @p x as beta sees it: projected onto z = 0 for cylinders, unchanged for balls.
    dealii::Point<dim>
    project(const dealii::Point<dim> &x) const;
    /// The nearest seed's distance to @p x (of equally near seeds the first), or the largest
    /// double if none lies within a bin; its index in @p index if given (unchanged if none).
    double
    nearest_seed(const dealii::Point<dim> &x, unsigned int *index = nullptr) const;

    /// The width of the bins of the seeds: R + w + 2 delta (a seed's weight and a bond beyond).
    double bin_width = 0.;
    /// The seeds by bin of width bin_width.
    CellList<dim> seed_cells;
  };
} // namespace perideal

#endif
