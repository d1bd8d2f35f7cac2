// ---------------------------------------------------------------------
// PeriDeal: what the physics of a problem publish for each other.
// ---------------------------------------------------------------------
#include <perideal/coupling/physics_exchange.h>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  void
  PhysicsExchange<dim>::publish(const std::string    &name,
                                const ParticleVector &particles,
                                const FEVector       &fe,
                                const FERegion<dim>  &region,
                                const FieldLayout    &layout,
                                const unsigned int    component)
  {
    AssertThrow(quantities.count(name) == 0,
                ExcMessage("The quantity <" + name + "> is published twice."));
    Quantity &quantity = quantities[name];
    quantity.particles = &particles;
    quantity.fe        = &fe;
    quantity.region    = &region;
    quantity.layout    = layout;
    quantity.component = component;
  }

  template <int dim>
  bool
  PhysicsExchange<dim>::has(const std::string &name) const
  {
    return quantities.count(name) > 0;
  }

  template <int dim>
  const typename PhysicsExchange<dim>::Quantity &
  PhysicsExchange<dim>::get(const std::string &name) const
  {
    const auto found = quantities.find(name);
    AssertThrow(found != quantities.end(),
                ExcMessage("No physics of the problem publishes <" + name + ">."));
    return found->second;
  }

  template <int dim>
  double
  PhysicsExchange<dim>::particle_value(const std::string &name, const unsigned int i) const
  {
    const Quantity &quantity = get(name);
    return quantity.particles->local_element(i * quantity.layout.n_components() +
                                             quantity.component);
  }

  template <int dim>
  std::vector<unsigned int> &
  PhysicsExchange<dim>::record()
  {
    return broken;
  }

  template <int dim>
  void
  PhysicsExchange<dim>::share_broken_bonds(BondList &bonds)
  {
    if (broken.empty())
      return;
    bonds.set_state_of(broken, 0);
    broken.clear();
  }

  template class PhysicsExchange<2>;
  template class PhysicsExchange<3>;
} // namespace perideal
