// ---------------------------------------------------------------------
// PeriDeal: prescribed displacement, velocity and traction on particle sets.
// ---------------------------------------------------------------------
#ifndef perideal_pd_boundary_conditions_h
#define perideal_pd_boundary_conditions_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <perideal/base/linear_algebra.h>
#include <perideal/base/region.h>
#include <perideal/pd/particle_system.h>

#include <memory>
#include <string>
#include <vector>

namespace perideal
{
  /**
   * @brief Boundary conditions on the particles of named regions, and a body force.
   *
   * - 'displacement': u_c(x, t) = g_c(x, t) for the listed components c;
   * - 'velocity': v_c(x, t) = g_c(x, t) for the listed components;
   * - 'traction': a traction vector T(x, t) [Pa] applied as the body force T / d on the
   *   particles of the region, a layer of thickness d ('Layer thickness') at the loaded surface;
   *   the resultant is T times the area of the layer's face, to within the lattice resolution.
   * Functions are deal.II FunctionParser expressions of x, y, (z) and t. A component may be
   * prescribed by one condition only.
   *
   * The body force b(x, t) [N/m^3] ('Body force/Function') acts on every particle with the
   * particle's energy weight (ParticleSystem::energy_weights(): 1 in a PD problem, beta_i in a
   * blended coupled problem, whose FE region carries the rest, 1 - beta), so that the load is
   * weighted like the energy and a body force is not counted twice in the overlap. Tractions act
   * in full on the particles of their region.
   */
  template <int dim>
  class BoundaryConditions
  {
  public:
    enum class Type
    {
      displacement,
      velocity,
      traction
    };

    /// Declare "Names" of subsection "Boundary conditions" (first pass).
    static void
    declare_names(dealii::ParameterHandler &prm);
    /// Declare every condition's subsection and the body force.
    static void
    declare_parameters(dealii::ParameterHandler &prm, const std::vector<std::string> &names);
    /// The names read in the first pass.
    static std::vector<std::string>
    parse_names(dealii::ParameterHandler &prm);
    /// Read every condition; region names are checked against @p regions.
    void
    parse_parameters(dealii::ParameterHandler &prm, const RegionCollection<dim> &regions);

    /**
     * @brief Find the particles of every condition; throws (naming the condition) if a region
     * holds no particle or two conditions prescribe the same component of a particle.
     */
    void
    setup(const ParticleSystem<dim> &particles);

    /// Set the velocity of prescribed components over the step from @p time to time + @p dt.
    void
    prescribe_step_velocity(const double time, const double dt, ParticleVector &v) const;
    /// Set the displacement of components with a prescribed displacement at @p time.
    void
    prescribe_displacement(const double time, ParticleVector &u) const;
    /// Whether there is a body force or a traction condition.
    bool
    has_loads() const;
    /// Add the body force (times the energy weights) and traction loads [N/m^3] at @p time to
    /// @p force.
    void
    add_loads(const double time, ParticleVector &force) const;
    /// The body force b(x, t) of <Body force/Function>, or nullptr if it is zero.
    std::shared_ptr<dealii::Function<dim>>
    body_force_function() const;
    /// Whether component @p c of owned particle @p i is prescribed.
    bool
    is_prescribed(const unsigned int i, const unsigned int c) const
    {
      return prescribed[i * dim + c] != 0;
    }
    /// Names of the conditions of type @p type.
    std::vector<std::string>
    names_of_type(const Type type) const;
    /// Names of the conditions.
    const std::vector<std::string> &
    names() const;
    /// Reaction of every condition: minus the sum of the internal forces f V on its particles.
    std::vector<dealii::Tensor<1, dim>>
    reactions(const ParticleVector &internal_force) const;

  private:
    struct Condition
    {
      std::string                                  name;
      const Region<dim>                           *region = nullptr;
      Type                                         type   = Type::displacement;
      std::vector<unsigned int>                    components;
      std::string                                  expression;
      double                                       layer_thickness = 0.;
      std::unique_ptr<dealii::FunctionParser<dim>> function;
      std::vector<unsigned int>                    particles;
    };
    std::vector<Condition>                       conditions;
    std::vector<std::string>                     condition_names;
    std::shared_ptr<dealii::FunctionParser<dim>> body_force;
    bool                                         has_body_force = false;
    std::vector<std::uint8_t>                    prescribed;
    const ParticleSystem<dim>                   *particle_system = nullptr;
  };
} // namespace perideal

#endif
