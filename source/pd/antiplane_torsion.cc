// ---------------------------------------------------------------------
// PeriDeal: what the antiplane models need for Saint-Venant torsion (the warping as unknown).
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/pd/antiplane_torsion.h>

#include <algorithm>
#include <limits>

namespace perideal
{
  namespace AntiplaneTorsion
  {
    using namespace dealii;

    template <int dim>
    BoundingBox<2>
    section_box(const ParticleSystem<dim> &particles)
    {
      const MPI_Comm comm = particles.get_communicator();
      const double   dx   = particles.settings().spacing;
      const auto    &x    = particles.positions();
      Point<2>       low, high;
      for (unsigned int d = 0; d < 2; ++d)
        {
          low[d]  = std::numeric_limits<double>::max();
          high[d] = -low[d];
          for (unsigned int i = 0; i < particles.n_owned(); ++i)
            {
              low[d]  = std::min(low[d], x[i][d]);
              high[d] = std::max(high[d], x[i][d]);
            }
          // The lattice cells of the particles.
          low[d]  = Utilities::MPI::min(low[d], comm) - 0.5 * dx;
          high[d] = Utilities::MPI::max(high[d], comm) + 0.5 * dx;
        }
      return BoundingBox<2>(std::make_pair(low, high));
    }

    template <int dim>
    void
    check_section(const ParticleSystem<dim> &particles)
    {
      const double         delta = particles.settings().horizon;
      const BoundingBox<2> box   = section_box(particles);
      for (unsigned int d = 0; d < 2; ++d)
        {
          const double width = box.side_length(d);
          AssertThrow(width >= 2. * delta,
                      ExcMessage(std::string("Torsion: the section is ") +
                                 ParameterUtilities::format_number(width) + " m wide in " +
                                 (d == 0 ? "x" : "y") + ", less than two horizons (delta = " +
                                 ParameterUtilities::format_number(delta) +
                                 " m): the particles near one face would see the other. "
                                 "Accepted: <Discretization/Horizon factor> times "
                                 "<Discretization/Lattice spacing> at most half the section's "
                                 "width (refine the lattice)."));
        }
    }

    template <int dim>
    std::vector<double>
    twist_fields(const ParticleSystem<dim> &particles, const Torsion &torsion)
    {
      const auto         &x = particles.positions();
      std::vector<double> fields(2 * x.size());
      for (unsigned int i = 0; i < x.size(); ++i)
        {
          fields[2 * i]     = torsion.twist() * (x[i][0] - torsion.axis()[0]);
          fields[2 * i + 1] = torsion.twist() * (x[i][1] - torsion.axis()[1]);
        }
      return fields;
    }

    template <int dim>
    void
    scalar_gradient(const ParticleSystem<dim>   &particles,
                    const ParticleVector        &w,
                    std::vector<Tensor<1, dim>> &gradient)
    {
      const unsigned int          n_owned = particles.n_owned();
      const auto                 &bonds   = particles.bonds();
      const auto                 &x       = particles.positions();
      const auto                 &volume  = particles.volumes();
      std::vector<Tensor<2, dim>> shape(n_owned);
      std::vector<Tensor<1, dim>> moment(n_owned);
      for (unsigned int i = 0; i < n_owned; ++i)
        for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
          {
            if (bonds.intact[b] == 0)
              continue;
            const unsigned int   j    = bonds.neighbor[b];
            const Tensor<1, dim> xi   = x[j] - x[i];
            const Tensor<2, dim> xixi = outer_product(xi, xi);
            const Tensor<1, dim> dw   = xi * (w.local_element(j) - w.local_element(i));
            const double         chi  = bonds.volume_factor(b);
            shape[i] += chi * volume[j] * xixi;
            moment[i] += chi * volume[j] * dw;
            // The other end sees -xi and -(w_j - w_i): the same products.
            if (particles.neighbor_is_owned(b))
              {
                shape[j] += chi * volume[i] * xixi;
                moment[j] += chi * volume[i] * dw;
              }
          }
      gradient.assign(n_owned, Tensor<1, dim>());
      for (unsigned int i = 0; i < n_owned; ++i)
        if (std::abs(determinant(shape[i])) > 1e-12 * std::pow(trace(shape[i]), dim))
          gradient[i] = invert(shape[i]) * moment[i];
    }

    template <int dim>
    void
    shear_stresses(const ParticleSystem<dim>   &particles,
                   const ParticleVector        &w,
                   const Torsion               &torsion,
                   const double                 shear_modulus,
                   std::vector<Tensor<1, dim>> &tau)
    {
      scalar_gradient(particles, w, tau);
      const auto &x = particles.positions();
      for (unsigned int i = 0; i < tau.size(); ++i)
        tau[i] = shear_modulus * (tau[i] + torsion.twist_strain(x[i]));
    }

    std::vector<std::string>
    integral_names()
    {
      return {"torque", "torsion_energy"};
    }

    template <int dim>
    std::vector<double>
    section_integrals(const ParticleSystem<dim> &particles,
                      const ParticleVector      &w,
                      const Torsion             &torsion,
                      const double               shear_modulus,
                      const double               strain_energy)
    {
      std::vector<Tensor<1, dim>> tau;
      shear_stresses(particles, w, torsion, shear_modulus, tau);
      const auto  &x      = particles.positions();
      const auto  &volume = particles.volumes();
      const auto  &weight = particles.energy_weights();
      const double h      = particles.settings().thickness;
      double       torque = 0.;
      for (unsigned int i = 0; i < particles.n_owned(); ++i)
        torque += weight[i] * torsion.torque_density(x[i], tau[i]) * volume[i] / h;
      return {Utilities::MPI::sum(torque, particles.get_communicator()), strain_energy / h};
    }

#define PERIDEAL_INSTANTIATE(dim)                                                          \
  template BoundingBox<2>      section_box(const ParticleSystem<dim> &);                   \
  template void                check_section(const ParticleSystem<dim> &);                 \
  template std::vector<double> twist_fields(const ParticleSystem<dim> &, const Torsion &); \
  template void                scalar_gradient(const ParticleSystem<dim> &,                \
                                               const ParticleVector &,                     \
                                               std::vector<Tensor<1, dim>> &);             \
  template void                shear_stresses(const ParticleSystem<dim> &,                 \
                                              const ParticleVector &,                      \
                                              const Torsion &,                             \
                                              const double,                                \
                                              std::vector<Tensor<1, dim>> &);              \
  template std::vector<double> section_integrals(const ParticleSystem<dim> &,              \
                                                 const ParticleVector &,                   \
                                                 const Torsion &,                          \
                                                 const double,                             \
                                                 const double);
    PERIDEAL_INSTANTIATE(2)
    PERIDEAL_INSTANTIATE(3)
#undef PERIDEAL_INSTANTIATE
  } // namespace AntiplaneTorsion
} // namespace perideal
