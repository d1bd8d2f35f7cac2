// ---------------------------------------------------------------------
// PeriDeal: the least-squares fit of FE dof values from the particle field (the interface
// values of the overlapping Schwarz method).
// ---------------------------------------------------------------------
#ifndef perideal_coupling_interface_fit_h
#define perideal_coupling_interface_fit_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <perideal/base/linear_algebra.h>
#include <perideal/pd/particle_system.h>

#include <string>
#include <vector>

namespace perideal
{
  /**
   * @brief The values of FE dofs fitted from the particle displacements around their support
   * points: the value of a dof is sum_k w_k u_k over the particle nearest to its support point
   * (on all ranks; ties: the smaller invariant index) and that particle's family, computed by
   * the rank that owns the particle (its family is owned or ghost there) and sent to the dof's
   * owner.
   *
   * The weights are those of a quadratic least-squares fit over the family:
   * u(y + r) = sum_m c_m a_m(r / delta), a the monomials of degree <= 2 (1, r_d, r_d r_e for
   * d <= e), so the value at y is c_0 = sum_k w_k u_k with w_k = (M^-1 a(r_k))_0,
   * M = sum_k a(r_k) a(r_k)^T, r_k = x_k - y (computed as w = Q R^-T e_0 from a Householder QR
   * of the fit matrix A = [a(r_k)^T], without forming M = A^T A). Exact for quadratic fields; a
   * linear fit is exact for linear fields only and, evaluated at y, biased by the field's curvature
   * times the family's second moment (of order u'' delta^2), which in a bending arm changed the
   * coupled stiffness by percent. A family with fewer than twice as many members as monomials (a
   * corner of the body with a small horizon) gets the linear fit, which it determines well.
   */
  template <int dim>
  class InterfaceFit
  {
  public:
    /// An owned FE dof to fit: its global index, vector component and support point.
    struct Node
    {
      /// Its global index, its vector component, its support point.
      ///@{
      dealii::types::global_dof_index dof;
      unsigned int                    component;
      dealii::Point<dim>              location;
      ///@}
    };

    /**
     * @brief Build the weights of the @p nodes of every rank (collective), the FE dofs being
     * owned as @p owned. Throws, naming @p blending_entry, if a node has no particle within a
     * horizon or its nearest particle belongs to the volume constraint (@p constrained, per
     * owned particle), which takes its values from the FE field.
     */
    void
    reinit(const ParticleSystem<dim> &particles,
           const std::vector<bool>   &constrained,
           const std::vector<Node>   &nodes,
           const dealii::IndexSet    &owned,
           const std::string         &blending_entry);

    /**
     * @brief The fitted values of the particle field @p u (@p n_components per particle,
     * ghosts current) at the owned dofs @p local_dofs (indices within the owned set) into
     * @p values (collective).
     */
    void
    evaluate(const ParticleVector            &u,
             const unsigned int               n_components,
             const std::vector<unsigned int> &local_dofs,
             std::vector<double>             &values);

  private:
    /// The fits this rank computes: the dof (global), its component and its particles' weights
    /// (local particle indices, owned or ghost) in particles_of/weights[start[k]..start[k+1]).
    std::vector<dealii::types::global_dof_index> dofs;
    std::vector<unsigned int>                    components, start, particles_of;
    std::vector<double>                          weights;
    /// The fitted values, owned like the FE dofs with the fits of other ranks' dofs as ghosts.
    FEVector fitted;
  };
} // namespace perideal

#endif
