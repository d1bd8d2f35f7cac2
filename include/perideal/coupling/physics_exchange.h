// ---------------------------------------------------------------------
// PeriDeal: what the physics of a problem publish for each other.
// ---------------------------------------------------------------------
#ifndef perideal_coupling_physics_exchange_h
#define perideal_coupling_physics_exchange_h

#include <perideal/base/field_layout.h>
#include <perideal/base/linear_algebra.h>
#include <perideal/fem/fe_region.h>
#include <perideal/pd/particle_system.h>

#include <map>
#include <string>
#include <vector>

namespace perideal
{
  /**
   * @brief The one interface between the physics of a problem
   * (doc/architecture/16_multiphysics.md): each physics publishes named quantities (the heat
   * its temperature), each reads them here and not
   * from another physics' state; and the bonds the physics share (one BondList) break for all
   * of them.
   *
   * A quantity is a component of a physics' field: its values at the particles (the same
   * particles for every physics) and at the FE nodes of its own dofs, live (they change as the
   * physics advances). A bond broken by a force evaluation of one physics (its kernel's
   * BondBlocks::break_lanes()) is recorded (record()) and passed to the bond list through its
   * own function (share_broken_bonds(): BondList::set_state_of()), so that the other physics'
   * kernels re-read the states before their next evaluation: a crack insulates.
   */
  template <int dim>
  class PhysicsExchange
  {
  public:
    /// A published quantity: component @p component of the field @p layout.
    struct Quantity
    {
      /// The particle vector (laid out by the field) and the FE vector of the publishing
      /// physics.
      ///@{
      const ParticleVector *particles = nullptr;
      const FEVector       *fe        = nullptr;
      ///@}
      /// The publisher's FE region, whose DoFHandler numbers @p fe.
      const FERegion<dim> *region = nullptr;
      /// The publisher's layout and the component of it.
      ///@{
      FieldLayout  layout;
      unsigned int component = 0;
      ///@}
    };

    /**
     * @brief Publish @p name: component @p component of @p layout, whose values are
     * @p particles and @p fe on the dofs of @p region (kept by reference: they must outlive the
     * exchange). A name is published once.
     */
    void
    publish(const std::string    &name,
            const ParticleVector &particles,
            const FEVector       &fe,
            const FERegion<dim>  &region,
            const FieldLayout    &layout,
            const unsigned int    component);

    /// Whether @p name is published.
    bool
    has(const std::string &name) const;

    /// The quantity @p name (published).
    const Quantity &
    get(const std::string &name) const;

    /// The value of @p name at local particle @p i (owned or ghost).
    double
    particle_value(const std::string &name, const unsigned int i) const;

    /**
     * @brief The bonds the force evaluations of a physics broke: CoupledState appends its
     * BondList::newly_broken here before the energy they released is taken (which clears the
     * list).
     */
    std::vector<unsigned int> &
    record();

    /**
     * @brief Break the recorded bonds in @p bonds through BondList::set_state_of() (which tells
     * every kernel to re-read the states) and clear the record; nothing if none broke.
     */
    void
    share_broken_bonds(BondList &bonds);

  private:
    std::map<std::string, Quantity> quantities;
    std::vector<unsigned int>       broken;
  };
} // namespace perideal

#endif
